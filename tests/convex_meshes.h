#pragma once
// Independent geometry for the tests of convex polyhedra (Meng-Prautzsch schemes, definition 2.3 angles):
// a brute-force convex hull, face normals and angles computed without the library's own code.

#include <cmath>
#include <cstdint>
#include <glm/geometric.hpp>
#include <vector>

#include <dlfl/mesh.h>
#include <dlfl/polygon_soup.h>

namespace dlfl::test {

/// The convex hull of points in general position (no four coplanar), by brute force: a triangle is a face
/// when every other point lies strictly on one side of its plane; it is oriented to face away from them.
/// O(n^4), for small test inputs.
inline PolygonSoup hull_soup(const std::vector<glm::dvec3>& points) {
  PolygonSoup s;
  s.positions = points;
  const auto n = static_cast<std::uint32_t>(points.size());
  for (std::uint32_t i = 0; i < n; ++i) {
    for (std::uint32_t j = i + 1; j < n; ++j) {
      for (std::uint32_t k = j + 1; k < n; ++k) {
        const glm::dvec3 normal = glm::cross(points[j] - points[i], points[k] - points[i]);
        int above = 0, below = 0;
        for (std::uint32_t l = 0; l < n; ++l) {
          if (l == i || l == j || l == k) continue;
          const double d = glm::dot(normal, points[l] - points[i]);
          above += d > 1e-9;
          below += d < -1e-9;
        }
        if (below == int(n) - 3) s.add_face({i, j, k});
        if (above == int(n) - 3) s.add_face({i, k, j});
      }
    }
  }
  return s;
}

/// Outward unit normal of a planar face from its first three vertices (a strictly convex corner).
inline glm::dvec3 normal_of(const Mesh& m, FaceId f) {
  const CornerId c = m.first_corner(f);
  const glm::dvec3 a = m.position(m.vertex(c)), b = m.position(m.vertex(m.next(c))),
                   d = m.position(m.vertex(m.next(m.next(c))));
  return glm::normalize(glm::cross(b - a, d - b));
}

/// The angle between two vectors, accurate near 0 and near pi.
inline double angle(const glm::dvec3& a, const glm::dvec3& b) {
  return std::atan2(glm::length(glm::cross(a, b)), glm::dot(a, b));
}

}  // namespace dlfl::test
