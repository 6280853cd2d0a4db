// The dual of an open mesh (boundary=curve: boundary edges give boundary vertices at their midpoints,
// boundary vertices give boundary edges, a sharp vertex also keeps itself), and dual-honeycomb-dual on open
// meshes, whose boundary converges to the quartic B-spline of the twice-midpointed boundary polygon.
#include <doctest/doctest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include <dlfl/build_mesh.h>
#include <dlfl/schemes/dual.h>
#include <dlfl/schemes/dual_honeycomb_dual.h>
#include <dlfl/schemes/origins.h>
#include <dlfl/statistics.h>
#include "boundary_checks.h"
#include "open_meshes.h"
#include "test_helpers.h"
#include "triangle_meshes.h"

using namespace dlfl;
using namespace dlfl::test;

namespace {

// The loop at z = 0 of open_tube_soup(8, 3): the regular octagon of radius 1.
std::vector<glm::dvec3> octagon() {
  std::vector<glm::dvec3> p;
  for (int i = 0; i < 8; ++i) {
    const double a = 2 * std::numbers::pi * i / 8;
    p.push_back({std::cos(a), std::sin(a), 0.0});
  }
  return p;
}

// Every origin set, of the kinds given.
void check_origin_kinds(const std::vector<Origin>& origins, std::initializer_list<Origin::Kind> kinds) {
  for (const Origin& o : origins) {
    CAPTURE(int(o.kind));
    CHECK(std::find(kinds.begin(), kinds.end(), o.kind) != kinds.end());
  }
}

}  // namespace

TEST_CASE("dual: the boundary of the dual of an open mesh is the polygon of its edge midpoints") {
  const Mesh tube = build_mesh(open_tube_soup(8, 3));
  const Mesh d = dual(tube);
  check_same_points(loop_at_z(d, 0.0, 0.0), edge_midpoints(octagon()), 1e-15);
  // A boundary vertex of valence 3 has two faces and two boundary edges: a quad, as every other face.
  CHECK(statistics(d).face_sizes == std::map<std::uint32_t, std::size_t>{{4, 32}});
  // The grid's corners (valence 2) keep themselves: one face, two midpoints and the corner, a quad too.
  const Mesh grid_dual = dual(build_mesh(grid_with_holes(3, 2, {})));
  CHECK(statistics(grid_dual).face_sizes == std::map<std::uint32_t, std::size_t>{{4, 12}});
  CHECK(marked_vertices(grid_dual).size() == 4);
}

TEST_CASE("dual: the dual of the dual of an open mesh is the mesh with a collar of quads") {
  // Tube: V = 32, E = 56, 24 quads and 2 holes of 8. Dual: V' = 24 + 16, E' = 56 + 16, F' = 32 + 2. Again:
  // V'' = 32 + 16, E'' = 72 + 16, F'' = 40 + 2: the tube's 24 quads and one quad per boundary edge, whose
  // outer corners are the twice-midpointed polygon (p_{i-1} + 2 p_i + p_{i+1}) / 4.
  const Mesh twice = dual(dual(build_mesh(open_tube_soup(8, 3))));
  require_valid(twice);
  CHECK(counts_of(twice) == MeshCounts{48, 88, 42});
  CHECK(statistics(twice).face_sizes == std::map<std::uint32_t, std::size_t>{{4, 40}});
  check_same_points(loop_at_z(twice, 0.0, 0.0), edge_midpoints(edge_midpoints(octagon())), 1e-15);
}

