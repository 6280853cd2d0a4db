// sqrt(3)'s curve boundary rule (Kobbelt's, docs/boundaries.md), over pairs of steps: a step keeps the
// boundary loops it finds unmarked (their vertices stay, their edges are not flipped) and marks them
// sqrt3_trisect; the next trisects the marked ones by the ternary cubic B-spline rules. Expected values from
// that curve in closed form, from invariants and from the closed-form counts. (Agreement with CGAL's
// implementation over 2 and 4 steps is in tests/oracle.)

#include <doctest/doctest.h>

#include <cmath>
#include <numbers>

#include <dlfl/build_mesh.h>
#include <dlfl/errors.h>
#include <dlfl/schemes/scheme_registry.h>
#include <dlfl/schemes/sqrt3.h>
#include "boundary_curve_checks.h"
#include "modeling_checks.h"
#include "triangle_meshes.h"

using namespace dlfl;
using namespace dlfl::test;

namespace {

Mesh curve_step(const Mesh& m) { return sqrt3(m); }

// Whether hole face h carries the mark that has the next step trisect it.
bool marked_trisect(const Mesh& m, FaceId h) {
  const auto marks = m.find_attribute<FaceId, bool>(sqrt3_trisect_attribute);
  return marks && (*marks)[h];
}

FaceId hole_at(const Mesh& m, VertexId v) {
  for (CornerId c : m.corners(v)) {
    if (m.is_hole(m.face(c))) return m.face(c);
  }
  FAIL("no hole at the vertex");
  return FaceId();
}

std::vector<glm::dvec3> loop_from(const Mesh& m, VertexId v) {
  return positions_of(m, loop_vertices(m, hole_at(m, v), v));
}

}  // namespace

TEST_CASE("boundary curve, sqrt3: two halves of a closed mesh subdivided apart leave no crack") {
  for (const PolygonSoup& closed :
       {triangulated(capped_tube_soup(6, 4)), triangulated(wobbled_xy(capped_tube_soup(7, 4)))}) {
    for (int steps = 1; steps <= 4; ++steps) {
      CAPTURE(steps);
      CHECK(crack(curve_step, closed, steps) < 1e-12);
    }
  }
}

TEST_CASE(
    "boundary curve, sqrt3: a step keeps the boundary and marks it, the next trisects it towards the cubic "
    "B-spline of the boundary polygon") {
  const int around = 8;
  const double limit_radius = (4 + 2 * std::cos(2 * std::numbers::pi / around)) / 6;
  const Mesh tube = build_mesh(triangulated(open_tube_soup(around, 3)));
  const std::vector<glm::dvec3> polygon = loop_from(tube, VertexId(0));
  auto curve = [&](double u) { return closed_cubic_bspline(polygon, u); };
  Mesh m = tube;
  std::vector<glm::dvec3> before = polygon;
  double previous_error = 1;
  for (int steps = 1; steps <= 4; ++steps) {
    CAPTURE(steps);
    m = curve_step(m);
    const std::vector<glm::dvec3> q = loop_from(m, VertexId(0));
    if (steps % 2 == 1) {
      // Kept: the same loop, point for point, and both loops marked.
      CHECK(q == before);
      for (FaceId f : m.faces()) CHECK(marked_trisect(m, f) == m.is_hole(f));
    } else {
      // Trisected: vertex j is the control point at parameter j / 3^(k/2) of the same curve. No mark left.
      const int thirds = steps == 2 ? 3 : 9;
      REQUIRE(q.size() == std::size_t(around * thirds));
      CHECK(limit_point_error(q, thirds, curve) < 1e-12);
      CHECK_FALSE(m.has_face_attribute(sqrt3_trisect_attribute));
      // Vertex 0 closes in on its limit point, at radius (4 + 2 cos(2 pi / n)) / 6 (by 9 per pair of steps
      // in the long run: the subdominant eigenvalue of the ternary rules is 1/9).
      const double error = std::abs(glm::length(glm::dvec2(q[0])) - limit_radius);
      CHECK(error < previous_error / 5);
      previous_error = error;
      for (const glm::dvec3& p : q) CHECK(glm::length(glm::dvec2(p)) > 0.89);  // no shrinking
    }
    before = q;
  }
  CHECK(previous_error < 2e-3);  // two ternary refinements: about 1.1e-2 / 9
}

