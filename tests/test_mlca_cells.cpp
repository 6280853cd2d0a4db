// MLCA on cell complexes: input checks, the numbering, curves (d = 1) and quad surfaces (d = 2), against the
// claims of Bajaj, Schaefer, Warren and Xu, re-derived here: the curve rules and the cubic B-spline limit,
// non-manifold vertices, formula (2) and its partition of unity (4), Catmull-Clark on 4-valent quad meshes,
// the eigenvalues of the reduced matrix (6), and the boundary creases of section 3.2.

#include <doctest/doctest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include <dlfl/build_mesh.h>
#include <dlfl/cells/cell_average.h>
#include <dlfl/cells/convert.h>
#include <dlfl/cells/mlca_subdivide.h>
#include <dlfl/cells/multilinear_subdivide.h>
#include <dlfl/errors.h>
#include <dlfl/schemes/catmull_clark.h>
#include "scheme_meshes.h"
#include "test_meshes.h"
#include "test_mlca_cells_util.h"

using namespace dlfl;
using namespace dlfl::test;

namespace {

std::vector<glm::dvec3> random_points(std::size_t n, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  std::vector<glm::dvec3> p(n);
  for (auto& q : p) q = {u(rng), u(rng), u(rng)};
  return p;
}

// Segments (i, i+1 mod n): a closed curve through the points.
CellComplex closed_curve(const std::vector<glm::dvec3>& points) {
  CellComplex c;
  c.positions = points;
  const auto n = std::uint32_t(points.size());
  for (std::uint32_t i = 0; i < n; ++i) c.add_cell({i, (i + 1) % n});
  return c;
}

// n quads around vertex 0: edge neighbours 1..n, face-diagonal vertices n+1..2n; quad j is
// (0, e_j, e_{j+1}, f_j) in tensor-product order, i.e. the cycle 0, e_j, f_j, e_{j+1}.
CellComplex umbrella(std::uint32_t n) {
  CellComplex c;
  c.positions.push_back({0, 0, 0});
  for (std::uint32_t j = 0; j < n; ++j) {
    const double a = 2 * std::numbers::pi * j / n;
    c.positions.push_back({std::cos(a), std::sin(a), 0.1 * j});
  }
  for (std::uint32_t j = 0; j < n; ++j) {
    const double a = 2 * std::numbers::pi * (j + 0.5) / n;
    c.positions.push_back({1.5 * std::cos(a), 1.5 * std::sin(a), -0.2 * j});
  }
  for (std::uint32_t j = 0; j < n; ++j) c.add_cell({0, 1 + j, 1 + (j + 1) % n, 1 + n + j});
  return c;
}

// n hexahedra around each of two stacked edges: the umbrella extruded over the layers z = -1, 0, 1. The
// centre of the middle layer (vertex 2n + 1) lies on an extraordinary edge of valence n.
CellComplex extruded_umbrella(std::uint32_t n) {
  const CellComplex flat = umbrella(n);
  const auto layer = std::uint32_t(flat.positions.size());
  CellComplex c;
  for (int z = -1; z <= 1; ++z) {
    for (const auto& q : flat.positions) c.positions.push_back(q + glm::dvec3(0.05 * z * z, 0.1 * z, z));
  }
  for (std::uint32_t z = 0; z < 2; ++z) {
    for (std::size_t f = 0; f < flat.num_cells(); ++f) {
      std::vector<std::uint32_t> hex;
      for (std::uint32_t v : flat.cell(f)) hex.push_back(z * layer + v);
      for (std::uint32_t v : flat.cell(f)) hex.push_back((z + 1) * layer + v);
      c.add_cell(hex);
    }
  }
  return c;
}

// Three quads hanging from the spine edge (0, 1): a non-manifold edge.
CellComplex book() {
  CellComplex c;
  c.positions = {{0, 0, 0}, {1, 0, 0}};
  for (int page = 0; page < 3; ++page) {
    const double a = 2 * std::numbers::pi * page / 3;
    c.positions.push_back({0, std::cos(a), std::sin(a)});
    c.positions.push_back({1, std::cos(a), std::sin(a)});
    const auto p = std::uint32_t(2 + 2 * page);
    c.add_cell({0, 1, p, p + 1});
  }
  return c;
}

void check_close(const glm::dvec3& a, const glm::dvec3& b, double tolerance = 1e-13) {
  CHECK(glm::length(a - b) <= tolerance);
}

}  // namespace

