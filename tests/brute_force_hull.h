#pragma once
// The convex hull by its definition, for the tests of the hulls and of multi_connect: every plane through
// three of the points that has all of them on one side (O(n^4)), and the points on three of those planes
// with independent normals. Written without the library's hull.

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <set>
#include <tuple>
#include <vector>

namespace dlfl::test {

/// A point as a comparable key.
using Key = std::tuple<double, double, double>;
inline Key key(const glm::dvec3& p) { return {p.x, p.y, p.z}; }

struct Plane {
  glm::dvec3 normal;  // unit, outward
  double offset;      // the plane is normal . x = offset
};

// Every plane through three of the points (not on one line) with all the points on one side, up to `tol`
// (absolute), oriented so that they are below it; each plane once. For points with small integer
// coordinates the sums below are exact and tol is 0.
inline std::vector<Plane> brute_force_planes(const std::vector<glm::dvec3>& p, double tol) {
  std::vector<Plane> planes;
  const std::size_t n = p.size();
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t j = i + 1; j < n; ++j) {
      for (std::size_t k = j + 1; k < n; ++k) {
        glm::dvec3 normal = glm::cross(p[j] - p[i], p[k] - p[i]);
        if (glm::length(normal) <= 1e-12) continue;
        bool above = false, below = false;
        for (const glm::dvec3& q : p) {
          const double s = glm::dot(normal, q - p[i]) / glm::length(normal);
          above = above || s > tol;
          below = below || s < -tol;
        }
        if (above == below) continue;  // points on both sides (or, never here, on the plane only)
        normal = glm::normalize(above ? -normal : normal);
        const Plane plane{normal, glm::dot(normal, p[i])};
        const bool known = std::any_of(planes.begin(), planes.end(), [&](const Plane& q) {
          return glm::length(q.normal - plane.normal) < 1e-9 && std::abs(q.offset - plane.offset) < 1e-9;
        });
        if (!known) planes.push_back(plane);
      }
    }
  }
  return planes;
}

// The points that are corners of the brute-force hull: on three of its planes whose normals are independent
// (a point inside a face is on one plane, a point inside an edge on two).
inline std::set<Key> brute_force_vertices(const std::vector<glm::dvec3>& p, const std::vector<Plane>& planes,
                                          double tol) {
  std::set<Key> out;
  for (const glm::dvec3& q : p) {
    std::vector<glm::dvec3> on;
    for (const Plane& plane : planes) {
      if (std::abs(glm::dot(plane.normal, q) - plane.offset) <= tol) on.push_back(plane.normal);
    }
    bool corner = false;
    for (std::size_t a = 0; a < on.size() && !corner; ++a) {
      for (std::size_t b = a + 1; b < on.size() && !corner; ++b) {
        for (std::size_t c = b + 1; c < on.size() && !corner; ++c) {
          corner = std::abs(glm::dot(on[a], glm::cross(on[b], on[c]))) > 1e-9;
        }
      }
    }
    if (corner) out.insert(key(q));
  }
  return out;
}

}  // namespace dlfl::test
