#pragma once
// Checks of the curve boundary rules (docs/boundaries.md) shared by the tests of Catmull-Clark, Loop and
// sqrt(3): boundary loops read from the hole faces, the cubic B-spline of a boundary polygon in closed form,
// the crack between two halves of a closed mesh subdivided apart, and the counts of a step.

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <glm/geometric.hpp>
#include <vector>

#include <dlfl/build_mesh.h>
#include <dlfl/mesh.h>
#include <dlfl/schemes/boundary_rule.h>
#include <dlfl/validate.h>

#include "open_meshes.h"

namespace dlfl::test {

using SchemeStep = std::function<Mesh(const Mesh&)>;

/// `steps` applications of `step`.
inline Mesh steps_of(const SchemeStep& step, Mesh mesh, int steps) {
  for (int i = 0; i < steps; ++i) mesh = step(mesh);
  return mesh;
}

/// The vertices of hole face h in its order, from its corner at `start` when given (it must be on h).
inline std::vector<VertexId> loop_vertices(const Mesh& m, FaceId h, VertexId start = VertexId()) {
  std::vector<VertexId> loop;
  CornerId first = m.first_corner(h);
  for (CornerId c : m.corners(h)) {
    if (m.vertex(c) == start) first = c;
  }
  CornerId c = first;
  do {
    loop.push_back(m.vertex(c));
    c = m.next(c);
  } while (c != first);
  return loop;
}

/// The positions of every boundary vertex (every corner of every hole face).
inline std::vector<glm::dvec3> boundary_points(const Mesh& m) {
  std::vector<glm::dvec3> points;
  for (FaceId f : m.faces()) {
    if (!m.is_hole(f)) continue;
    for (CornerId c : m.corners(f)) points.push_back(m.position(m.vertex(c)));
  }
  return points;
}

/// The largest distance from a point of `a` to the nearest point of `b`, both ways (the Hausdorff distance
/// of two finite sets).
inline double set_distance(const std::vector<glm::dvec3>& a, const std::vector<glm::dvec3>& b) {
  auto one_way = [](const std::vector<glm::dvec3>& from, const std::vector<glm::dvec3>& to) {
    double worst = 0;
    for (const glm::dvec3& p : from) {
      double best = 1e300;
      for (const glm::dvec3& q : to) best = std::min(best, glm::length(p - q));
      worst = std::max(worst, best);
    }
    return worst;
  };
  return std::max(one_way(a, b), one_way(b, a));
}

/// The crack after `steps` steps between the two open halves of `closed` cut at z = 0, subdivided apart:
/// the distance between their boundary point sets (one loop each). Also checks that the loops have the same
/// number of vertices.
inline double crack(const SchemeStep& step, const PolygonSoup& closed, int steps) {
  const auto [below, above] = halves_at_z(closed);
  const Mesh a = steps_of(step, build_mesh(below), steps);
  const Mesh b = steps_of(step, build_mesh(above), steps);
  const auto pa = boundary_points(a), pb = boundary_points(b);
  CHECK(pa.size() == pb.size());
  return set_distance(pa, pb);
}

/// The uniform cubic B-spline of the closed control polygon `p` at parameter u in [0, n): C(i) is the limit
/// point (p[i-1] + 4 p[i] + p[i+1]) / 6 of control point i.
inline glm::dvec3 closed_cubic_bspline(const std::vector<glm::dvec3>& p, double u) {
  const auto n = static_cast<long>(p.size());
  const long i = static_cast<long>(std::floor(u));
  const double t = u - double(i);
  auto at = [&](long k) { return p[std::size_t(((k % n) + n) % n)]; };
  const double b0 = (1 - t) * (1 - t) * (1 - t) / 6, b1 = (3 * t * t * t - 6 * t * t + 4) / 6;
  const double b2 = (-3 * t * t * t + 3 * t * t + 3 * t + 1) / 6, b3 = t * t * t / 6;
  return b0 * at(i - 1) + b1 * at(i) + b2 * at(i + 1) + b3 * at(i + 2);
}

/// The same for an open chain p[0] .. p[n] (n + 1 points) whose ends are sharp: extended by the reflections
/// 2 p[0] - p[1] and 2 p[n] - p[n-1], u in [0, n]; C(0) = p[0] and C(n) = p[n].
inline glm::dvec3 open_cubic_bspline(const std::vector<glm::dvec3>& p, double u) {
  const auto n = static_cast<long>(p.size()) - 1;
  const long i = std::min(static_cast<long>(std::floor(u)), n - 1);
  const double t = u - double(i);
  auto at = [&](long k) {
    if (k < 0) return 2.0 * p[0] - p[1];
    if (k > n) return 2.0 * p[std::size_t(n)] - p[std::size_t(n - 1)];
    return p[std::size_t(k)];
  };
  const double b0 = (1 - t) * (1 - t) * (1 - t) / 6, b1 = (3 * t * t * t - 6 * t * t + 4) / 6;
  const double b2 = (-3 * t * t * t + 3 * t * t + 3 * t + 1) / 6, b3 = t * t * t / 6;
  return b0 * at(i - 1) + b1 * at(i) + b2 * at(i + 1) + b3 * at(i + 2);
}

/// The limit points of the polygon `q` (closed) by the cubic B-spline mask (1/6, 4/6, 1/6), against the
/// curve `curve(u)` at u = j / refinement for vertex j: the largest distance.
inline double limit_point_error(const std::vector<glm::dvec3>& q, double refinement,
                                const std::function<glm::dvec3(double)>& curve) {
  double worst = 0;
  const std::size_t n = q.size();
  for (std::size_t j = 0; j < n; ++j) {
    const glm::dvec3 limit = (q[(j + n - 1) % n] + 4.0 * q[j] + q[(j + 1) % n]) / 6.0;
    worst = std::max(worst, glm::length(limit - curve(double(j) / refinement)));
  }
  return worst;
}

/// Positions of vertices.
inline std::vector<glm::dvec3> positions_of(const Mesh& m, const std::vector<VertexId>& vertices) {
  std::vector<glm::dvec3> p;
  for (VertexId v : vertices) p.push_back(m.position(v));
  return p;
}

/// The counts of an open mesh: vertices, edges, surface faces, hole faces, boundary edges (hole corners).
struct OpenCounts {
  std::size_t vertices = 0, edges = 0, faces = 0, holes = 0, boundary = 0;
  bool operator==(const OpenCounts&) const = default;
};
inline OpenCounts open_counts(const Mesh& m) {
  OpenCounts c{m.num_vertices(), m.num_edges(), m.num_surface_faces(), m.num_hole_faces(), 0};
  for (FaceId f : m.faces()) c.boundary += m.is_hole(f) ? m.size(f) : 0;
  return c;
}

/// The step's result is valid, with the input's components, Euler characteristics, genera and holes.
inline void check_same_topology(const Mesh& in, const Mesh& out) {
  const ValidationReport before = validate(in), after = validate(out);
  REQUIRE(after.valid());
  REQUIRE(after.components.size() == before.components.size());
  for (std::size_t i = 0; i < before.components.size(); ++i) {
    CHECK(after.components[i].euler_characteristic == before.components[i].euler_characteristic);
    CHECK(after.components[i].genus == before.components[i].genus);
    CHECK(after.components[i].holes == before.components[i].holes);
  }
}

/// Whether vertex v carries the `sharp` mark.
inline bool marked_sharp(const Mesh& m, VertexId v) {
  const auto marks = m.find_attribute<VertexId, bool>(sharp_vertex_attribute);
  return marks && (*marks)[v];
}

/// The soup with every vertex moved in x and y by its own small offset, z kept: a closed mesh cut at z = 0
/// by `halves_at_z` still has its ring there, and no symmetry can hide a wrong weight.
inline PolygonSoup wobbled_xy(PolygonSoup soup) {
  for (std::size_t i = 0; i < soup.positions.size(); ++i) {
    soup.positions[i] += 0.1 * glm::dvec3(std::sin(7.0 * double(i)), std::cos(3.0 * double(i)), 0.0);
  }
  return soup;
}

/// A point turned by 0.7 rad about a tilted axis (Rodrigues' rotation) and moved: planes stay planes, and
/// the plane z = 0 becomes one that is no coordinate plane.
inline glm::dvec3 tilted(const glm::dvec3& p) {
  const glm::dvec3 axis = glm::normalize(glm::dvec3(1, 2, 3));
  const double angle = 0.7;
  return p * std::cos(angle) + glm::cross(axis, p) * std::sin(angle) +
         axis * glm::dot(axis, p) * (1 - std::cos(angle)) + glm::dvec3(0.5, -1.0, 2.0);
}
inline PolygonSoup tilted(PolygonSoup soup) {
  for (auto& p : soup.positions) p = tilted(p);
  return soup;
}

/// Open meshes with one to three boundary loops: a cup (half a capped hexagonal tube), a tube, grids with one
/// and two holes (their outer corners have two edges).
inline std::vector<PolygonSoup> open_polygon_soups() {
  return {halves_at_z(capped_tube_soup(6, 4)).first, open_tube_soup(8, 3), grid_with_holes(4, 4, {{1, 1}}),
          grid_with_holes(5, 4, {{1, 1}, {3, 2}})};
}

}  // namespace dlfl::test
