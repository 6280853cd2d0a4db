#pragma once
// Helpers for the tests of the schemes' boundary rules: the boundary loops of a mesh, steps of a scheme, and
// an independent evaluation of uniform closed B-spline curves (the limit curves the rules promise).

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <limits>
#include <string>
#include <vector>

#include <dlfl/build_mesh.h>
#include <dlfl/mesh.h>
#include <dlfl/schemes/boundary_rule.h>
#include <dlfl/schemes/scheme_registry.h>
#include "open_meshes.h"

namespace dlfl::test {

/// The positions of the corners of every hole face, each loop in its face order.
inline std::vector<std::vector<glm::dvec3>> boundary_loops(const Mesh& m) {
  std::vector<std::vector<glm::dvec3>> loops;
  for (FaceId f : m.faces()) {
    if (!m.is_hole(f)) continue;
    auto& loop = loops.emplace_back();
    for (CornerId c : m.corners(f)) loop.push_back(m.position(m.vertex(c)));
  }
  return loops;
}

/// All the positions of the hole faces' corners.
inline std::vector<glm::dvec3> boundary_points(const Mesh& m) {
  std::vector<glm::dvec3> points;
  for (const auto& loop : boundary_loops(m)) points.insert(points.end(), loop.begin(), loop.end());
  return points;
}

/// The hole face's loop whose points all have z within `tol` of `z`; fails if there is none.
inline std::vector<glm::dvec3> loop_at_z(const Mesh& m, double z, double tol = 1e-9) {
  for (const auto& loop : boundary_loops(m)) {
    if (std::all_of(loop.begin(), loop.end(), [&](const glm::dvec3& p) { return std::abs(p.z - z) <= tol; }))
      return loop;
  }
  FAIL("no boundary loop at z = ", z);
  return {};
}

/// The distance from p to the nearest of `points` (infinity if there are none).
inline double distance_to_nearest(const glm::dvec3& p, const std::vector<glm::dvec3>& points) {
  double best = std::numeric_limits<double>::infinity();
  for (const glm::dvec3& q : points) best = std::min(best, glm::distance(p, q));
  return best;
}

/// True if some point of `points` lies within `tol` of p.
inline bool has_point(const std::vector<glm::dvec3>& points, const glm::dvec3& p, double tol = 1e-12) {
  return distance_to_nearest(p, points) <= tol;
}

/// The two point sets are the same to `tol`: as many points, each within `tol` of one of the other's.
inline void check_same_points(const std::vector<glm::dvec3>& a, const std::vector<glm::dvec3>& b,
                              double tol = 1e-12) {
  REQUIRE(a.size() == b.size());
  double worst = 0;
  for (const glm::dvec3& p : a) worst = std::max(worst, distance_to_nearest(p, b));
  for (const glm::dvec3& p : b) worst = std::max(worst, distance_to_nearest(p, a));
  CHECK(worst <= tol);
}

/// The vertices marked with a true `sharp` attribute (none without the attribute).
inline std::vector<VertexId> marked_vertices(const Mesh& m) {
  std::vector<VertexId> marked;
  const auto marks = m.find_attribute<VertexId, bool>(sharp_vertex_attribute);
  if (!marks) return marked;
  for (VertexId v : m.vertices()) {
    if ((*marks)[v]) marked.push_back(v);
  }
  return marked;
}

/// A mesh every scheme with a boundary rule refuses under boundary=curve: its `sharp` mark is not boolean.
inline Mesh badly_marked_grid() {
  Mesh m = build_mesh(grid_with_holes(2, 2, {}));
  m.add_vertex_attribute<int>(sharp_vertex_attribute, 1);
  return m;
}

/// `steps` steps of the scheme with these parameters.
inline Mesh steps_of(Mesh m, const std::string& scheme, const Params& params, int steps) {
  for (int i = 0; i < steps; ++i) m = apply_scheme(m, scheme, params);
  return m;
}

/// The uniform B-spline of degree d with knots at the integers, support [0, d + 1] (Cox-de Boor).
inline double uniform_bspline(int d, double x) {
  if (x < 0.0 || x >= d + 1) return 0.0;
  if (d == 0) return 1.0;
  return (x * uniform_bspline(d - 1, x) + (d + 1 - x) * uniform_bspline(d - 1, x - 1)) / d;
}

/// The closed uniform B-spline curve of degree d with control points c (periodic), at parameter u in
/// [0, n): sum over j of c_j B_d(u - j + k n), all wraps.
inline glm::dvec3 closed_bspline(const std::vector<glm::dvec3>& c, int d, double u) {
  const int n = int(c.size());
  glm::dvec3 p(0.0);
  for (int j = 0; j < n; ++j) {
    for (int wrap = -2; wrap <= 2; ++wrap) p += c[j] * uniform_bspline(d, u - j + wrap * n);
  }
  return p;
}

/// Samples of that curve, `per_span` per unit of the parameter.
inline std::vector<glm::dvec3> closed_bspline_samples(const std::vector<glm::dvec3>& c, int d, int per_span) {
  std::vector<glm::dvec3> samples;
  const int n = int(c.size());
  for (int i = 0; i < n * per_span; ++i) samples.push_back(closed_bspline(c, d, double(i) / per_span));
  return samples;
}

/// The midpoints of a closed polygon's edges: m_i = (p_i + p_{i+1}) / 2.
inline std::vector<glm::dvec3> edge_midpoints(const std::vector<glm::dvec3>& p) {
  std::vector<glm::dvec3> m;
  for (std::size_t i = 0; i < p.size(); ++i) m.push_back(0.5 * (p[i] + p[(i + 1) % p.size()]));
  return m;
}

/// The largest distance from a point of `points` to the sampled curve.
inline double farthest_from(const std::vector<glm::dvec3>& points, const std::vector<glm::dvec3>& curve) {
  double worst = 0;
  for (const glm::dvec3& p : points) worst = std::max(worst, distance_to_nearest(p, curve));
  return worst;
}

}  // namespace dlfl::test
