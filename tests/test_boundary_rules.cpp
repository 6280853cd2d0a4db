// The boundary rules of Doo-Sabin, the two honeycombs, dual and dual-honeycomb-dual (boundary=curve): what
// they share. Two halves of a closed mesh meet without a crack, a planar boundary stays in its plane, closed
// meshes are not touched, the counts follow the closed forms of the headers on meshes with 1 to 3 boundary
// loops, sharp corners and marked vertices stay in place, and bad marks are refused before any work.
#include <doctest/doctest.h>

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include <dlfl/build_mesh.h>
#include <dlfl/errors.h>
#include <dlfl/schemes/boundary_rule.h>
#include <dlfl/schemes/scheme_registry.h>
#include <dlfl/statistics.h>
#include <dlfl/validate.h>
#include "boundary_checks.h"
#include "honeycomb_checks.h"
#include "open_meshes.h"
#include "test_helpers.h"
#include "test_meshes.h"

using namespace dlfl;
using namespace dlfl::test;

namespace {

// The schemes with these boundary rules. dual-honeycomb-dual takes a constant tension, since its honeycomb
// step runs on the dual, whose faces are the input's vertices.
const std::vector<std::string> boundary_schemes = {"doo-sabin", "honeycomb", "honeycomb-zw", "dual",
                                                   "dual-honeycomb-dual"};

Params curve_params(const std::string& scheme) {
  if (scheme == "dual-honeycomb-dual") return {{"a", 0.6}};
  return {};
}

// A closed tube of 8 quads around and 4 rows, capped, whose upper half is sheared, stretched and widened so
// that nothing but the ring at z = 0 is shared with the lower half, even by symmetry.
PolygonSoup lopsided_capped_tube() {
  PolygonSoup s = capped_tube_soup(8, 4);
  for (auto& p : s.positions) {
    if (p.z <= 0) continue;
    const double widen = 1.0 + 0.3 * p.z;
    p = {widen * p.x + 0.4 * p.z, widen * p.y, 1.7 * p.z};
  }
  return s;
}

// The counts a mesh's boundary decides (see the headers' closed forms): hole corners H, those at sharp
// vertices S, sharp vertices with one face K (Doo-Sabin leaves their V-face out), faces that are not holes,
// holes. Sharp: a boundary vertex with exactly two edges, or one marked `sharp`.
struct BoundaryCounts {
  std::size_t H = 0, S = 0, K = 0, surface_faces = 0, holes = 0;
};

BoundaryCounts boundary_counts(const Mesh& m) {
  BoundaryCounts b;
  const auto marks = m.find_attribute<VertexId, bool>(sharp_vertex_attribute);
  for (FaceId f : m.faces()) {
    if (!m.is_hole(f)) {
      ++b.surface_faces;
      continue;
    }
    ++b.holes;
    for (CornerId c : m.corners(f)) {
      ++b.H;
      const VertexId v = m.vertex(c);
      const bool sharp = m.valence(v) == 2 || (marks && (*marks)[v]);
      b.S += sharp;
      b.K += sharp && m.valence(v) == 2;
    }
  }
  return b;
}

// V', E', F' after one step with boundary=curve, by the closed forms of each scheme's header.
MeshCounts expected_counts(const std::string& scheme, const Mesh& m) {
  const std::uint64_t V = m.num_vertices(), E = m.num_edges(), F = m.num_faces();
  const BoundaryCounts b = boundary_counts(m);
  if (scheme == "doo-sabin") return {2 * E + b.H - b.S, 4 * E + b.H - b.S - b.K, V + E + F - b.K};
  if (scheme == "honeycomb" || scheme == "honeycomb-zw") return {2 * E + b.H, 3 * E + b.H, F + V};
  const auto dual_counts = [](std::uint64_t V, std::uint64_t E, const BoundaryCounts& b) {
    return MeshCounts{b.surface_faces + b.H + b.S, E + b.H + b.S, V + b.holes};
  };
  if (scheme == "dual") return dual_counts(V, E, b);
  // dual-honeycomb-dual: the dual D keeps each sharp hole corner as one more hole corner, marked; the
  // honeycomb of D doubles the hole corners and keeps the marked ones marked; then the dual of that.
  const MeshCounts d = dual_counts(V, E, b);
  const BoundaryCounts bd{b.H + b.S, b.S, 0, d.faces - b.holes, b.holes};
  const MeshCounts h{2 * d.edges + bd.H, 3 * d.edges + bd.H, d.faces + d.vertices};
  const BoundaryCounts bh{2 * bd.H, b.S, 0, h.faces - b.holes, b.holes};
  return dual_counts(h.vertices, h.edges, bh);
}

// Calls check(scheme, mesh) after each of `steps` steps of every boundary scheme from `start`.
template <class Check>
void after_each_step(const Mesh& start, int steps, const Check& check) {
  for (const std::string& scheme : boundary_schemes) {
    CAPTURE(scheme);
    Mesh m = start;
    for (int step = 1; step <= steps; ++step) {
      CAPTURE(step);
      m = apply_scheme(m, scheme, curve_params(scheme));
      check(scheme, m);
    }
  }
}

}  // namespace