TEST_CASE("mlca cells: bad input is refused with a message naming the cell or the vertex") {
  auto message = [](const CellComplex& c) -> std::string {
    try {
      mlca_subdivide(c);
    } catch (const InvalidArgument& e) {
      return e.what();
    }
    return "no error";
  };
  CellComplex c;
  c.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}};
  c.add_cell({0, 1, 2, 3});
  CHECK(mlca_subdivide(c).num_cells() == 4);

  // A cell of 3 vertices: add_cell refuses it, and so does the check of a hand-built complex.
  CHECK_THROWS_AS(c.add_cell({0, 1, 2}), InvalidArgument);
  CellComplex three = c;
  three.indices.insert(three.indices.end(), {0, 1, 2});
  three.offsets.push_back(std::uint32_t(three.indices.size()));
  CHECK(message(three).find("cell 1 has 3 vertices") != std::string::npos);

  CellComplex out_of_range = c;
  out_of_range.add_cell({1, 4});
  CHECK(message(out_of_range).find("cell 1 uses vertex 4 but there are 4 vertices") != std::string::npos);

  CellComplex repeated = c;
  repeated.add_cell({0, 1, 2, 1});
  CHECK(message(repeated).find("cell 1 uses vertex 1 twice") != std::string::npos);

  CellComplex not_finite = c;
  not_finite.positions[2].y = std::nan("");
  CHECK(message(not_finite).find("vertex 2") != std::string::npos);

  CHECK_THROWS_AS(mlca_subdivide(c, -1), InvalidArgument);
  // One quad has 4^(t+1) indices after t steps, beyond 32 bits from t = 15 on: refused before any work.
  CHECK_THROWS_WITH_AS(mlca_subdivide(c, 15), doctest::Contains("15 iterations"), InvalidArgument);
  CHECK_THROWS_AS(multilinear_subdivide(repeated), InvalidArgument);
  CHECK_THROWS_AS(cell_average(repeated), InvalidArgument);
  CHECK(mlca_subdivide(c, 0).positions == c.positions);
}

TEST_CASE("mlca cells: the numbering of one split quad, by hand") {
  CellComplex c;
  c.positions = {{0, 0, 0}, {4, 0, 0}, {0, 2, 0}, {4, 2, 0}};
  c.add_cell({0, 1, 2, 3});
  const CellComplex out = multilinear_subdivide(c);
  // The 3x3 grid in index order (x fastest): (1,0) edge 0-1, (0,1) edge 0-2, (1,1) centre, (2,1) edge 1-3,
  // (1,2) edge 2-3; the corners are the old vertices.
  REQUIRE(out.positions.size() == 9);
  for (std::uint32_t v = 0; v < 4; ++v) CHECK(out.positions[v] == c.positions[v]);
  CHECK(out.positions[4] == glm::dvec3(2, 0, 0));
  CHECK(out.positions[5] == glm::dvec3(0, 1, 0));
  CHECK(out.positions[6] == glm::dvec3(2, 1, 0));
  CHECK(out.positions[7] == glm::dvec3(4, 1, 0));
  CHECK(out.positions[8] == glm::dvec3(2, 2, 0));
  // Sub-cell s holds grid points s + k: lower-left, lower-right, upper-left, upper-right.
  const std::vector<std::uint32_t> expected = {0, 4, 5, 6, 4, 1, 6, 7, 5, 6, 2, 8, 6, 7, 8, 3};
  CHECK(out.indices == expected);
  CHECK(out.offsets == std::vector<std::uint32_t>{0, 4, 8, 12, 16});
  // A crease segment on an edge and a 0-cell share the quad's vertices: nothing new.
  c.add_cell({3, 1});
  c.add_cell({2});
  const CellComplex with_creases = multilinear_subdivide(c);
  CHECK(with_creases.positions.size() == 9);
  CHECK(with_creases.num_cells() == 4 + 2 + 1);
  CHECK(std::vector<std::uint32_t>(with_creases.cell(4).begin(), with_creases.cell(4).end()) ==
        std::vector<std::uint32_t>{3, 7});
  CHECK(std::vector<std::uint32_t>(with_creases.cell(5).begin(), with_creases.cell(5).end()) ==
        std::vector<std::uint32_t>{7, 1});
  CHECK(with_creases.cell(6)[0] == 2);
  // A second quad on the same four vertices (a pillow) shares the centre too.
  c.add_cell({0, 2, 1, 3});
  CHECK(multilinear_subdivide(c).positions.size() == 9);
}

