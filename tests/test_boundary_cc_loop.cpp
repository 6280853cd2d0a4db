// The curve boundary rule of Catmull-Clark and Loop (docs/boundaries.md): a boundary edge's point at its
// midpoint, a boundary vertex at (1/8, 6/8, 1/8) of its loop neighbours and itself, so that the boundary is
// the cubic B-spline subdivision of the boundary polygon, independent of the faces inside. Expected values
// come from that curve in closed form, from invariants (no crack, planarity, Euler characteristic) and from
// the closed-form counts. (Agreement with CGAL's implementation is in tests/oracle.)

#include <doctest/doctest.h>

#include <cmath>
#include <numbers>

#include <dlfl/build_mesh.h>
#include <dlfl/io/mesh_io.h>
#include <dlfl/mesh_hash.h>
#include <dlfl/schemes/catmull_clark.h>
#include <dlfl/schemes/loop.h>
#include <dlfl/schemes/scheme_registry.h>
#include "boundary_curve_checks.h"
#include "tool_runner.h"
#include "triangle_meshes.h"

using namespace dlfl;
using namespace dlfl::test;

namespace {

struct BinaryScheme {
  std::string name;
  bool triangles;  // Loop: the inputs triangulated
  std::function<Mesh(const Mesh&, const BoundaryOptions&)> step;
  // The counts of one step under the curve rule, in closed form (see the scheme's header).
  std::function<OpenCounts(const OpenCounts&)> counts;
};

const std::vector<BinaryScheme>& binary_schemes() {
  static const std::vector<BinaryScheme> schemes = {
      {"catmull-clark", false, [](const Mesh& m, const BoundaryOptions& b) { return catmull_clark(m, b); },
       [](const OpenCounts& c) {
         // A quad per surface corner (C_s = 2E - B), an edge point per edge, a face point per surface face;
         // every hole keeps its face with twice the sides.
         const std::size_t corners = 2 * c.edges - c.boundary;
         return OpenCounts{c.vertices + c.edges + c.faces, 2 * c.edges + corners, corners, c.holes,
                           2 * c.boundary};
       }},
      {"loop", true, [](const Mesh& m, const BoundaryOptions& b) { return loop(m, b); },
       [](const OpenCounts& c) {
         return OpenCounts{c.vertices + c.edges, 2 * c.edges + 3 * c.faces, 4 * c.faces, c.holes,
                           2 * c.boundary};
       }},
  };
  return schemes;
}

PolygonSoup input_for(const BinaryScheme& s, const PolygonSoup& soup) {
  return s.triangles ? triangulated(soup) : soup;
}

SchemeStep curve_step(const BinaryScheme& s, BoundaryOptions options = {}) {
  return [&s, options](const Mesh& m) { return s.step(m, options); };
}

// The hole face of m through vertex v.
FaceId hole_at(const Mesh& m, VertexId v) {
  for (CornerId c : m.corners(v)) {
    if (m.is_hole(m.face(c))) return m.face(c);
  }
  FAIL("no hole at the vertex");
  return FaceId();
}

}  // namespace

TEST_CASE(
    "boundary curve, catmull-clark and loop: two halves of a closed mesh subdivided apart leave no crack") {
  for (const BinaryScheme& s : binary_schemes()) {
    CAPTURE(s.name);
    for (const PolygonSoup& closed : {capped_tube_soup(6, 4), wobbled_xy(capped_tube_soup(7, 4))}) {
      for (int steps = 1; steps <= 4; ++steps) {
        CAPTURE(steps);
        CHECK(crack(curve_step(s), input_for(s, closed), steps) < 1e-12);
      }
    }
  }
  // The old rule smooths each half's boundary as if capped, so the halves part (by about a third of the
  // radius here).
  const SchemeStep hole = [](const Mesh& m) { return catmull_clark(m, {BoundaryRule::hole}); };
  CHECK(crack(hole, capped_tube_soup(6, 4), 1) > 0.1);
}

