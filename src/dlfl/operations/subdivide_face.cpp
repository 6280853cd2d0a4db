// subdivide_face: see subdivide_face.h. The midpoints go in first (subdivide_edge), so that the face has a
// corner at each of them; then the face vertex is joined to those corners as stellate_face joins its apex to
// the corners.

#include <dlfl/operations/subdivide_face.h>

#include <string>

#include <dlfl/errors.h>
#include <dlfl/geometry.h>
#include <dlfl/operations/detail/operation_table.h>
#include <dlfl/operations/stellate_face.h>

namespace dlfl {
namespace {

[[noreturn]] void refuse(FaceId f, const std::string& what) {
  throw ParameterError(
      "subdivide_face: parameter face = " + std::to_string(f.valid() ? std::int64_t(f.index()) : -1) + ": " +
          to_string(f) + " " + what,
      "face");
}

SubdivideFaceResult subdivide_into_quads(Transaction& tx, FaceId f) {
  const Mesh& m = tx.mesh();
  const glm::dvec3 center = face_centroid(m, f);
  std::vector<CornerId> corners;
  corners.reserve(m.size(f));
  for (CornerId c : m.corners(f)) corners.push_back(c);
  // Vertices are appended, so a handle at or past this one is a midpoint made here.
  const std::uint32_t first_new = m.vertex_capacity();
  SubdivideFaceResult result;
  for (CornerId c : corners) {
    // An edge with f on both sides is met twice; its second side already leads to the midpoint.
    if (m.vertex(m.next(c)).index() >= first_new) continue;
    const glm::dvec3 middle = 0.5 * (m.position(m.vertex(c)) + m.position(m.vertex(m.next(c))));
    result.midpoints.push_back(tx.subdivide_edge(m.edge(c), middle));
  }
  // Each corner is now followed by the corner of its edge's midpoint.
  std::vector<CornerId> midpoint_corners;
  midpoint_corners.reserve(corners.size());
  for (CornerId c : corners) midpoint_corners.push_back(m.next(c));
  StellateFaceResult joined = join_corners_to_new_vertex(tx, midpoint_corners, center);
  result.center = joined.vertices.front();
  // The face of midpoint i runs from it through corner i+1 to the next midpoint: corner i's quad is the face
  // of the midpoint before it.
  result.faces.reserve(corners.size());
  for (CornerId c : corners) result.faces.push_back(m.face(c));
  return result;
}

}  // namespace

void check_subdivide_face(const Mesh& m, FaceId f) {
  if (!m.is_alive(f)) refuse(f, "does not exist (removed or never created)");
  if (m.is_hole(f)) refuse(f, "is a hole face, not a surface face");
  if (m.size(f) < 2) refuse(f, "is a point sphere's face (it has no edge)");
}

SubdivideFaceResult subdivide_face(Transaction& tx, FaceId f, const SubdivideFaceOptions& options) {
  check_subdivide_face(tx.mesh(), f);
  if (options.style == SubdivideFaceStyle::quads) return subdivide_into_quads(tx, f);
  const StellateFaceResult r = stellate_face(tx, f);
  return {r.vertices.front(), {}, r.faces};
}

std::vector<OperationSpec> detail::subdivide_face_operation_specs() {
  return {edit_operation(
      "subdivide_face",
      "a vertex at the centroid joined to new edge midpoints (n quads) or to the corners (n triangles)",
      {param("face", ParamType::face, "the face to subdivide"),
       param("style", ParamType::text, "quads", "quads: through edge midpoints; triangles: stellate_face")
           .one_of({"quads", "triangles"})},
      "quads: V+n+1, E+2n, F+n-1; triangles: V+1, E+n, F+n-1",
      [](Transaction& tx, const Params& p) {
        const SubdivideFaceStyle style =
            p.text("style") == "triangles" ? SubdivideFaceStyle::triangles : SubdivideFaceStyle::quads;
        const SubdivideFaceResult r = subdivide_face(tx, p.handle<FaceId>("face"), {style});
        Params out;
        out["vertex"] = r.center;
        if (style == SubdivideFaceStyle::quads) out["vertices"] = r.midpoints;
        out["faces"] = r.faces;
        return out;
      },
      [](const Mesh& m, Params& p) { check_subdivide_face(m, p.handle<FaceId>("face")); })};
}
}  // namespace dlfl
