// stellate_face: see stellate_face.h. The new vertex starts as a point sphere; one insert_edge merges it into
// the face as a dangling spoke, and each further insert_edge from the new vertex's corner cuts one triangle
// off the face.

#include <dlfl/operations/stellate_face.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <string_view>

#include <dlfl/errors.h>
#include <dlfl/geometry.h>
#include <dlfl/operations/detail/operation_table.h>

namespace dlfl {
namespace {

[[noreturn]] void refuse(const char* parameter, const std::string& what) {
  throw ParameterError(std::string("stellate_face: parameter ") + parameter + " " + what, parameter);
}

// The corners of f from its first corner, taken before anything changes (corner handles survive the cuts).
std::vector<CornerId> face_corners(const Mesh& m, FaceId f) {
  std::vector<CornerId> corners;
  corners.reserve(m.size(f));
  for (CornerId c : m.corners(f)) corners.push_back(c);
  return corners;
}

glm::dvec3 apex(const Mesh& m, FaceId f, double height) {
  return face_centroid(m, f) + height * face_normal(m, f);
}

}  // namespace

StellateFaceResult join_corners_to_new_vertex(Transaction& tx, std::span<const CornerId> corners,
                                              const glm::dvec3& position) {
  const Mesh& m = tx.mesh();
  StellateFaceResult result;
  const VertexId v = tx.create_vertex(position);
  result.vertices.push_back(v);
  // Merging the point sphere in: the walk becomes ..., prev(corners[0]), n1, s, corners[0], ... where s, the
  // sphere's own corner, is now the new vertex's corner in the angle just before corners[0].
  tx.insert_edge(corners[0], m.corner(v));
  CornerId hub = m.corner(v);
  // Each cut from the hub to the next chosen corner closes the part hub, corners[i-1] .. corners[i]; the
  // new edge's side-0 corner, at the new vertex just before corners[i], is the hub of what is left.
  for (std::size_t i = 1; i < corners.size(); ++i) hub = m.corner(tx.insert_edge(hub, corners[i]).edge, 0);
  for (CornerId c : corners) result.faces.push_back(m.face(c));
  return result;
}

void check_stellate_faces(const Mesh& m, std::span<const FaceId> faces, double height,
                          const char* parameter) {
  if (!std::isfinite(height)) refuse("height", "is not finite");
  if (faces.empty()) refuse(parameter, "is empty: no face to stellate");
  const bool one = std::string_view(parameter) == "face";
  for (FaceId f : faces) {
    // "face = 6: f6 is ..." or "faces lists f6, which is ...".
    const std::string who =
        one ? "= " + std::to_string(f.valid() ? std::int64_t(f.index()) : -1) + ": " + to_string(f)
            : "lists " + to_string(f) + ", which";
    if (!m.is_alive(f)) refuse(parameter, who + " does not exist (removed or never created)");
    if (m.is_hole(f)) refuse(parameter, who + " is a hole face, not a surface face");
    if (m.size(f) < 2) refuse(parameter, who + " is a point sphere's face (it has no edge)");
    const glm::dvec3 p = apex(m, f, height);
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) {
      refuse(parameter, who + " would get its new vertex at a non-finite position");
    }
  }
  if (faces.size() > 1) {
    std::vector<FaceId> sorted(faces.begin(), faces.end());
    std::sort(sorted.begin(), sorted.end(), [](FaceId a, FaceId b) { return a.index() < b.index(); });
    const auto twice = std::adjacent_find(sorted.begin(), sorted.end());
    if (twice != sorted.end()) refuse(parameter, "lists " + to_string(*twice) + " twice");
  }
}

namespace {

// The stellations, once the arguments are checked.
StellateFaceResult stellate_checked(Transaction& tx, std::span<const FaceId> faces,
                                    const StellateFaceOptions& options) {
  StellateFaceResult result;
  for (FaceId f : faces) {
    // Each face's apex comes from its own corners, which stellating another face does not move.
    const glm::dvec3 at = apex(tx.mesh(), f, options.height);
    const std::vector<CornerId> corners = face_corners(tx.mesh(), f);
    StellateFaceResult one = join_corners_to_new_vertex(tx, corners, at);
    result.vertices.push_back(one.vertices.front());
    result.faces.insert(result.faces.end(), one.faces.begin(), one.faces.end());
  }
  return result;
}

}  // namespace

StellateFaceResult stellate_faces(Transaction& tx, std::span<const FaceId> faces,
                                  const StellateFaceOptions& options) {
  check_stellate_faces(tx.mesh(), faces, options.height, "faces");
  return stellate_checked(tx, faces, options);
}

StellateFaceResult stellate_face(Transaction& tx, FaceId f, const StellateFaceOptions& options) {
  const FaceId one[] = {f};
  check_stellate_faces(tx.mesh(), one, options.height, "face");
  return stellate_checked(tx, one, options);
}

std::vector<OperationSpec> detail::stellate_face_operation_specs() {
  return {edit_operation(
      "stellate_face",
      "a new vertex above the face's centroid, joined to every corner: an n-gon becomes n triangles",
      {param("face", ParamType::face, "the face to stellate").optional("exactly one of face and faces"),
       param("faces", ParamType::faces, "several faces, each stellated on its own")
           .optional("exactly one of face and faces"),
       param("height", ParamType::number, 0.0, "how far the new vertex is moved along the face's normal")},
      "V+1, E+n, F+n-1 per face",
      [](Transaction& tx, const Params& p) {
        const StellateFaceOptions options{p.number("height")};
        Params out;
        if (p.has("face")) {
          const StellateFaceResult r = stellate_face(tx, p.handle<FaceId>("face"), options);
          out["vertex"] = r.vertices.front();
          out["faces"] = r.faces;
        } else {
          const StellateFaceResult r = stellate_faces(tx, p.handles<FaceId>("faces"), options);
          out["vertices"] = r.vertices;
          out["faces"] = r.faces;
        }
        return out;
      },
      [](const Mesh& m, Params& p) {
        if (p.has("face") == p.has("faces")) {
          refuse("face", p.has("face") ? "and faces are both given; give one of them"
                                       : "is missing: give face or faces");
        }
        const bool single = p.has("face");
        const std::vector<FaceId> faces =
            single ? std::vector<FaceId>{p.handle<FaceId>("face")} : p.handles<FaceId>("faces");
        check_stellate_faces(m, faces, p.number("height"), single ? "face" : "faces");
      })};
}
}  // namespace dlfl