TEST_CASE(
    "boundary curve, catmull-clark and loop: an open tube's boundary converges to the cubic B-spline of its "
    "boundary polygon, not to a point") {
  const int around = 8;
  const double limit_radius = (4 + 2 * std::cos(2 * std::numbers::pi / around)) / 6;  // 0.902...
  for (const BinaryScheme& s : binary_schemes()) {
    CAPTURE(s.name);
    const Mesh tube = build_mesh(input_for(s, open_tube_soup(around, 3)));
    // The bottom loop from vertex 0 in the hole's order; vertex 0 stays vertex 0 in every step.
    const std::vector<glm::dvec3> polygon =
        positions_of(tube, loop_vertices(tube, hole_at(tube, VertexId(0)), VertexId(0)));
    auto curve = [&](double u) { return closed_cubic_bspline(polygon, u); };
    double previous_error = 1;
    Mesh m = tube;
    for (int steps = 1; steps <= 4; ++steps) {
      CAPTURE(steps);
      m = s.step(m, {});
      const auto q = positions_of(m, loop_vertices(m, hole_at(m, VertexId(0)), VertexId(0)));
      REQUIRE(q.size() == std::size_t(around) << steps);
      // Vertex j of the loop after k steps is the control point at parameter j / 2^k of the same curve: its
      // limit point (1/6, 4/6, 1/6) lies on the curve there.
      CHECK(limit_point_error(q, double(1 << steps), curve) < 1e-12);
      // Vertex 0 closes in on its limit point, at radius (4 + 2 cos(2 pi / n)) / 6 (a curvature term that
      // shrinks by 4 per step, the subdominant eigenvalue 1/4 of the cubic B-spline rules).
      const double error = std::abs(glm::length(glm::dvec2(q[0])) - limit_radius);
      CHECK(error < previous_error / 3);
      previous_error = error;
      for (const glm::dvec3& p : q) CHECK(glm::length(glm::dvec2(p)) > 0.89);  // no shrinking
    }
    CHECK(previous_error < 1e-3);
  }
}

TEST_CASE("boundary curve, catmull-clark and loop: a planar boundary polygon stays in its plane") {
  const glm::dvec3 origin = tilted(glm::dvec3(0.0)), normal = tilted(glm::dvec3(0, 0, 1)) - origin;
  for (const BinaryScheme& s : binary_schemes()) {
    CAPTURE(s.name);
    // A cup whose rim lies in the tilted image of z = 0, its bottom 1.5 below it.
    Mesh m = build_mesh(input_for(s, tilted(halves_at_z(capped_tube_soup(6, 4)).first)));
    for (int steps = 1; steps <= 3; ++steps) {
      CAPTURE(steps);
      m = s.step(m, {});
      for (const glm::dvec3& p : boundary_points(m)) CHECK(std::abs(glm::dot(p - origin, normal)) < 1e-12);
      double deepest = 0;
      for (VertexId v : m.vertices()) deepest = std::max(deepest, -glm::dot(m.position(v) - origin, normal));
      CHECK(deepest > 1.0);
    }
  }
}

TEST_CASE("boundary curve, catmull-clark and loop: corners and marked vertices stay put, and stay marked") {
  for (const BinaryScheme& s : binary_schemes()) {
    CAPTURE(s.name);
    // A 3 x 3 grid: vertex (i, j) is 4 j + i. Corners 3 and 12 have two edges in both meshes; 0 and 15 too
    // on the quads, but the fan triangulation adds a diagonal there, so on triangles they have three and are
    // marked here to stay.
    const Mesh grid = build_mesh(input_for(s, grid_with_holes(3, 3, {})));
    Mesh m = grid;
    auto marks = m.add_vertex_attribute<bool>(sharp_vertex_attribute, false);
    const std::vector<VertexId> corners = {VertexId(0), VertexId(3), VertexId(12), VertexId(15)};
    for (VertexId v : corners) marks[v] = grid.valence(v) == 3;
    for (int steps = 1; steps <= 3; ++steps) {
      m = s.step(m, {});
      for (VertexId v : corners) CHECK(m.position(v) == grid.position(v));
      // The sides stay on the square: their points are averages of points with that coordinate.
      for (const glm::dvec3& p : boundary_points(m)) {
        CHECK(std::min({std::abs(p.x), std::abs(p.x - 3), std::abs(p.y), std::abs(p.y - 3)}) == 0.0);
      }
    }
    // Without the corner rule (or at a corner with three edges), (1/8, 6/8, 1/8) of (1, 0), (0, 0), (0, 1).
    const Mesh smooth = s.step(grid, {BoundaryRule::curve, false});
    CHECK(smooth.position(VertexId(0)) == glm::dvec3(0.125, 0.125, 0));
    CHECK(s.step(grid, {}).position(VertexId(0)) ==
          (grid.valence(VertexId(0)) == 2 ? glm::dvec3(0.0) : glm::dvec3(0.125, 0.125, 0)));

    // A marked vertex of a tube's bottom loop, which becomes an open chain from it around to itself: it
    // stays put over every step and keeps its mark; nothing else is marked.
    Mesh tube = build_mesh(input_for(s, open_tube_soup(8, 3)));
    tube.add_vertex_attribute<bool>(sharp_vertex_attribute, false)[VertexId(0)] = true;
    const auto chain_vertices = loop_vertices(tube, hole_at(tube, VertexId(0)), VertexId(0));
    std::vector<glm::dvec3> chain = positions_of(tube, chain_vertices);
    chain.push_back(chain.front());
    m = tube;
    for (int steps = 1; steps <= 4; ++steps) {
      CAPTURE(steps);
      m = s.step(m, {});
      CHECK(m.position(VertexId(0)) == tube.position(VertexId(0)));
      std::size_t marks = 0;
      for (VertexId v : m.vertices()) marks += marked_sharp(m, v);
      CHECK(marks == 1);
      CHECK(marked_sharp(m, VertexId(0)));
      // The chain's limit: the cubic B-spline of the chain extended by 2 p0 - p1 at both ends (the open
      // curve interpolates vertex 0); the limit point of the sharp vertex is itself.
      auto q = positions_of(m, loop_vertices(m, hole_at(m, VertexId(0)), VertexId(0)));
      double worst = glm::length(q[0] - chain.front());
      const std::size_t n = q.size();
      for (std::size_t j = 1; j < n; ++j) {
        const glm::dvec3 limit = (q[j - 1] + 4.0 * q[j] + q[(j + 1) % n]) / 6.0;
        worst =
            std::max(worst, glm::length(limit - open_cubic_bspline(chain, double(j) / double(1 << steps))));
      }
      CHECK(worst < 1e-12);
    }
  }
}

