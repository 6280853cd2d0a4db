// triangulate: see triangulate.h. Ear clipping on the face's corners projected into its plane; each ear cut
// off is one insert_edge between the ear's two neighbours, which splits the triangle off the face.

#include <dlfl/operations/triangulate.h>

#include <algorithm>
#include <optional>
#include <string>

#include <dlfl/detail/ear_clipping.h>
#include <dlfl/errors.h>
#include <dlfl/operations/detail/operation_table.h>

namespace dlfl {
namespace {

// Cuts f into triangles; returns one corner of each of the faces f became.
void triangulate_face(Transaction& tx, FaceId f, std::vector<CornerId>& pieces) {
  const Mesh& m = tx.mesh();
  detail::EarClipper clipper(m, f);
  std::vector<CornerId> corner;  // per node; the node before a cut ear gets the diagonal's corner
  for (CornerId c : m.corners(f)) corner.push_back(c);
  while (const std::optional<detail::EarClipper::Ear> ear = clipper.cut()) {
    // The part of corner `before` is before, tip, and a new corner at `after`: the triangle. The rest starts
    // with the new edge's corner at `before`, which stands for it from now on.
    const InsertEdgeResult cut = tx.insert_edge(corner[ear->before], corner[ear->after]);
    pieces.push_back(corner[ear->tip]);
    corner[ear->before] = m.corner(cut.edge, 0);
  }
  pieces.push_back(corner[clipper.rest()]);
}

}  // namespace

void check_triangulate(const Mesh& m, std::span<const FaceId> faces) {
  for (FaceId f : faces) {
    if (!m.is_alive(f)) {
      throw ParameterError("triangulate: parameter faces has " + to_string(f) +
                               ", which does not exist (removed or never created)",
                           "faces");
    }
  }
  std::vector<FaceId> sorted(faces.begin(), faces.end());
  std::sort(sorted.begin(), sorted.end(), [](FaceId a, FaceId b) { return a.index() < b.index(); });
  const auto twice = std::adjacent_find(sorted.begin(), sorted.end());
  if (twice != sorted.end()) {
    throw ParameterError("triangulate: parameter faces lists " + to_string(*twice) + " twice", "faces");
  }
}

TriangulateResult triangulate(Transaction& tx, std::span<const FaceId> faces) {
  check_triangulate(tx.mesh(), faces);
  std::vector<CornerId> pieces;
  for (FaceId f : faces) {
    if (tx.mesh().is_hole(f) || tx.mesh().size(f) <= 3) continue;
    triangulate_face(tx, f, pieces);
  }
  TriangulateResult result;
  result.faces.reserve(pieces.size());
  // A triangle, once cut off, is not touched again: its corner still names it.
  for (CornerId c : pieces) result.faces.push_back(tx.mesh().face(c));
  return result;
}

TriangulateResult triangulate_all(Transaction& tx) {
  std::vector<FaceId> faces;
  for (FaceId f : tx.mesh().faces()) faces.push_back(f);
  return triangulate(tx, faces);
}

std::vector<OperationSpec> detail::triangulate_operation_specs() {
  return {edit_operation(
      "triangulate",
      "cuts faces into triangles by diagonals (ear clipping in the face's plane); holes and triangles stay",
      {param("faces", ParamType::faces, "the faces to triangulate").optional("every face")},
      "E+(n-3), F+(n-3) per face of n > 3 sides",
      [](Transaction& tx, const Params& p) {
        const TriangulateResult r =
            p.has("faces") ? triangulate(tx, p.handles<FaceId>("faces")) : triangulate_all(tx);
        return Params{{"faces", r.faces}};
      },
      [](const Mesh& m, Params& p) {
        if (p.has("faces")) check_triangulate(m, p.handles<FaceId>("faces"));
      })};
}
}  // namespace dlfl