TEST_CASE("dual: under boundary=curve every element of an open mesh's dual has its origin") {
  const Mesh grid = build_mesh(grid_with_holes(4, 3, {{1, 1}}));
  Origins o;
  const Mesh d = dual(grid, &o);
  CHECK(d == dual(grid));
  // Vertices from faces (centroids), edges (midpoints) and vertices (kept corners); edges from edges (across)
  // and vertices (along the boundary); faces from vertices and the holes.
  check_origin_kinds(o.vertices, {Origin::Kind::face, Origin::Kind::edge, Origin::Kind::vertex});
  check_origin_kinds(o.edges, {Origin::Kind::edge, Origin::Kind::vertex});
  check_origin_kinds(o.faces, {Origin::Kind::vertex, Origin::Kind::face});
  for (VertexId v : d.vertices()) {
    const Origin src = o.of(v);
    if (src.kind == Origin::Kind::edge) {
      CHECK(d.position(v) ==
            0.5 * (grid.position(grid.from(src.edge())) + grid.position(grid.to(src.edge()))));
    } else if (src.kind == Origin::Kind::vertex) {
      CHECK(d.position(v) == grid.position(src.vertex()));
    }
  }
  for (FaceId f : d.faces()) CHECK(d.is_hole(f) == (o.of(f).kind == Origin::Kind::face));
  Origins dhd;
  HoneycombParams p;
  p.a = 0.6;
  CHECK(dual_honeycomb_dual(grid, p, &dhd) == dual_honeycomb_dual(grid, p));
  for (const auto* table : {&dhd.vertices, &dhd.edges, &dhd.faces}) {
    for (const Origin& src : *table) CHECK(src.kind != Origin::Kind::none);
  }
}

TEST_CASE(
    "dual-honeycomb-dual: the boundary is refined by the masks (1, 5, 7, 3) / 16 and (3, 7, 5, 1) / 16") {
  // dual: the midpoints m_i; honeycomb: (m_{i-1} + 2 m_i + m_{i+1}) / 4 and (m_i + m_{i+1}) / 2; dual: the
  // midpoints of those, in terms of the polygon p: (p_{i-1} + 5 p_i + 7 p_{i+1} + 3 p_{i+2}) / 16 and
  // (3 p_i + 7 p_{i+1} + 5 p_{i+2} + p_{i+3}) / 16, twice as many points.
  const std::vector<glm::dvec3> p = octagon();
  const auto at = [&](int i) { return p[(i + 8) % 8]; };
  std::vector<glm::dvec3> expected;
  for (int i = 0; i < 8; ++i) {
    expected.push_back((at(i - 1) + 5.0 * at(i) + 7.0 * at(i + 1) + 3.0 * at(i + 2)) / 16.0);
    expected.push_back((3.0 * at(i) + 7.0 * at(i + 1) + 5.0 * at(i + 2) + at(i + 3)) / 16.0);
  }
  check_same_points(loop_at_z(dual_honeycomb_dual(build_mesh(open_tube_soup(8, 3))), 0.0, 0.0), expected,
                    1e-15);
}

TEST_CASE(
    "dual-honeycomb-dual: an open tube's boundary converges to the quartic B-spline of the "
    "twice-midpointed polygon") {
  // The symbol of those masks is (1 + z)^3 (1 + z^2)^2 / 16: the quadratic B-spline convolved with two boxes
  // of width 2, that is the quartic B-spline of the control points (p_{j-1} + 2 p_j + p_{j+1}) / 4. The loop
  // approaches it by a factor 4 a step and does not shrink to a point.
  const auto curve = closed_bspline_samples(edge_midpoints(edge_midpoints(octagon())), 4, 256);
  double curve_radius = 1;
  for (const glm::dvec3& q : curve) curve_radius = std::min(curve_radius, std::hypot(q.x, q.y));
  Mesh m = build_mesh(open_tube_soup(8, 3));
  double first = 0;
  for (int step = 1; step <= 4; ++step) {
    CAPTURE(step);
    m = dual_honeycomb_dual(m);
    const auto loop = loop_at_z(m, 0.0, 0.0);
    const double distance = farthest_from(loop, curve);
    if (step == 1) first = distance;
    CHECK(distance <= 1.05 * first / std::pow(4.0, step - 1));
    for (const glm::dvec3& q : loop) CHECK(std::hypot(q.x, q.y) >= curve_radius - 1e-12);
  }
  CHECK(curve_radius > 0.7);
}

TEST_CASE("dual, dual-honeycomb-dual: open meshes through the editor, its undo and the log") {
  const Mesh grid = build_mesh(grid_with_holes(4, 3, {{1, 1}}));
  check_editor_and_log(grid, "dual", {}, dual(dual(grid)), badly_marked_grid());
  HoneycombParams p;
  p.a = 0.6;
  check_editor_and_log(grid, "dual-honeycomb-dual", {{"a", 0.6}},
                       dual_honeycomb_dual(dual_honeycomb_dual(grid, p), p), badly_marked_grid());
}