TEST_CASE("mlca cells: on a curve the vertex rule is (1/8, 3/4, 1/8) and the edge rule (1/2, 1/2)") {
  const auto p = random_points(7, 11);
  const CellComplex out = mlca_subdivide(closed_curve(p));
  REQUIRE(out.positions.size() == 14);
  REQUIRE(out.num_cells() == 14);
  for (std::size_t i = 0; i < 7; ++i) {
    const glm::dvec3 prev = p[(i + 6) % 7], next = p[(i + 1) % 7];
    check_close(out.positions[i], prev / 8.0 + 0.75 * p[i] + next / 8.0);
    // Segment i is cell i; its midpoint is the first new vertex it meets.
    check_close(out.positions[7 + i], 0.5 * (p[i] + next));
  }
}

TEST_CASE("mlca cells: a curve converges to its cubic B-spline, at the rate 1/4 of the subdominant mode") {
  const std::size_t n = 6;
  const auto p = random_points(n, 5);
  // The closed cubic B-spline at knot i is (p_{i-1} + 4 p_i + p_{i+1}) / 6; halfway to knot i+1 it is
  // (p_{i-1} + 23 p_i + 23 p_{i+1} + p_{i+2}) / 48 (the basis functions at t = 1/2).
  auto at = [&](std::size_t i) { return p[i % n]; };
  std::vector<double> error;
  CellComplex c = closed_curve(p);
  c = mlca_subdivide(c, 8);
  for (int step = 8; step <= 11; ++step) {
    double worst = 0;
    for (std::size_t i = 0; i < n; ++i) {
      const glm::dvec3 knot = (at(i + n - 1) + 4.0 * at(i) + at(i + 1)) / 6.0;
      worst = std::max(worst, glm::length(c.positions[i] - knot));
      // Input vertex i and the midpoint of input segment i (vertex n + i) keep their indices at every step.
      const glm::dvec3 half = (at(i + n - 1) + 23.0 * at(i) + 23.0 * at(i + 1) + at(i + 2)) / 48.0;
      CHECK(glm::length(c.positions[n + i] - half) < 1e-4);
    }
    error.push_back(worst);
    c = mlca_subdivide(c);
  }
  CHECK(error.back() < 2e-6);
  for (std::size_t k = 0; k + 1 < error.size(); ++k) {
    CHECK(error[k] / error[k + 1] == doctest::Approx(4.0).epsilon(0.02));
  }
}

TEST_CASE("mlca cells: at a vertex of n segments the rule is 3/4 plus 1/(4n) of each neighbour") {
  for (std::uint32_t n : {1u, 3u, 4u, 6u}) {
    CAPTURE(n);
    CellComplex star;
    star.positions = random_points(n + 1, 100 + n);
    for (std::uint32_t j = 1; j <= n; ++j) {  // both orientations: the rule does not depend on them
      if (j % 2) {
        star.add_cell({0, j});
      } else {
        star.add_cell({j, 0});
      }
    }
    const CellComplex out = mlca_subdivide(star);
    glm::dvec3 expected = 0.75 * star.positions[0];
    for (std::uint32_t j = 1; j <= n; ++j) expected += star.positions[j] / (4.0 * n);
    check_close(out.positions[0], expected);
    // A free end (one segment) is the case n = 1 seen from the leaf: 3/4 of itself and 1/4 of the centre.
    for (std::uint32_t j = 1; j <= n; ++j) {
      check_close(out.positions[j], 0.75 * star.positions[j] + 0.25 * star.positions[0]);
    }
  }
}

