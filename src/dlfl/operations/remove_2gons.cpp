// remove_2gons: see remove_2gons.h.

#include <dlfl/operations/remove_2gons.h>

#include <vector>

#include <dlfl/operations/detail/operation_table.h>

namespace dlfl {
namespace {

// The edge of the 2-gon f to delete, or an invalid edge if f is left alone.
EdgeId edge_to_delete(const Mesh& m, FaceId f) {
  if (m.size(f) != 2 || m.is_hole(f)) return {};
  const CornerId first = m.first_corner(f);
  const CornerId second = m.next(first);
  if (m.edge(first) == m.edge(second)) return {};  // one edge seen from both sides
  const FaceId across_first = m.face(m.opposite(first));
  const FaceId across_second = m.face(m.opposite(second));
  if (across_first == across_second) return {};
  if (!m.is_hole(across_first)) return m.edge(first);
  if (!m.is_hole(across_second)) return m.edge(second);
  return {};
}

}  // namespace

std::size_t remove_2gons(Transaction& tx) {
  const Mesh& m = tx.mesh();
  // The 2-gons first: a merge keeps the size of the face across, so no new 2-gon appears, but faces may
  // be renumbered.
  std::vector<FaceId> two_gons;
  for (FaceId f : m.faces()) {
    if (m.size(f) == 2) two_gons.push_back(f);
  }
  std::size_t removed = 0;
  for (FaceId f : two_gons) {
    // An earlier merge may have removed this face. A 2-gon merged into a 2-gon leaves one 2-gon, which may
    // carry either handle: it is taken on at once.
    while (m.is_alive(f)) {
      const EdgeId e = edge_to_delete(m, f);
      if (!e.valid()) break;
      const FaceId sides[2] = {m.face(e, 0), m.face(e, 1)};
      const FaceId gone = tx.delete_edge(e).removed_face;
      f = sides[0] == gone ? sides[1] : sides[0];
      ++removed;
    }
  }
  return removed;
}

std::vector<OperationSpec> detail::remove_2gons_operation_specs() {
  return {counting_operation(
      "remove_2gons",
      "removes every surface 2-gon by deleting one of its edges (merging it into the face across)",
      "V+0, E-k, F-k for k 2-gons removed", "two_gons_removed", &remove_2gons)};
}
}  // namespace dlfl
