// The boundary rules of Doo-Sabin (Chaikin along the boundary: the quadratic B-spline of the boundary
// polygon) and of the two honeycombs (vertex insertion then corner cutting, Zhang-Wang's formula (15) with
// s_n = 1/2: the quadratic B-spline of the polygon of edge midpoints), checked against those closed forms on
// an open tube, whose loops used to shrink to a point. docs/boundaries.md derives the curves.
#include <doctest/doctest.h>

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include <dlfl/build_mesh.h>
#include <dlfl/schemes/doo_sabin.h>
#include <dlfl/schemes/honeycomb.h>
#include <dlfl/schemes/origins.h>
#include <dlfl/schemes/zhang_wang_honeycomb.h>
#include "boundary_checks.h"
#include "open_meshes.h"
#include "test_helpers.h"
#include "triangle_meshes.h"

using namespace dlfl;
using namespace dlfl::test;

namespace {

constexpr double pi = std::numbers::pi;

// The loop at z = 0 of open_tube_soup(8, 3): the regular octagon of radius 1.
std::vector<glm::dvec3> octagon() {
  std::vector<glm::dvec3> p;
  for (int i = 0; i < 8; ++i) p.push_back({std::cos(2 * pi * i / 8), std::sin(2 * pi * i / 8), 0.0});
  return p;
}

glm::dvec3 at(const std::vector<glm::dvec3>& p, int i) { return p[(i + p.size()) % p.size()]; }

double radius(const glm::dvec3& p) { return std::hypot(p.x, p.y); }

double min_radius(const std::vector<glm::dvec3>& points) {
  double r = 1e300;
  for (const glm::dvec3& p : points) r = std::min(r, radius(p));
  return r;
}

double max_radius(const std::vector<glm::dvec3>& points) {
  double r = 0;
  for (const glm::dvec3& p : points) r = std::max(r, radius(p));
  return r;
}

const Params hole_rule = {{"boundary", "hole"}};

}  // namespace

TEST_CASE("doo-sabin: the boundary is Chaikin's refinement of the boundary polygon") {
  const std::vector<glm::dvec3> p = octagon();
  const auto loop = loop_at_z(doo_sabin(build_mesh(open_tube_soup(8, 3))), 0.0, 0.0);
  // Two points per edge, at 1/4 and 3/4, and nothing else: as many points as before, twice.
  std::vector<glm::dvec3> chaikin;
  for (int i = 0; i < 8; ++i) {
    chaikin.push_back(0.75 * at(p, i) + 0.25 * at(p, i + 1));
    chaikin.push_back(0.25 * at(p, i) + 0.75 * at(p, i + 1));
  }
  check_same_points(loop, chaikin, 1e-15);
}

TEST_CASE("doo-sabin: an open tube's boundary converges to the quadratic B-spline of its polygon") {
  // The quadratic B-spline of the octagon passes through each edge's midpoint and through
  // (p_{i-1} + 6 p_i + p_{i+1}) / 8 next to each vertex; Chaikin keeps every edge's midpoint, so both are
  // midpoints of boundary edges at every step. The loop's points approach the curve by a factor 4 a step,
  // from outside (a convex polygon's Chaikin polygons enclose its limit): radius at least cos(pi/8).
  const std::vector<glm::dvec3> p = octagon();
  const auto curve = closed_bspline_samples(p, 2, 512);
  const double start = farthest_from(p, curve);
  Mesh m = build_mesh(open_tube_soup(8, 3));
  Mesh old_rule = m;
  for (int step = 1; step <= 4; ++step) {
    CAPTURE(step);
    m = doo_sabin(m);
    const auto loop = loop_at_z(m, 0.0, 0.0);
    const auto midpoints = edge_midpoints(loop);
    for (int i = 0; i < 8; ++i) {
      CHECK(has_point(midpoints, 0.5 * (at(p, i) + at(p, i + 1)), 1e-12));
      CHECK(has_point(midpoints, (at(p, i - 1) + 6.0 * at(p, i) + at(p, i + 1)) / 8.0, 1e-12));
    }
    CHECK(farthest_from(loop, curve) <= 1.05 * start / std::pow(4.0, step));
    CHECK(min_radius(loop) >= std::cos(pi / 8) - 1e-12);
    // The old rule shrinks the loop towards its centre: radius 1/2, 1/4, ... (the measurement).
    old_rule = doo_sabin(old_rule, BoundaryOptions{BoundaryRule::hole});
    CHECK(max_radius(loop_at_z(old_rule, 0.0)) == doctest::Approx(std::pow(0.5, step)));
  }
}

