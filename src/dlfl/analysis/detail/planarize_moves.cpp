#include <dlfl/analysis/detail/planarize_moves.h>

#include <cmath>
#include <cstdint>
#include <glm/geometric.hpp>

#include <dlfl/analysis/detail/best_fit_plane.h>
#include <dlfl/navigation.h>

namespace dlfl::detail {
namespace {

// Below this a face counts as planar (relative to its mean edge length): rounding leaves about 1e-16.
constexpr double planar_tolerance = 1e-12;

bool finite(const glm::dvec3& p) { return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z); }

}  // namespace

std::vector<std::pair<VertexId, glm::dvec3>> planarize_moves(const Mesh& m) {
  std::vector<glm::dvec3> shift(m.vertex_capacity(), glm::dvec3(0.0));
  std::vector<std::uint32_t> planes(m.vertex_capacity(), 0);
  for (FaceId f : surface_faces(m)) {
    if (m.size(f) < 4) continue;
    const Plane plane = best_fit_plane(m, f);
    const bool planar = face_nonplanarity(m, f, plane) <= planar_tolerance;
    for (VertexId v : vertices(m, f)) {
      ++planes[v.index()];
      if (!planar) shift[v.index()] -= plane.normal * glm::dot(plane.normal, m.position(v) - plane.point);
    }
  }
  std::vector<std::pair<VertexId, glm::dvec3>> moves;
  for (VertexId v : m.vertices()) {
    if (planes[v.index()] == 0 || shift[v.index()] == glm::dvec3(0.0)) continue;
    const glm::dvec3 to = m.position(v) + shift[v.index()] / double(planes[v.index()]);
    if (finite(to) && to != m.position(v)) moves.emplace_back(v, to);
  }
  return moves;
}

}  // namespace dlfl::detail
