#include <dlfl/operations/detail/valence2_join.h>

#include <vector>

namespace dlfl::detail {
namespace {

// The two corners of a vertex of valence 2, or invalid corners otherwise. O(1).
struct TwoCorners {
  CornerId c, d;
};
TwoCorners two_corners(const Mesh& m, VertexId v) {
  const CornerId c = m.corner(v);
  if (!m.edge(c).valid()) return {};
  const CornerId d = m.next_around_vertex(c);
  if (d == c || m.next_around_vertex(d) != c) return {};
  return {c, d};
}

bool leaves(const Mesh& m, CornerId c) { return m.corner(m.edge(c), 0) == c; }

}  // namespace

bool joinable(const Mesh& m, VertexId v) {
  if (!m.is_alive(v)) return false;
  const auto [c, d] = two_corners(m, v);
  if (!c.valid()) return false;
  // Along face(c): y, v, x; along face(d): x, v, y.
  const VertexId x = m.vertex(m.next(c));
  const VertexId y = m.vertex(m.next(d));
  if (x == y) return false;
  if (leaves(m, c) == leaves(m, d) && m.face(c) == m.face(d)) return false;
  const EdgeId allowed1 = m.size(m.face(c)) == 3 ? m.edge(m.next(c)) : EdgeId();
  const EdgeId allowed2 = m.size(m.face(d)) == 3 ? m.edge(m.next(d)) : EdgeId();
  for (CornerId a : m.corners(x)) {
    const EdgeId e = m.edge(a);
    if (m.vertex(m.next(a)) == y && e != allowed1 && e != allowed2) return false;
  }
  // Edges from y to x that leave y along a face appear above too: each edge leaves both its ends.
  return true;
}

void join_edges_at(Transaction& tx, VertexId v) {
  const Mesh& m = tx.mesh();
  const auto [c, d] = two_corners(m, v);
  const bool c_leaves = leaves(m, c);
  if (c_leaves == leaves(m, d)) {
    // Draw edge(c) again the other way round, in the same place: after the merge that deleting it makes,
    // inserting it between the corner that followed it along face(c) and d splits the faces back.
    const CornerId after = m.next(c);
    const bool hole_c = m.is_hole(m.face(c));
    const bool hole_d = m.is_hole(m.face(d));
    tx.delete_edge(m.edge(c));
    if (c_leaves) {
      tx.insert_edge(after, d);  // side 0 now starts at the far end
    } else {
      tx.insert_edge(d, after);  // side 0 now starts at v
    }
    // A split copies the merged face's flag, which was the larger face's.
    if (m.is_hole(m.face(after)) != hole_c) tx.set_hole(m.face(after), hole_c);
    if (m.is_hole(m.face(d)) != hole_d) tx.set_hole(m.face(d), hole_d);
  }
  tx.unsubdivide_edge(v);
}

std::size_t join_valence2_vertices(Transaction& tx, std::span<const VertexId> candidates) {
  const Mesh& m = tx.mesh();
  std::vector<char> is_candidate(m.vertex_capacity(), 0);
  for (VertexId v : candidates) is_candidate[v.index()] = 1;
  // A stack, seeded so that the candidates come off it in the given order.
  std::vector<VertexId> work(candidates.rbegin(), candidates.rend());
  std::size_t joined = 0;
  while (!work.empty()) {
    const VertexId v = work.back();
    work.pop_back();
    if (!joinable(m, v)) continue;
    const CornerId c = m.corner(v);
    const VertexId x = m.vertex(m.next(c));
    const VertexId y = m.vertex(m.next(m.next_around_vertex(c)));
    join_edges_at(tx, v);
    ++joined;
    // Each neighbour now has the other as a neighbour instead of v, which may make it joinable.
    for (VertexId w : {x, y}) {
      if (w.index() < is_candidate.size() && is_candidate[w.index()]) work.push_back(w);
    }
  }
  return joined;
}

}  // namespace dlfl::detail