TEST_CASE("doo-sabin: next to a sharp vertex the boundary is clamped, and midpoints elsewhere persist") {
  // Vertex 0 of the octagon marked: the chain from it around to itself is a clamped quadratic B-spline. Its
  // refinement keeps p_0, puts the midpoints of its two edges next to it (not the Chaikin points), and keeps
  // the midpoints of the other edges as midpoints of boundary edges.
  const std::vector<glm::dvec3> p = octagon();
  Mesh m = build_mesh(open_tube_soup(8, 3));
  m.add_vertex_attribute<bool>(sharp_vertex_attribute, false)[VertexId(0)] = true;
  const auto first = loop_at_z(doo_sabin(m), 0.0, 0.0);
  CHECK(has_point(first, p[0], 0.0));
  CHECK(has_point(first, 0.5 * (p[0] + p[1])));
  CHECK(has_point(first, 0.5 * (p[0] + p[7])));
  CHECK_FALSE(has_point(first, 0.75 * p[0] + 0.25 * p[1], 1e-6));
  CHECK(first.size() == 15);  // the kept vertex is one point where the others have two
  for (int step = 1; step <= 3; ++step) m = doo_sabin(m);
  const auto loop = loop_at_z(m, 0.0, 0.0);
  CHECK(has_point(loop, p[0], 0.0));
  for (int i = 1; i < 7; ++i) CHECK(has_point(edge_midpoints(loop), 0.5 * (at(p, i) + at(p, i + 1)), 1e-12));
}

TEST_CASE("doo-sabin: corners of two edges keep their place and leave no 2-gon") {
  // grid 3 x 2: V = 12, E = 17, 6 quads, one hole of 10 corners, four corners of one face. Their V-faces
  // would be 2-gons (the face's point and the kept corner): left out, so F' = V + E + F - 4 = 32 and the kept
  // corner gets three edges and the mark that keeps it over the next steps.
  const Mesh grid = build_mesh(grid_with_holes(3, 2, {}));
  const Mesh out = doo_sabin(grid);
  require_valid(out);
  CHECK(out.num_faces() == 12 + 17 + 7 - 4);
  CHECK(face_size_histogram(out).begin()->first == 4);  // triangles come next step, at the kept corners
  const std::vector<VertexId> marked = marked_vertices(out);
  CHECK(marked.size() == 4);
  for (VertexId v : marked) {
    CHECK(out.valence(v) == 3);
    const glm::dvec3 q = out.position(v);
    CHECK(((q.x == 0 || q.x == 3) && (q.y == 0 || q.y == 2)));
  }
  // The old rule made those 2-gons.
  CHECK(face_size_histogram(doo_sabin(grid, BoundaryOptions{BoundaryRule::hole})).begin()->first == 2);
}

TEST_CASE("honeycomb: the boundary is vertex insertion then corner cutting of the boundary polygon") {
  // Step 1 on the octagon: the midpoint of every edge, and every vertex cut off by the chord between the
  // midpoints of its edges, at the chord's midpoint (p_{i-1} + 2 p_i + p_{i+1}) / 4.
  const std::vector<glm::dvec3> p = octagon();
  const auto loop = loop_at_z(honeycomb(build_mesh(open_tube_soup(8, 3))), 0.0, 0.0);
  std::vector<glm::dvec3> expected;
  for (int i = 0; i < 8; ++i) {
    expected.push_back(0.5 * (at(p, i) + at(p, i + 1)));
    expected.push_back((at(p, i - 1) + 2.0 * at(p, i) + at(p, i + 1)) / 4.0);
  }
  check_same_points(loop, expected, 1e-15);
}

