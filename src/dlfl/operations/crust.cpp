// crust: the mirrored copy (detail/shell_copy.h) at the inner positions.

#include <dlfl/operations/crust.h>

#include <dlfl/operations/detail/operation_table.h>
#include <dlfl/operations/detail/shell_copy.h>

namespace dlfl {
namespace {

constexpr std::string_view op_name = "crust";

std::vector<VertexId> copies_of(const Mesh& mesh, const detail::MirroredCopy& copy) {
  std::vector<VertexId> out;
  out.reserve(mesh.num_vertices());
  for (VertexId v : copy.vertices) {
    if (v.valid()) out.push_back(v);
  }
  return out;
}

}  // namespace

std::vector<VertexId> crust(Transaction& tx, const CrustOptions& options) {
  const std::vector<glm::dvec3> inner =
      detail::inner_positions(tx.mesh(), op_name, "thickness", options.thickness);
  return copies_of(tx.mesh(), detail::add_shell(tx, inner, {}));
}

void check_crust(const Mesh& mesh, const CrustOptions& options) {
  detail::inner_positions(mesh, op_name, "thickness", options.thickness);
}

std::vector<OperationSpec> detail::crust_operation_specs() {
  return {edit_operation(
      "crust",
      "an inner reversed copy of every component, thickness below it; hole faces tube to their twins",
      {param("thickness", ParamType::number, 0.1, "how far the copy lies below, along the vertex normals")
           .range(0.0, std::numeric_limits<double>::infinity(), true, false)},
      "closed: V+V, E+E, F+F; each hole face of h sides adds E+h, F+h-2",
      [](Transaction& tx, const Params& p) {
        return Params{{"vertices", crust(tx, {p.number("thickness")})}};
      },
      [](const Mesh& mesh, Params& p) { check_crust(mesh, {p.number("thickness")}); })};
}
}  // namespace dlfl