TEST_CASE(
    "mlca cells: 0-cells at the ends of an open curve are interpolated, the rest keeps the curve rules") {
  const auto p = random_points(6, 21);
  CellComplex c;
  c.positions = p;
  for (std::uint32_t i = 0; i + 1 < 6; ++i) c.add_cell({i, i + 1});
  c.add_cell({0});
  c.add_cell({5});
  REQUIRE(crease_dimensions(c) == std::vector<std::int8_t>{0, 1, 1, 1, 1, 0});
  const CellComplex out = mlca_subdivide(c);
  CHECK(out.positions[0] == p[0]);
  CHECK(out.positions[5] == p[5]);
  for (std::size_t i = 1; i < 5; ++i)
    check_close(out.positions[i], p[i - 1] / 8.0 + 0.75 * p[i] + p[i + 1] / 8.0);
  // Three more steps: the ends stay exactly where they were.
  const CellComplex more = mlca_subdivide(c, 4);
  CHECK(more.positions[0] == p[0]);
  CHECK(more.positions[5] == p[5]);
  // A vertex in no cell has dim -1 and keeps its position.
  c.positions.push_back({7, 8, 9});
  CHECK(crease_dimensions(c).back() == -1);
  CHECK(mlca_subdivide(c, 2).positions[6] == glm::dvec3(7, 8, 9));
}

TEST_CASE("mlca cells: the composite weights are formula (2), the central weight (3/4)^d, the sum 1 (4)") {
  struct Case {
    const char* name;
    CellComplex complex;
    std::uint32_t vertex;
  };
  std::vector<Case> cases;
  cases.push_back({"closed curve", closed_curve(random_points(5, 1)), 0});
  CellComplex star;
  star.positions = random_points(5, 2);
  for (std::uint32_t j = 1; j <= 4; ++j) star.add_cell({0, j});
  cases.push_back({"curve network, 4 segments", star, 0});
  for (std::uint32_t n = 3; n <= 7; ++n) cases.push_back({"quad umbrella", umbrella(n), 0});
  cases.push_back({"book of three quads, spine vertex", book(), 0});
  cases.push_back({"torus grid", quads_of(torus_soup(5, 4)), 7});
  cases.push_back({"one hexahedron", hex_grid(1, 1, 1, jittered_lattice(3)), 0});
  cases.push_back(
      {"hexahedra, interior vertex", hex_grid(2, 2, 2, jittered_lattice(4)), lattice_index(2, 2, 1, 1, 1)});
  cases.push_back(
      {"hexahedra, boundary vertex", hex_grid(2, 2, 2, jittered_lattice(5)), lattice_index(2, 2, 1, 0, 1)});
  for (std::uint32_t n : {3u, 5u}) {
    cases.push_back(
        {"extraordinary edge", extruded_umbrella(n), std::uint32_t(umbrella(n).positions.size())});
  }
  // Hexahedral splits of polyhedra: the centroid (V + E + F) is an extraordinary vertex in V hexahedra, a
  // face centre (V + E) one in as many as the face has sides.
  cases.push_back({"tetrahedron split, centroid", polyhedron_to_hexahedra(test::tetrahedron()), 4 + 6 + 4});
  cases.push_back(
      {"dodecahedron split, centroid", polyhedron_to_hexahedra(test::dodecahedron()), 20 + 30 + 12});
  cases.push_back(
      {"dodecahedron split, face centre", polyhedron_to_hexahedra(test::dodecahedron()), 20 + 30});

  for (const Case& k : cases) {
    CAPTURE(k.name);
    CAPTURE(k.complex.num_cells());
    const auto expected = formula2_weights(k.complex, k.vertex);
    std::vector<std::uint32_t> all(k.complex.positions.size());
    for (std::uint32_t v = 0; v < all.size(); ++v) all[v] = v;
    const auto row = subdivision_matrix(k.complex, {k.vertex}, all)[0];
    double sum = 0;
    for (std::size_t u = 0; u < all.size(); ++u) {
      CHECK(row[u] == doctest::Approx(expected[u]).epsilon(1e-13));
      sum += row[u];
    }
    CHECK(sum == doctest::Approx(1.0).epsilon(1e-14));
    int d = 0;
    for (std::size_t i = 0; i < k.complex.num_cells(); ++i) d = std::max(d, k.complex.dimension(i));
    CHECK(row[k.vertex] == doctest::Approx(std::pow(0.75, d)).epsilon(1e-14));
  }
}