TEST_CASE("honeycomb: an open tube's boundary converges to the quadratic B-spline of its edge midpoints") {
  // The limit is the quadratic B-spline whose control points are the octagon's edge midpoints: it passes
  // through (p_{i-1} + 2 p_i + p_{i+1}) / 4, the vertex point of step 1, which stays where it is, and through
  // (p_{i-1} + 7 p_i + 7 p_{i+1} + p_{i+2}) / 16 halfway along each edge, where the midpoint of step 1 lands
  // at step 2. The loop approaches the curve by a factor 4 a step and keeps a radius of at least that of
  // the curve's points, (2 + 2 cos(pi/4)) / 4; the old rule shrinks it to 0.618, 0.382, ...
  const std::vector<glm::dvec3> p = octagon();
  const auto curve = closed_bspline_samples(edge_midpoints(p), 2, 512);
  Mesh m = build_mesh(open_tube_soup(8, 3));
  Mesh old_rule = m;
  HoneycombParams hole;
  hole.boundary.rule = BoundaryRule::hole;
  double first = 0;
  for (int step = 1; step <= 4; ++step) {
    CAPTURE(step);
    m = honeycomb(m);
    const auto loop = loop_at_z(m, 0.0, 0.0);
    for (int i = 0; i < 8; ++i) {
      CHECK(has_point(loop, (at(p, i - 1) + 2.0 * at(p, i) + at(p, i + 1)) / 4.0, 1e-12));
      if (step >= 2)
        CHECK(has_point(loop, (at(p, i - 1) + 7.0 * at(p, i) + 7.0 * at(p, i + 1) + at(p, i + 2)) / 16.0,
                        1e-12));
    }
    const double distance = farthest_from(loop, curve);
    if (step == 1) first = distance;
    CHECK(distance <= 1.05 * first / std::pow(4.0, step - 1));
    CHECK(min_radius(loop) >= (2 + 2 * std::cos(pi / 4)) / 4 - 1e-12);
    old_rule = honeycomb(old_rule, hole);
    CHECK(max_radius(loop_at_z(old_rule, 0.0)) < std::pow(0.62, step));
  }
}

TEST_CASE("honeycomb: the 2-valent boundary vertices of a step are already where the rule puts them") {
  // After one step every other boundary vertex has two edges, so sharp_corners keeps them all; each is the
  // midpoint of its two neighbours, where the rule would move it, so keeping and smoothing agree.
  const Mesh once = honeycomb(build_mesh(open_tube_soup(8, 3)));
  HoneycombParams smooth;
  smooth.boundary.sharp_corners = false;
  check_same_points(boundary_points(honeycomb(once)), boundary_points(honeycomb(once, smooth)), 1e-15);
}

TEST_CASE("honeycomb-zw: formula (15) with s_n = 1/2 gives the honeycomb's boundary curve") {
  // The boundary depends on the boundary polygon alone, so Zhang-Wang's steps, whose faces inside differ,
  // put the same points on it as the honeycomb's.
  Mesh zw = build_mesh(open_tube_soup(8, 3)), ak = zw;
  for (int step = 1; step <= 3; ++step) {
    CAPTURE(step);
    zw = zhang_wang_honeycomb(zw);
    ak = honeycomb(ak);
    check_same_points(boundary_points(zw), boundary_points(ak), 1e-12);
  }
}

