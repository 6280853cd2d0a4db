// dual_hull: the dual scheme's topology of the hull, with the poles of the hull's faces as its vertices.

#include <dlfl/operations/dual_hull.h>

#include <glm/geometric.hpp>
#include <vector>

#include <dlfl/analysis/convex_polyhedron.h>
#include <dlfl/operations/detail/convex_hull_3d.h>
#include <dlfl/operations/detail/operation_table.h>
#include <dlfl/operations/detail/refusal.h>
#include <dlfl/schemes/dual.h>

namespace dlfl {
namespace {

constexpr std::string_view op_name = "dual_hull";

Mesh polar_dual(const Mesh& hull, std::string_view parameter) {
  const glm::dvec3 c = vertex_centroid(hull);
  std::vector<FacePlane> planes;
  planes.reserve(hull.num_faces());
  double plane_distance = 0.0, vertex_distance = 0.0;
  for (FaceId f : hull.faces()) {
    planes.push_back(face_plane(hull, f));
    plane_distance += -planes.back().distance(c);
  }
  for (VertexId v : hull.vertices()) vertex_distance += glm::length(hull.position(v) - c);
  const double r2 = plane_distance / double(hull.num_faces()) * vertex_distance / double(hull.num_vertices());
  // dual(): its vertex i stands for the hull's i-th live face, which build_mesh numbered densely.
  Mesh out = dual(hull);
  for (std::uint32_t i = 0; i < planes.size(); ++i) {
    out.set_position(VertexId(i), c + planes[i].normal * (r2 / -planes[i].distance(c)));
  }
  if (const auto violation = convexity_violation(out, vertex_centroid(out))) {
    detail::refuse(
        op_name, parameter,
        "the dual of the hull is too close to degenerate for the tolerances of the convexity check: " +
            violation->message);
  }
  return out;
}

}  // namespace

Mesh dual_hull(std::span<const glm::dvec3> points) {
  return polar_dual(detail::hull_of_point_set(points, op_name).mesh, "points");
}

Mesh dual_hull(const Mesh& mesh) {
  Mesh out = polar_dual(detail::hull_of_mesh(mesh, op_name).mesh, "mesh");
  detail::declare_attributes(mesh, out);
  return out;
}

std::vector<OperationSpec> detail::dual_hull_operation_specs() {
  return {hull_operation(
      "dual_hull", "replaces the mesh with the polar dual of its vertices' convex hull about their centroid",
      [](const Mesh& current) { return dual_hull(current); })};
}

}  // namespace dlfl