TEST_CASE("mlca cells: along an extraordinary edge the rule is the surface rule times the curve rule (4.2)") {
  for (std::uint32_t n : {3u, 5u, 6u}) {
    CAPTURE(n);
    const CellComplex c = extruded_umbrella(n);
    const auto layer = std::uint32_t(2 * n + 1);
    std::vector<std::uint32_t> all(c.positions.size());
    for (std::uint32_t v = 0; v < all.size(); ++v) all[v] = v;
    const auto row = subdivision_matrix(c, {layer}, all)[0];
    // The bivariate rule at a valence-n vertex from formula (2) with d = 2, times (1/8, 3/4, 1/8) across
    // layers.
    const auto surface = formula2_weights(umbrella(n), 0);
    const double curve[3] = {0.125, 0.75, 0.125};
    for (std::uint32_t z = 0; z < 3; ++z) {
      for (std::uint32_t v = 0; v < layer; ++v) {
        CHECK(row[z * layer + v] == doctest::Approx(curve[z] * surface[v]).epsilon(1e-14));
      }
    }
  }
}

TEST_CASE("mlca cells: the reduced matrix (6) has a = 1/(16n) and eigenvalues 1, 1/4, 1/16") {
  for (std::uint32_t n = 3; n <= 8; ++n) {
    CAPTURE(n);
    const CellComplex c = umbrella(n);
    // The new centre, the new vertex on edge (0, e_0) and the new centre of quad 0, found by where linear
    // subdivision puts them.
    const CellComplex split = multilinear_subdivide(c);
    const std::uint32_t on_edge = vertex_at(split, 0.5 * (c.positions[0] + c.positions[1]));
    glm::dvec3 quad_centre(0.0);
    for (std::uint32_t v : c.cell(0)) quad_centre += c.positions[v] / 4.0;
    const std::uint32_t in_face = vertex_at(split, quad_centre);
    std::vector<std::uint32_t> all(2 * n + 1);
    for (std::uint32_t v = 0; v < all.size(); ++v) all[v] = v;
    const auto s = subdivision_matrix(c, {0, on_edge, in_face}, all);
    // Restricted to rotation-invariant data (all e_j equal, all f_j equal): columns summed per ring.
    std::array<std::array<double, 3>, 3> r{};
    for (int i = 0; i < 3; ++i) {
      r[i][0] = s[i][0];
      for (std::uint32_t j = 0; j < n; ++j) {
        r[i][1] += s[i][1 + j];
        r[i][2] += s[i][1 + n + j];
      }
    }
    const double a = 1.0 / (16.0 * n);
    const double paper[3][3] = {
        {1 - 7 * n * a, 6 * n * a, n * a}, {3.0 / 8, 1.0 / 2, 1.0 / 8}, {1.0 / 4, 1.0 / 2, 1.0 / 4}};
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) CHECK(r[i][j] == doctest::Approx(paper[i][j]).epsilon(1e-14));
    }
    // Characteristic polynomial l^3 + c2 l^2 + c1 l + c0 of the measured matrix.
    const double trace = r[0][0] + r[1][1] + r[2][2];
    const double minors = r[0][0] * r[1][1] - r[0][1] * r[1][0] + r[0][0] * r[2][2] - r[0][2] * r[2][0] +
                          r[1][1] * r[2][2] - r[1][2] * r[2][1];
    const double det = r[0][0] * (r[1][1] * r[2][2] - r[1][2] * r[2][1]) -
                       r[0][1] * (r[1][0] * r[2][2] - r[1][2] * r[2][0]) +
                       r[0][2] * (r[1][0] * r[2][1] - r[1][1] * r[2][0]);
    const double c2 = -trace, c1 = minors, c0 = -det;
    // Rows sum to one, so 1 is a root; divide it out and solve the quadratic l^2 + q1 l + q0.
    const double q1 = c2 + 1.0, q0 = c1 + q1, remainder = c0 + q0;
    CHECK(std::abs(remainder) < 1e-14);
    const double disc = q1 * q1 - 4 * q0;
    REQUIRE(disc > 0);
    const double big = (-q1 + std::sqrt(disc)) / 2, small = (-q1 - std::sqrt(disc)) / 2;
    CHECK(big == doctest::Approx(0.25).epsilon(1e-12));
    CHECK(small == doctest::Approx(1.0 / 16).epsilon(1e-12));
  }
}