TEST_CASE("boundary curve, sqrt3: a planar boundary polygon stays in its plane") {
  const glm::dvec3 origin = tilted(glm::dvec3(0.0)), normal = tilted(glm::dvec3(0, 0, 1)) - origin;
  Mesh m = build_mesh(triangulated(tilted(halves_at_z(capped_tube_soup(6, 4)).first)));
  for (int steps = 1; steps <= 4; ++steps) {
    CAPTURE(steps);
    m = curve_step(m);
    for (const glm::dvec3& p : boundary_points(m)) CHECK(std::abs(glm::dot(p - origin, normal)) < 1e-12);
    double deepest = 0;
    for (VertexId v : m.vertices()) deepest = std::max(deepest, -glm::dot(m.position(v) - origin, normal));
    CHECK(deepest > 1.0);
  }
}

TEST_CASE("boundary curve, sqrt3: corners and marked vertices stay put, and stay marked") {
  // The triangulated 3 x 3 grid: vertex (i, j) is 4 j + i; corners 3 and 12 have two edges, 0 and 15 three
  // (the fan's diagonal), so they are marked to stay. A step gives the corners a third edge, so it marks
  // them to keep them sharp in the next.
  const Mesh grid = build_mesh(triangulated(grid_with_holes(3, 3, {})));
  const std::vector<VertexId> corners = {VertexId(0), VertexId(3), VertexId(12), VertexId(15)};
  Mesh m = grid;
  auto marks = m.add_vertex_attribute<bool>(sharp_vertex_attribute, false);
  marks[VertexId(0)] = marks[VertexId(15)] = true;
  for (int steps = 1; steps <= 4; ++steps) {
    CAPTURE(steps);
    m = curve_step(m);
    for (VertexId v : corners) {
      CHECK(m.position(v) == grid.position(v));
      CHECK(marked_sharp(m, v));
    }
    for (const glm::dvec3& p : boundary_points(m)) {
      CHECK(std::min({std::abs(p.x), std::abs(p.x - 3), std::abs(p.y), std::abs(p.y - 3)}) == 0.0);
    }
  }
  // Without the corner rule, the second step moves corner 3 = (3, 0) to (4, 19, 4) / 27 of (2, 0), itself
  // and (3, 1).
  const Mesh smooth = steps_of([](const Mesh& x) { return sqrt3(x, {BoundaryRule::curve, false}); }, grid, 2);
  CHECK(close(smooth.position(VertexId(3)), glm::dvec3(77.0 / 27, 4.0 / 27, 0), 1e-15));

  // A marked vertex of a tube's bottom loop, which becomes an open chain from it around to itself.
  Mesh tube = build_mesh(triangulated(open_tube_soup(8, 3)));
  tube.add_vertex_attribute<bool>(sharp_vertex_attribute, false)[VertexId(0)] = true;
  std::vector<glm::dvec3> chain = loop_from(tube, VertexId(0));
  chain.push_back(chain.front());
  m = tube;
  for (int steps = 1; steps <= 4; ++steps) {
    CAPTURE(steps);
    m = curve_step(m);
    CHECK(m.position(VertexId(0)) == tube.position(VertexId(0)));
    CHECK(marked_sharp(m, VertexId(0)));
    if (steps % 2 == 1) continue;
    // The chain's limit: the cubic B-spline of the chain extended by 2 p0 - p1 at both ends.
    const auto q = loop_from(m, VertexId(0));
    const double thirds = steps == 2 ? 3 : 9;
    double worst = 0;
    for (std::size_t j = 1; j < q.size(); ++j) {
      const glm::dvec3 limit = (q[j - 1] + 4.0 * q[j] + q[(j + 1) % q.size()]) / 6.0;
      worst = std::max(worst, glm::length(limit - open_cubic_bspline(chain, double(j) / thirds)));
    }
    CHECK(worst < 1e-12);
  }
}