TEST_CASE("boundary rules: two open halves of a closed mesh subdivided apart share their boundary") {
  const auto [below, above] = halves_at_z(lopsided_capped_tube());
  for (const std::string& scheme : boundary_schemes) {
    CAPTURE(scheme);
    Mesh a = build_mesh(below), b = build_mesh(above);
    REQUIRE(a.num_hole_faces() == 1);
    REQUIRE(b.num_hole_faces() == 1);
    for (int step = 1; step <= 4; ++step) {
      CAPTURE(step);
      a = apply_scheme(a, scheme, curve_params(scheme));
      b = apply_scheme(b, scheme, curve_params(scheme));
      // The cut stays in the plane z = 0 (it is planar), and its points agree on both sides.
      check_same_points(loop_at_z(a, 0.0, 0.0), loop_at_z(b, 0.0, 0.0), 1e-12);
    }
  }
}

TEST_CASE("boundary rules: a planar boundary polygon stays in its plane") {
  // A 4 x 3 grid with a hole, turned into a tilted plane: every boundary point stays in it.
  PolygonSoup s = grid_with_holes(4, 3, {{1, 1}});
  const glm::dvec3 u = glm::normalize(glm::dvec3(1, 2, 2)), w = glm::normalize(glm::cross(u, {0, 0, 1}));
  const glm::dvec3 normal = glm::cross(u, w);
  for (auto& p : s.positions) p = glm::dvec3(0.3, -1.2, 2.0) + p.x * u + p.y * w;
  const double offset = glm::dot(normal, s.positions[0]);
  after_each_step(build_mesh(s), 3, [&](const std::string&, const Mesh& m) {
    double worst = 0;
    for (const glm::dvec3& p : boundary_points(m))
      worst = std::max(worst, std::abs(glm::dot(normal, p) - offset));
    CHECK(worst <= 1e-12);
  });
}

TEST_CASE("boundary rules: on a closed mesh boundary=curve and boundary=hole give the same mesh") {
  for (const PolygonSoup& soup : {cube_soup(), torus_soup(5, 4), capped_tube_soup(6, 2)}) {
    const Mesh closed = build_mesh(soup);
    for (const std::string& scheme : boundary_schemes) {
      CAPTURE(scheme);
      Params hole = curve_params(scheme);
      hole["boundary"] = "hole";
      const Mesh curve = apply_scheme(closed, scheme, curve_params(scheme));
      CHECK(curve == apply_scheme(closed, scheme, hole));
      CHECK_FALSE(curve.has_vertex_attribute(sharp_vertex_attribute));
    }
  }
}