TEST_CASE("mlca cells: on a closed quad mesh with all vertices 4-valent MLCA is Catmull-Clark") {
  PolygonSoup soup = torus_soup(6, 5);
  std::mt19937 rng(9);
  std::uniform_real_distribution<double> u(-0.1, 0.1);
  for (auto& p : soup.positions) p += glm::dvec3(u(rng), u(rng), u(rng));
  const CellComplex ours = mlca_subdivide(quads_of(soup), 2);
  const Mesh theirs = catmull_clark(catmull_clark(build_mesh(soup)));
  REQUIRE(ours.positions.size() == theirs.num_vertices());
  REQUIRE(ours.num_cells() == theirs.num_faces());
  // Match vertices by position (the closest; the grid keeps them far apart), one to one.
  std::vector<std::uint32_t> match(theirs.vertex_capacity(), 0);
  std::vector<int> used(ours.positions.size(), 0);
  double worst = 0;
  for (VertexId v : theirs.vertices()) {
    std::uint32_t best = 0;
    double best_distance = 1e300;
    for (std::uint32_t w = 0; w < ours.positions.size(); ++w) {
      const double dist = glm::length(ours.positions[w] - theirs.position(v));
      if (dist < best_distance) {
        best_distance = dist;
        best = w;
      }
    }
    worst = std::max(worst, best_distance);
    match[v.index()] = best;
    ++used[best];
  }
  CHECK(worst < 1e-12);
  CHECK(std::count(used.begin(), used.end(), 1) == std::ptrdiff_t(used.size()));
  // The same quads: each face's cycle a b c d is the cell (a, b, d, c).
  std::vector<std::array<std::uint32_t, 4>> faces, cells;
  for (FaceId f : theirs.faces()) {
    std::vector<std::uint32_t> cycle;
    for (CornerId c : theirs.corners(f)) cycle.push_back(match[theirs.vertex(c).index()]);
    REQUIRE(cycle.size() == 4);
    // Rotate so that the smallest comes first, then store in tensor-product order.
    std::rotate(cycle.begin(), std::min_element(cycle.begin(), cycle.end()), cycle.end());
    faces.push_back({cycle[0], cycle[1], cycle[3], cycle[2]});
  }
  for (std::size_t i = 0; i < ours.num_cells(); ++i) {
    const auto q = ours.cell(i);
    std::array<std::uint32_t, 4> cycle = {q[0], q[1], q[3], q[2]};
    std::rotate(cycle.begin(), std::min_element(cycle.begin(), cycle.end()), cycle.end());
    cells.push_back({cycle[0], cycle[1], cycle[3], cycle[2]});
  }
  std::sort(faces.begin(), faces.end());
  std::sort(cells.begin(), cells.end());
  CHECK(faces == cells);
}

TEST_CASE(
    "mlca cells: on the cube MLCA has Catmull-Clark's edge and face rules but a = 1/(16n) at vertices") {
  PolygonSoup soup = test::cube_soup();
  std::mt19937 rng(4);
  std::uniform_real_distribution<double> u(-0.2, 0.2);
  for (auto& p : soup.positions) p += glm::dvec3(u(rng), u(rng), u(rng));
  const CellComplex ours = mlca_subdivide(quads_of(soup));
  const Mesh theirs = catmull_clark(build_mesh(soup));
  REQUIRE(ours.positions.size() == 26);
  // Catmull-Clark numbers vertex points 0..7, edge points 8..19, face points 20..25.
  for (std::uint32_t v = 8; v < 26; ++v) vertex_at(ours, theirs.position(VertexId(v)));
  for (std::uint32_t v = 0; v < 8; ++v) {
    // n = 3: Catmull-Clark's vertex rule is MLCA's with a = 1/36 instead of 1/48.
    CHECK(glm::length(ours.positions[v] - theirs.position(VertexId(v))) > 1e-4);
  }
}

