// inset_face: one ring of quads (detail/extrusion_rings.h) around a shrunk copy of the face.

#include <dlfl/operations/inset_face.h>

#include <cmath>
#include <glm/geometric.hpp>
#include <string>

#include <dlfl/errors.h>
#include <dlfl/format.h>
#include <dlfl/geometry.h>
#include <dlfl/navigation.h>
#include <dlfl/operations/detail/extrusion_faces.h>
#include <dlfl/operations/detail/extrusion_rings.h>
#include <dlfl/operations/detail/operation_table.h>

namespace dlfl {
namespace {

constexpr std::string_view op_name = "inset_face";

bool finite(const glm::dvec3& p) { return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z); }

// The corners of the copy, in the order of the face's corners from its first; empty if one is not finite.
std::vector<glm::dvec3> copy_of(const Mesh& mesh, FaceId f, const InsetFaceOptions& o) {
  const glm::dvec3 c = face_centroid(mesh, f);
  const glm::dvec3 lift = o.depth == 0.0 ? glm::dvec3(0.0) : o.depth * face_normal(mesh, f);
  std::vector<glm::dvec3> out;
  for (VertexId v : vertices(mesh, f)) {
    out.push_back(c + (1.0 - o.amount) * (mesh.position(v) - c) + lift);
    if (!finite(out.back())) return {};
  }
  return out;
}

struct FaceCopy {
  FaceId face;
  std::vector<glm::dvec3> positions;
};

std::vector<FaceCopy> planned(const Mesh& mesh, std::span<const FaceId> faces, const InsetFaceOptions& o,
                              std::string_view parameter) {
  if (!std::isfinite(o.amount) || !(o.amount > 0.0 && o.amount < 1.0))
    detail::refuse_worded(op_name, "amount", " = " + format_number(o.amount) + " is outside (0, 1)");
  if (!std::isfinite(o.depth))
    detail::refuse_worded(op_name, "depth", " = " + format_number(o.depth) + " is not finite");
  detail::check_surface_faces(op_name, mesh, faces, parameter);
  std::vector<FaceCopy> out;
  out.reserve(faces.size());
  for (FaceId f : faces) {
    if (o.depth != 0.0 && face_normal(mesh, f) == glm::dvec3(0.0)) {
      detail::refuse_worded(
          op_name, parameter,
          ": " + to_string(f) + " has no normal (its Newell vector is zero), so depth must be 0");
    }
    std::vector<glm::dvec3> positions = copy_of(mesh, f, o);
    if (positions.empty()) {
      const bool face_at_fault = copy_of(mesh, f, {o.amount, 0.0}).empty();
      detail::refuse_worded(op_name, face_at_fault ? parameter : "depth",
                            ": the copy of " + to_string(f) + " would not have finite positions");
    }
    out.push_back({f, std::move(positions)});
  }
  return out;
}

InsetFaceOptions options_of(const Params& p) { return {p.number("amount"), p.number("depth")}; }

}  // namespace

FaceId inset_face(Transaction& tx, FaceId face, const InsetFaceOptions& options) {
  return inset_faces(tx, std::span<const FaceId>(&face, 1), options, "face").front();
}

std::vector<FaceId> inset_faces(Transaction& tx, std::span<const FaceId> faces,
                                const InsetFaceOptions& options, std::string_view face_parameter) {
  return detail::build_each(
      tx, planned(tx.mesh(), faces, options, face_parameter), [](Transaction& tx, const FaceCopy& copy) {
        const auto corners = detail::corners_from(tx.mesh(), tx.mesh().first_corner(copy.face));
        return tx.mesh().face(detail::grow_quad_ring(tx, corners, copy.positions).front());
      });
}

std::vector<OperationSpec> detail::inset_face_operation_specs() {
  return {face_operation(
      op_name, "a smaller copy of a face inside it, joined to it by a ring of quads", "the face to inset",
      "faces to inset, each on its own",
      {param("amount", ParamType::number, 0.25,
             "the share of the way each corner moves towards the centroid: c + (1 - amount)(p - c)")
           .in_open(0.0, 1.0),
       param("depth", ParamType::number, 0.0, "how far the copy then moves along the face's normal")},
      "per face of n sides: V+n, E+2n, F+n",
      [](Transaction& tx, const FaceSelection& selection, const Params& p) {
        Params out;
        put_made(out, "faces", "face", inset_faces(tx, selection.faces, options_of(p), selection.parameter),
                 selection.parameter == "face");
        return out;
      },
      [](const Mesh& mesh, const FaceSelection& selection, const Params& p) {
        planned(mesh, selection.faces, options_of(p), selection.parameter);
      })};
}
}  // namespace dlfl