TEST_CASE("boundary rules: counts, validity and topology on meshes with 1 to 3 boundary loops") {
  // One loop with four corners of two edges; two loops (a hole in the grid); three loops; the open tube's
  // two loops without corners; two steps each, so that the second step reads the first one's boundary.
  const std::vector<PolygonSoup> soups = {grid_with_holes(4, 3, {}), grid_with_holes(4, 3, {{1, 1}}),
                                          grid_with_holes(5, 4, {{1, 1}, {3, 2}}), open_tube_soup(8, 3)};
  for (const PolygonSoup& soup : soups) {
    const Mesh in = build_mesh(soup);
    for (const std::string& scheme : boundary_schemes) {
      CAPTURE(scheme);
      CAPTURE(in.num_hole_faces());
      Mesh m = in;
      for (int step = 1; step <= 2; ++step) {
        CAPTURE(step);
        const MeshCounts expected = expected_counts(scheme, m);
        const Mesh next = apply_scheme(m, scheme, curve_params(scheme));
        require_valid(next);
        CHECK(counts_of(next) == expected);
        CHECK(topology(next) == topology(in));  // Euler characteristic, genus and loops of every component
        CHECK(next.num_hole_faces() == in.num_hole_faces());
        CHECK(statistics(next).face_sizes.begin()->first >= 3);  // no 2-gons
        m = next;
      }
    }
  }
}

TEST_CASE("boundary rules: the corners of a grid stay in place, marked or with two edges, over steps") {
  const Mesh grid = build_mesh(grid_with_holes(3, 2, {}));
  const std::vector<glm::dvec3> corners = {{0, 0, 0}, {3, 0, 0}, {3, 2, 0}, {0, 2, 0}};
  after_each_step(grid, 3, [&](const std::string& scheme, const Mesh& m) {
    const auto points = boundary_points(m);
    for (const glm::dvec3& c : corners) CHECK(has_point(points, c, 0.0));
    // The sides are straight, so the boundary stays on them: x in {0, 3} or y in {0, 2}, exactly.
    for (const glm::dvec3& p : points) CHECK((p.x == 0 || p.x == 3 || p.y == 0 || p.y == 2));
    // Without sharp corners the corners are cut.
    Params smooth = curve_params(scheme);
    smooth["sharp_corners"] = false;
    const auto cut = boundary_points(apply_scheme(grid, scheme, smooth));
    for (const glm::dvec3& c : corners) CHECK_FALSE(has_point(cut, c, 1e-9));
  });
}

TEST_CASE("boundary rules: a vertex marked sharp stays in place and its mark follows it") {
  Mesh tube = build_mesh(open_tube_soup(8, 3));
  const VertexId marked(3);  // on the loop at z = 0
  tube.add_vertex_attribute<bool>(sharp_vertex_attribute, false)[marked] = true;
  tube.delete_vertex(tube.create_vertex({9, 9, 9}));  // a tombstone: the schemes read a compacted copy
  const glm::dvec3 where = tube.position(marked);
  after_each_step(tube, 3, [&](const std::string&, const Mesh& m) {
    const std::vector<VertexId> kept = marked_vertices(m);
    REQUIRE(kept.size() == 1);
    CHECK(m.position(kept[0]) == where);
  });
}

TEST_CASE("boundary rules: a sharp mark that is not boolean is refused, naming the scheme") {
  const Mesh grid = badly_marked_grid();
  const Mesh before = grid;
  for (const std::string& scheme : boundary_schemes) {
    CAPTURE(scheme);
    const std::string message =
        error_message<InvalidArgument>([&] { apply_scheme(grid, scheme, curve_params(scheme)); });
    const std::string inner = scheme == "dual-honeycomb-dual" ? "dual" : scheme;
    CHECK(message.find(inner +
                       ": the vertex attribute 'sharp' that marks sharp boundary vertices must be boolean") !=
          std::string::npos);
    CHECK(grid == before);
  }
}