TEST_CASE("boundary curve, catmull-clark and loop: counts, validity and genus with 1 to 3 boundary loops") {
  for (const BinaryScheme& s : binary_schemes()) {
    CAPTURE(s.name);
    const Params params = resolve_scheme_params(s.name, {});
    for (const PolygonSoup& soup : open_polygon_soups()) {
      Mesh m = build_mesh(input_for(s, soup));
      CAPTURE(m.num_hole_faces());
      for (int steps = 1; steps <= 2; ++steps) {
        const Mesh out = s.step(m, {});
        CHECK(open_counts(out) == s.counts(open_counts(m)));
        check_same_topology(m, out);
        // The declared counts read V, E and F only: on an open mesh they bound the curve rule's from above.
        const auto predicted = predict_counts(s.name, params, counts_of(m), 1);
        REQUIRE(predicted);
        const MeshCounts actual = counts_of(out);
        CHECK(predicted->vertices >= actual.vertices);
        CHECK(predicted->edges >= actual.edges);
        CHECK(predicted->faces >= actual.faces);
        m = out;
      }
    }
  }
}

TEST_CASE("boundary curve, catmull-clark and loop: edges with holes on both sides") {
  // The grid's face at corner 3 made a hole too: its two outer edges have holes on both sides, and corner 3,
  // on two hole corners, stays. Both holes stay whole, with the closed-form counts.
  for (const BinaryScheme& s : binary_schemes()) {
    CAPTURE(s.name);
    Mesh m = build_mesh(input_for(s, grid_with_holes(3, 3, {})));
    for (CornerId c : m.corners(VertexId(3))) {
      if (!m.is_hole(m.face(c))) {
        m.set_hole(m.face(c), true);
        break;
      }
    }
    for (int steps = 1; steps <= 2; ++steps) {
      const Mesh out = s.step(m, {BoundaryRule::curve, false});
      CHECK(open_counts(out) == s.counts(open_counts(m)));
      check_same_topology(m, out);
      CHECK(out.position(VertexId(3)) == glm::dvec3(3, 0, 0));
      m = out;
    }
  }
}

TEST_CASE("boundary curve, catmull-clark and loop: the registry passes boundary and sharp_corners") {
  for (const BinaryScheme& s : binary_schemes()) {
    CAPTURE(s.name);
    const Mesh grid = build_mesh(input_for(s, grid_with_holes(3, 2, {})));
    CHECK(apply_scheme(grid, s.name) == s.step(grid, {}));
    CHECK(apply_scheme(grid, s.name, {{"sharp_corners", false}}) ==
          s.step(grid, {BoundaryRule::curve, false}));
    if (!s.triangles) {  // Loop's old rule takes triangular holes only
      CHECK(apply_scheme(grid, s.name, {{"boundary", "hole"}}) == s.step(grid, {BoundaryRule::hole}));
      CHECK(apply_scheme(grid, s.name, {{"boundary", "hole"}}) != apply_scheme(grid, s.name));
    }
  }
}

#ifdef DLFL_TOOL
TEST_CASE("boundary curve: dlfl subdivide uses the curve rule, and boundary=hole the old one") {
  const auto grid = scratch("boundary_grid.obj");
  write_mesh(build_mesh(grid_with_holes(3, 3, {{1, 1}})), grid);
  const Mesh in = read_mesh(grid);
  auto hash_of = [](const std::filesystem::path& path) { return mesh_hash(read_mesh(path)); };
  const auto curve = scratch("boundary_curve.json"), hole = scratch("boundary_hole.json");
  REQUIRE(run("subdivide '" + grid.string() + "' -s catmull-clark -o '" + curve.string() + "'").exit_code ==
          0);
  REQUIRE(run("subdivide '" + grid.string() + "' -s catmull-clark --param boundary=hole -o '" +
              hole.string() + "'")
              .exit_code == 0);
  CHECK(hash_of(curve) == mesh_hash(catmull_clark(in)));
  CHECK(hash_of(hole) == mesh_hash(catmull_clark(in, {BoundaryRule::hole})));
  CHECK(hash_of(curve) != hash_of(hole));
}
#endif