TEST_CASE("mlca cells: the bounded patch of section 3.2 keeps its corners and has B-spline boundary curves") {
  // The paper's 3x3 grid numbered 1..9 row by row (here 0..8), with its 4 quads, 8 boundary edges and 4
  // corner vertices.
  CellComplex c;
  std::mt19937 rng(17);
  std::uniform_real_distribution<double> u(-0.2, 0.2);
  for (int row = 0; row < 3; ++row) {
    for (int col = 0; col < 3; ++col) c.positions.push_back({col + u(rng), -row + u(rng), u(rng)});
  }
  // {1,2,5,4} is a cycle; in tensor-product order it is (1, 2, 4, 5).
  c.add_cell({0, 1, 3, 4});
  c.add_cell({3, 4, 6, 7});
  c.add_cell({1, 2, 4, 5});
  c.add_cell({4, 5, 7, 8});
  for (auto [a, b] :
       {std::pair{0u, 3u}, {3u, 6u}, {0u, 1u}, {1u, 2u}, {2u, 5u}, {5u, 8u}, {6u, 7u}, {7u, 8u}}) {
    c.add_cell({a, b});
  }
  for (std::uint32_t v : {0u, 2u, 6u, 8u}) c.add_cell({v});
  // The table of dim[v] printed in the paper.
  CHECK(crease_dimensions(c) == std::vector<std::int8_t>{0, 1, 0, 1, 2, 1, 0, 1, 0});

  const auto& p = c.positions;
  const CellComplex out = mlca_subdivide(c);
  for (std::uint32_t v : {0u, 2u, 6u, 8u}) CHECK(out.positions[v] == p[v]);
  // Boundary vertices follow the curve rule along their boundary only.
  check_close(out.positions[1], (p[0] + 6.0 * p[1] + p[2]) / 8.0);
  check_close(out.positions[3], (p[0] + 6.0 * p[3] + p[6]) / 8.0);
  check_close(out.positions[5], (p[2] + 6.0 * p[5] + p[8]) / 8.0);
  check_close(out.positions[7], (p[6] + 6.0 * p[7] + p[8]) / 8.0);
  // The centre follows the bi-cubic rule: (1/8, 3/4, 1/8) in both directions.
  const double w[3] = {0.125, 0.75, 0.125};
  glm::dvec3 centre(0.0);
  for (int row = 0; row < 3; ++row) {
    for (int col = 0; col < 3; ++col) centre += w[row] * w[col] * p[3 * row + col];
  }
  check_close(out.positions[4], centre);
  // The new vertex on the boundary edge 0-1 is its midpoint (the curve's edge rule).
  const CellComplex split = multilinear_subdivide(c);
  check_close(out.positions[vertex_at(split, 0.5 * (p[0] + p[1]))], 0.5 * (p[0] + p[1]));
}

TEST_CASE("mlca cells: three quads at an edge (non-manifold) subdivide with the expected counts") {
  const CellComplex c = book();
  const CellComplex out = mlca_subdivide(c);
  // V + E + F: 8 vertices, 1 spine + 3 x 3 page edges, 3 quads.
  CHECK(out.positions.size() == 8 + 10 + 3);
  CHECK(out.num_cells() == 12);
  check_cell_complex(out);
  // The spine is shared: its midpoint lies in 6 of the new quads (2 per page).
  const CellComplex split = multilinear_subdivide(c);
  const std::uint32_t spine = vertex_at(split, 0.5 * (c.positions[0] + c.positions[1]));
  int holding = 0;
  for (std::size_t i = 0; i < split.num_cells(); ++i) {
    const auto q = split.cell(i);
    holding += int(std::count(q.begin(), q.end(), spine));
  }
  CHECK(holding == 6);
}
