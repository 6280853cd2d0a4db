// convex_hull: the hull of detail/convex_hull_3d.h as a library function and a registered operation.

#include <dlfl/operations/convex_hull.h>

#include <vector>

#include <dlfl/operations/detail/carry_attributes.h>
#include <dlfl/operations/detail/convex_hull_3d.h>
#include <dlfl/operations/detail/operation_table.h>

namespace dlfl {
namespace {

constexpr std::string_view op_name = "convex_hull";

}  // namespace

Mesh convex_hull(std::span<const glm::dvec3> points) {
  return detail::hull_of_point_set(points, op_name).mesh;
}

Mesh convex_hull(const Mesh& mesh) {
  detail::HullMesh hull = detail::hull_of_mesh(mesh, op_name);
  // Each vertex of the hull keeps the values of the input vertex it is.
  Origins origins;
  origins.vertices.reserve(hull.source.size());
  for (std::uint32_t source : hull.source) origins.vertices.push_back(origin_of(VertexId(source)));
  detail::carry_attributes(mesh, origins, {}, hull.mesh);
  return std::move(hull.mesh);
}

std::vector<OperationSpec> detail::convex_hull_operation_specs() {
  return {hull_operation(
      "convex_hull",
      "replaces the mesh with the convex hull of its vertices: planar, strictly convex faces, genus 0",
      [](const Mesh& current) { return convex_hull(current); })};
}

}  // namespace dlfl