TEST_CASE("honeycomb-zw: a hole has no CCV, and a boundary vertex's face spreads 1 - alpha over its faces") {
  // grid 3 x 2 (unit quads, CCVs their centroids): vertex (1, 0) has neighbours (0, 0), (2, 0), (1, 1) and
  // the faces of centroids (0.5, 0.5), (1.5, 0.5). Formula (4) with c = 1/2, alpha = 1/2 over the three
  // neighbours and the two faces: q~ = v/2 + (1/2)((1/2) mean of neighbours + (1/2) mean of CCVs).
  const Mesh grid = build_mesh(grid_with_holes(3, 2, {}));
  Origins o;
  const Mesh out = zhang_wang_honeycomb(grid, {}, &o);
  const glm::dvec3 v(1, 0, 0),
      neighbours = (glm::dvec3(0, 0, 0) + glm::dvec3(2, 0, 0) + glm::dvec3(1, 1, 0)) / 3.0;
  const glm::dvec3 ccvs = (glm::dvec3(0.5, 0.5, 0) + glm::dvec3(1.5, 0.5, 0)) / 2.0;
  std::size_t checked = 0;
  for (FaceId f : out.faces()) {
    if (out.is_hole(f)) {
      CHECK_FALSE(face_point(out, f));
      continue;
    }
    const Origin src = o.of(f);
    if (src.kind != Origin::Kind::vertex || grid.position(src.vertex()) != v) continue;
    CHECK(close(*face_point(out, f), 0.5 * v + 0.5 * (0.5 * neighbours + 0.5 * ccvs), 1e-15));
    ++checked;
  }
  CHECK(checked == 1);
}

TEST_CASE("doo-sabin, honeycomb, honeycomb-zw: open meshes through the editor, its undo and the log") {
  const Mesh grid = build_mesh(grid_with_holes(4, 3, {{1, 1}}));
  check_editor_and_log(grid, "doo-sabin", {}, doo_sabin(doo_sabin(grid)), badly_marked_grid());
  check_editor_and_log(grid, "honeycomb", {}, honeycomb(honeycomb(grid)), badly_marked_grid());
  check_editor_and_log(grid, "honeycomb-zw", {}, zhang_wang_honeycomb(zhang_wang_honeycomb(grid)),
                       badly_marked_grid());
  // The log records the rule, and boundary=hole replays the old rule (which refuses a point sphere).
  Mesh sphere = test::cube();
  sphere.create_vertex({5, 5, 5});
  const BoundaryOptions hole{BoundaryRule::hole};
  check_editor_and_log(grid, "doo-sabin", hole_rule, doo_sabin(doo_sabin(grid, hole), hole), sphere);
}

#ifdef DLFL_TOOL
#include <filesystem>
#include <fstream>

#include <dlfl/io/mesh_io.h>

#include "tool_runner.h"

TEST_CASE(
    "doo-sabin: the tool subdivides an open grid with corners into a file, which the old rule could not") {
  const auto in = scratch("grid.obj");
  {
    std::ofstream obj(in);
    for (int j = 0; j <= 2; ++j) {
      for (int i = 0; i <= 3; ++i) obj << "v " << i << ' ' << j << " 0\n";
    }
    for (int j = 0; j < 2; ++j) {
      for (int i = 0; i < 3; ++i) {
        const int a = j * 4 + i + 1;
        obj << "f " << a << ' ' << a + 1 << ' ' << a + 5 << ' ' << a + 4 << '\n';
      }
    }
  }
  const auto out = scratch("grid-doo-sabin.obj");
  const Run r = run("subdivide '" + in.string() + "' -s doo-sabin -n 2 -o '" + out.string() + "'");
  CHECK(r.exit_code == 0);
  const Mesh m = read_mesh(out.string());
  CHECK(face_size_histogram(m).begin()->first >= 3);
  const auto points = boundary_points(m);
  for (const glm::dvec3& c : {glm::dvec3(0, 0, 0), glm::dvec3(3, 2, 0)}) CHECK(has_point(points, c, 0.0));
  const Run old = run("subdivide '" + in.string() + "' -s doo-sabin --param boundary=hole -o '" +
                      scratch("old.obj").string() + "'");
  CHECK(old.exit_code != 0);
}
#endif
