// spheralize: see spheralize.h.

#include <dlfl/operations/spheralize.h>

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <vector>

#include <dlfl/operations/detail/operation_table.h>

namespace dlfl {

SpheralizeResult spheralize(Transaction& tx) {
  const Mesh& m = tx.mesh();
  SpheralizeResult r;
  if (m.num_vertices() == 0) return r;
  // Each position divided by the count before the sum, so that huge coordinates do not overflow.
  const double share = 1.0 / double(m.num_vertices());
  for (VertexId v : m.vertices()) r.center += m.position(v) * share;
  for (VertexId v : m.vertices()) r.radius = std::max(r.radius, glm::length(m.position(v) - r.center));
  std::vector<std::pair<VertexId, glm::dvec3>> moves;
  for (VertexId v : m.vertices()) {
    const glm::dvec3 d = m.position(v) - r.center;
    const double distance = glm::length(d);
    if (distance == 0.0) {
      ++r.vertices_at_center;
      continue;
    }
    if (distance == r.radius) continue;
    const glm::dvec3 to = r.center + d * (r.radius / distance);
    if (std::isfinite(to.x) && std::isfinite(to.y) && std::isfinite(to.z) && to != m.position(v))
      moves.emplace_back(v, to);
  }
  for (const auto& [v, to] : moves) tx.set_position(v, to);
  return r;
}

std::vector<OperationSpec> detail::spheralize_operation_specs() {
  return {edit_operation(
      "spheralize",
      "moves every vertex along the ray from the vertices' centroid onto the sphere through the farthest one",
      {}, "V+0, E+0, F+0", [](Transaction& tx, const Params&) {
        const SpheralizeResult r = spheralize(tx);
        return Params{
            {"center", r.center}, {"radius", r.radius}, {"vertices_at_center", r.vertices_at_center}};
      })};
}
}  // namespace dlfl
