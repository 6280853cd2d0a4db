// rind: the shell of detail/shell_copy.h with the given faces punched.

#include <dlfl/operations/rind.h>

#include <dlfl/operations/detail/extrusion_faces.h>
#include <dlfl/operations/detail/operation_table.h>
#include <dlfl/operations/detail/shell_copy.h>

namespace dlfl {
namespace {

constexpr std::string_view op_name = "rind";

std::vector<glm::dvec3> planned(const Mesh& mesh, std::span<const FaceId> faces, const RindOptions& o,
                                std::string_view parameter = "faces") {
  detail::check_surface_faces(op_name, mesh, faces, parameter);
  return detail::inner_positions(mesh, op_name, "thickness", o.thickness);
}

std::vector<VertexId> rind_faces(Transaction& tx, std::span<const FaceId> faces, const RindOptions& options,
                                 std::string_view parameter) {
  const std::vector<glm::dvec3> inner = planned(tx.mesh(), faces, options, parameter);
  const detail::MirroredCopy copy = detail::add_shell(tx, inner, faces);
  std::vector<VertexId> out;
  for (VertexId v : copy.vertices) {
    if (v.valid()) out.push_back(v);
  }
  return out;
}

}  // namespace

std::vector<VertexId> rind(Transaction& tx, std::span<const FaceId> faces, const RindOptions& options) {
  return rind_faces(tx, faces, options, "faces");
}

void check_rind(const Mesh& mesh, std::span<const FaceId> faces, const RindOptions& options) {
  planned(mesh, faces, options);
}

std::vector<OperationSpec> detail::rind_operation_specs() {
  return {edit_operation(
      "rind", "a crust with the given faces punched through to their inner twins by tubes of quads",
      {param("thickness", ParamType::number, 0.1, "how far the copy lies below, along the vertex normals")
           .range(0.0, std::numeric_limits<double>::infinity(), true, false),
       faces_param("the faces to punch through (at least one)"), face_param("one face to punch through")},
      "closed: V+V, E+E+sum n, F+F+sum (n-2) over the k faces: Euler characteristic 2chi-2k",
      [](Transaction& tx, const Params& p) {
        const FaceSelection selection = selected_faces(op_name, p);
        return Params{
            {"vertices", rind_faces(tx, selection.faces, {p.number("thickness")}, selection.parameter)}};
      },
      [](const Mesh& mesh, Params& p) {
        const FaceSelection selection = selected_faces(op_name, p);
        planned(mesh, selection.faces, {p.number("thickness")}, selection.parameter);
      })};
}
}  // namespace dlfl