TEST_CASE("boundary curve, sqrt3: counts, validity and genus with 1 to 3 boundary loops") {
  const Params params = resolve_scheme_params("sqrt3", {});
  for (const PolygonSoup& soup : open_polygon_soups()) {
    Mesh m = build_mesh(triangulated(soup));
    CAPTURE(m.num_hole_faces());
    for (int steps = 1; steps <= 4; ++steps) {
      CAPTURE(steps);
      const Mesh out = curve_step(m);
      // A kept step: a face point per triangle, three triangles for each (one per corner), the boundary as
      // it was. A trisecting one: the triangles on the boundary get two points on their boundary edge (B of
      // them) instead of a face point; still three triangles each, and every boundary edge in three.
      const OpenCounts c = open_counts(m);
      const std::size_t b = steps % 2 == 1 ? 0 : c.boundary;
      CHECK(open_counts(out) == OpenCounts{c.vertices + c.faces + b, c.edges + 3 * c.faces + b, 3 * c.faces,
                                           c.holes, steps % 2 == 1 ? c.boundary : 3 * c.boundary});
      check_same_topology(m, out);
      // The declared counts read V, E and F only: on an open mesh E and F are bounds (E' = 3E exactly when
      // trisecting), V' = V + F is short by B - H when trisecting (see sqrt3.h).
      const auto predicted = predict_counts("sqrt3", params, counts_of(m), 1);
      REQUIRE(predicted);
      CHECK(predicted->edges >= counts_of(out).edges);
      CHECK(predicted->faces >= counts_of(out).faces);
      CHECK(predicted->vertices + b == counts_of(out).vertices + c.holes);
      m = out;
    }
  }
}

TEST_CASE("boundary curve, sqrt3: steps run one by one, through the editor, undo and the log") {
  // The mark carries the parity from step to step: three separate steps are one run of three.
  const Mesh tube = build_mesh(triangulated(open_tube_soup(6, 2)));
  const Mesh three = curve_step(curve_step(curve_step(tube)));
  const Mesh run = check_editor_round_trip(tube, "subdivide", {{"scheme", "sqrt3"}, {"iterations", 3}});
  CHECK(run == three);
  Editor ed;
  ed.set_mesh(tube);
  for (int i = 0; i < 3; ++i) ed.subdivide("sqrt3");
  CHECK(ed.mesh() == three);
}

TEST_CASE("boundary curve, sqrt3: what one step cannot trisect is refused, naming it") {
  // A triangle with two boundary edges on a marked loop (the grid's corner triangle at vertex 3): trisecting
  // both is no sqrt(3) step. An unmarked loop is fine (the first step gives every triangle one boundary edge
  // at most).
  Mesh grid = build_mesh(triangulated(grid_with_holes(3, 3, {})));
  CHECK_NOTHROW(curve_step(grid));
  const FaceId hole = hole_at(grid, VertexId(3));
  grid.add_face_attribute<bool>(sqrt3_trisect_attribute, false)[hole] = true;
  const Mesh copy = grid;
  FaceId corner;
  for (CornerId c : grid.corners(VertexId(3))) {
    if (!grid.is_hole(grid.face(c))) corner = grid.face(c);
  }
  CHECK(error_message<TopologyError>([&] { curve_step(grid); }) ==
        "sqrt3: " + to_string(corner) +
            " has two edges on boundary loops to trisect (attribute sqrt3_trisect), which one sqrt(3) step "
            "cannot make; a step with the loops unmarked can");
  CHECK(grid == copy);

  // An edge with holes on both sides: the grid's corner triangle made a hole too.
  Mesh bare = build_mesh(triangulated(grid_with_holes(3, 3, {})));
  FaceId triangle;
  for (CornerId c : bare.corners(VertexId(3))) {
    if (!bare.is_hole(bare.face(c))) triangle = bare.face(c);
  }
  bare.set_hole(triangle, true);
  const std::string message = error_message<TopologyError>([&] { curve_step(bare); });
  CHECK(message.find("has holes on both sides; the boundary rule needs a surface face at every edge") !=
        std::string::npos);
}
