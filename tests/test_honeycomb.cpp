// Honeycomb subdivision: counts, valences and face sizes from closed forms, topology, orientation, positions
// against hand-derived values, affine invariance, coefficients, parameter errors, holes and point spheres.

#include <doctest/doctest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <glm/geometric.hpp>
#include <map>
#include <numbers>
#include <random>
#include <string>
#include <tuple>
#include <vector>

#include <dlfl/create_face_manifold.h>
#include <dlfl/errors.h>
#include <dlfl/schemes/honeycomb.h>
#include <dlfl/statistics.h>
#include <dlfl/validate.h>
#include "honeycomb_checks.h"
#include "scheme_meshes.h"
#include "test_helpers.h"
#include "test_meshes.h"

using namespace dlfl;
using test::require_valid;

namespace {

using test::Histogram;
using test::hole_sizes;
using test::topology;

std::size_t non_hexagons(const Mesh& m) {
  std::size_t n = 0;
  for (FaceId f : m.faces()) n += m.size(f) != 6;
  return n;
}

// One step on a mesh without point spheres, checked against the closed forms.
Mesh checked_step(const Mesh& m, const HoneycombParams& p = {}) {
  return test::checked_honeycomb_step(m, [&](const Mesh& in) { return honeycomb(in, p); });
}

Mesh face_manifold(const std::vector<glm::dvec3>& points) {
  Mesh m;
  create_face_manifold(m, points);
  return m;
}

std::vector<glm::dvec3> face_positions(const Mesh& m, FaceId f) {
  std::vector<glm::dvec3> p;
  for (CornerId c : m.corners(f)) p.push_back(m.position(m.vertex(c)));
  return p;
}

bool close(const glm::dvec3& a, const glm::dvec3& b, double tol) {
  return std::abs(a.x - b.x) <= tol && std::abs(a.y - b.y) <= tol && std::abs(a.z - b.z) <= tol;
}

// How many faces of m run through `expected` in order, starting at their first corner.
int faces_matching(const Mesh& m, const std::vector<glm::dvec3>& expected, double tol = 1e-12) {
  int count = 0;
  for (FaceId f : m.faces()) {
    if (m.size(f) != expected.size()) continue;
    const auto p = face_positions(m, f);
    bool same = true;
    for (std::size_t i = 0; i < p.size(); ++i) same = same && close(p[i], expected[i], tol);
    count += same;
  }
  return count;
}

// Formulas (1) and (2) written out directly, O(N^2), for a face given by its vertex positions.
std::vector<glm::dvec3> paper_points(const std::vector<glm::dvec3>& v, double t, double a) {
  const std::size_t N = v.size();
  std::vector<glm::dvec3> out(N, glm::dvec3(0.0));
  for (std::size_t n = 0; n < N; ++n) {
    for (std::size_t m = 0; m < N; ++m) {
      const double beta = 3 + 2 * std::cos(2 * (double(n) - double(m)) * std::numbers::pi / double(N));
      const double coefficient = n == m ? a : beta * (1 - a) / (3 * double(N) - 5);
      out[n] += coefficient * ((1 - t) * v[m] + t * v[(m + 1) % N]);
    }
  }
  return out;
}

glm::dvec3 newell_normal(const std::vector<glm::dvec3>& p) {
  glm::dvec3 n(0.0);
  for (std::size_t i = 0; i < p.size(); ++i) {
    const glm::dvec3& a = p[i];
    const glm::dvec3& b = p[(i + 1) % p.size()];
    n.x += (a.y - b.y) * (a.z + b.z);
    n.y += (a.z - b.z) * (a.x + b.x);
    n.z += (a.x - b.x) * (a.y + b.y);
  }
  return n;
}

// Every face's Newell normal points away from `center` (seen from its centroid).
void check_outward(const Mesh& m, const glm::dvec3& center) {
  for (FaceId f : m.faces()) {
    const auto p = face_positions(m, f);
    glm::dvec3 centroid(0.0);
    for (const auto& q : p) centroid += q;
    centroid /= double(p.size());
    const glm::dvec3 n = newell_normal(p);
    const glm::dvec3 d = centroid - center;
    CAPTURE(f.index());
    CHECK(n.x * d.x + n.y * d.y + n.z * d.z > 0.0);
  }
}

struct Named {
  const char* name;
  Mesh mesh;
};

std::vector<Named> closed_meshes() {
  std::vector<Named> list;
  list.push_back({"tetrahedron", test::tetrahedron()});
  list.push_back({"cube", test::cube()});
  list.push_back({"dodecahedron", test::dodecahedron()});
  list.push_back({"torus", build_mesh(test::torus_soup(6, 5))});
  list.push_back({"genus 3", build_mesh(test::genus_soup(3))});
  list.push_back({"mixed 3 to 7", test::mixed_polyhedron()});
  list.push_back(
      {"two-sided pentagon", face_manifold({{0, 0, 0}, {2, 0, 0}, {3, 1, 0}, {1, 3, 0}, {-1, 1, 0}})});
  return list;
}

}  // namespace

TEST_CASE("honeycomb: the test meshes are what they claim") {
  Mesh d = test::dodecahedron();
  require_valid(d);
  CHECK(statistics(d).face_sizes == Histogram{{5, 12}});
  CHECK(statistics(d).valences == Histogram{{3, 20}});
  CHECK(topology(d) == std::vector<std::tuple<long, long, std::size_t>>{{2, 0, 0}});
  check_outward(d, glm::dvec3(0.0));

  Mesh m = test::mixed_polyhedron();
  require_valid(m);
  CHECK(m.num_vertices() == 15);
  CHECK(m.num_edges() == 24);
  CHECK(statistics(m).face_sizes == Histogram{{3, 3}, {4, 4}, {5, 2}, {6, 1}, {7, 1}});
  CHECK(topology(m) == std::vector<std::tuple<long, long, std::size_t>>{{2, 0, 0}});
  check_outward(m, glm::dvec3(0.0));

  CHECK(topology(build_mesh(test::genus_soup(3))) ==
        std::vector<std::tuple<long, long, std::size_t>>{{-4, 3, 0}});
}

TEST_CASE("honeycomb: counts valences face sizes and topology on closed meshes") {
  for (const Named& n : closed_meshes()) {
    CAPTURE(n.name);
    checked_step(n.mesh);
  }
}

TEST_CASE("honeycomb: after the first step the number of non-hexagons stays constant") {
  for (const Named& n : closed_meshes()) {
    CAPTURE(n.name);
    // Step 1 keeps the old faces' sizes and makes a 2k-gon per k-valent vertex; from then on every vertex is
    // 3-valent, so every new vertex face is a hexagon and only the front faces can be non-hexagons.
    std::size_t expected = non_hexagons(n.mesh);
    for (VertexId v : n.mesh.vertices()) expected += n.mesh.valence(v) != 3;
    const Mesh m1 = checked_step(n.mesh);
    const Mesh m2 = checked_step(m1);
    const Mesh m3 = checked_step(m2);
    CHECK(non_hexagons(m1) == expected);
    CHECK(non_hexagons(m2) == expected);
    CHECK(non_hexagons(m3) == expected);
  }
}

TEST_CASE("honeycomb: a two-sided pentagon gives 10 vertices 15 edges and 7 faces") {
  const Mesh m = face_manifold({{0, 0, 0}, {1, 0, 0}, {1.3, 1, 0}, {0.5, 1.6, 0}, {-0.3, 1, 0}});
  const Mesh r = honeycomb(m);
  require_valid(r);
  CHECK(r.num_vertices() == 10);
  CHECK(r.num_edges() == 15);
  CHECK(r.num_faces() == 7);
  // Two pentagons (the front faces) and five quads (one per 2-valent vertex).
  CHECK(statistics(r).face_sizes == Histogram{{4, 5}, {5, 2}});
}

TEST_CASE("honeycomb: the dodecahedron becomes a truncated icosahedron") {
  const Mesh r = honeycomb(test::dodecahedron());
  require_valid(r);
  CHECK(r.num_vertices() == 60);
  CHECK(r.num_edges() == 90);
  CHECK(statistics(r).face_sizes == Histogram{{5, 12}, {6, 20}});
  // Each new vertex belongs to one half-edge (a face and one of its edges). The rotation group of the
  // dodecahedron (order 60) maps half-edges to half-edges transitively and keeps the cyclic order of every
  // face, and formulas (1) and (2) depend only on that order, so it maps new vertices to new vertices: all 60
  // are images of one under rotations about the centre, hence at one distance from it.
  const double r0 = glm::length(r.position(*r.vertices().begin()));
  CHECK(r0 > 0.5);
  for (VertexId v : r.vertices()) CHECK(std::abs(glm::length(r.position(v)) - r0) <= 1e-12 * r0);
}

TEST_CASE("honeycomb: face normals of convex inputs point outward") {
  // The inputs are centred at the origin and convex; the result is convex too, so every face normal must
  // point away from the centre if the new faces are oriented like the old ones.
  for (Mesh m : {test::cube(), test::dodecahedron(), test::mixed_polyhedron()}) {
    const Mesh r = honeycomb(m);
    check_outward(r, glm::dvec3(0.0));
    check_outward(honeycomb(r), glm::dvec3(0.0));
  }
}

TEST_CASE("honeycomb: new points of a square match the hand computation") {
  // Square v0..v3 = (0,0), (1,0), (1,1), (0,1) at z = 2; t = 1/2, so the edge points are the midpoints
  // p0 = (1/2, 0), p1 = (1, 1/2), p2 = (1/2, 1), p3 = (0, 1/2). Default tension a = 0.45 + 1.25/4 = 0.7625.
  // 3N - 5 = 7 and beta = 3 + 2 cos(2 (n-m) pi / 4): n-m = 1 or 3 (cos = 0) gives 3, n-m = 2 (cos = -1)
  // gives 1. With s = (1 - a) / 7 = 0.2375 / 7 = 19/560, row n of the coefficient matrix is
  //   a_{n,n} = 0.7625, a_{n,n+1} = a_{n,n+3} = 3s = 57/560, a_{n,n+2} = s = 19/560  (sum 1).
  // v'_0 = 0.7625 p0 + 3s (p1 + p3) + s p2:
  //   x = 0.7625/2 + 3s + s/2 = (213.5 + 57 + 9.5)/560 = 1/2,   y = 0 + 3s + s = 76/560 = 19/140.
  // By the quarter-turn symmetry of the square: v'_1 = (121/140, 1/2), v'_2 = (1/2, 121/140),
  // v'_3 = (19/140, 1/2).
  const Mesh m = face_manifold({{0, 0, 2}, {1, 0, 2}, {1, 1, 2}, {0, 1, 2}});
  const Mesh r = honeycomb(m);
  const double lo = 19.0 / 140.0, hi = 121.0 / 140.0;
  CHECK(faces_matching(r, {{0.5, lo, 2}, {hi, 0.5, 2}, {0.5, hi, 2}, {lo, 0.5, 2}}) == 1);
  // The back face (v3, v2, v1, v0) gives the same points in the order starting at the midpoint of v3 v2.
  CHECK(faces_matching(r, {{0.5, hi, 2}, {hi, 0.5, 2}, {0.5, lo, 2}, {lo, 0.5, 2}}) == 1);
}

TEST_CASE("honeycomb: new points of a pentagon match formulas (1) and (2)") {
  // N = 5, default a = 0.45 + 1.25/5 = 0.7, 3N - 5 = 10. cos(2 pi/5) = (sqrt5 - 1)/4 and
  // cos(4 pi/5) = -(sqrt5 + 1)/4, so beta = (5 + sqrt5)/2 for n - m = +-1 and (5 - sqrt5)/2 for n - m = +-2
  // (the four sum to 10, so each row sums to 0.7 + 10 * 0.3/10 = 1). t = 0.3 on an irregular, non-planar
  // pentagon.
  const std::vector<glm::dvec3> v = {{0, 0, 0}, {2, 0, 0.1}, {2.5, 1.5, 0}, {1, 2.5, -0.2}, {-0.5, 1.2, 0.3}};
  const double t = 0.3, a = 0.7, s5 = std::sqrt(5.0);
  const double near = (5 + s5) / 2 * 0.3 / 10, far = (5 - s5) / 2 * 0.3 / 10;
  std::vector<glm::dvec3> p(5), expected(5, glm::dvec3(0.0));
  for (int m = 0; m < 5; ++m) p[m] = (1 - t) * v[m] + t * v[(m + 1) % 5];
  for (int n = 0; n < 5; ++n) {
    expected[n] =
        a * p[n] + near * (p[(n + 1) % 5] + p[(n + 4) % 5]) + far * (p[(n + 2) % 5] + p[(n + 3) % 5]);
  }
  HoneycombParams params;
  params.t = t;
  const Mesh r = honeycomb(face_manifold(v), params);
  CHECK(faces_matching(r, expected) == 1);
}

TEST_CASE("honeycomb: large faces match formulas (1) and (2)") {
  // Faces above 64 sides take a different path in the implementation; both must agree with the paper.
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> jitter(-0.2, 0.2);
  for (int N : {63, 64, 65, 100, 257}) {
    CAPTURE(N);
    std::vector<glm::dvec3> v;
    for (int i = 0; i < N; ++i) {
      const double u = 2 * std::numbers::pi * i / N;
      v.push_back({10 + (1 + jitter(rng)) * std::cos(u), -3 + (1 + jitter(rng)) * std::sin(u), jitter(rng)});
    }
    for (double t : {0.5, 0.2}) {
      HoneycombParams params;
      params.t = t;
      const Mesh r = honeycomb(face_manifold(v), params);
      require_valid(r);
      CHECK(faces_matching(r, paper_points(v, t, 0.45 + 1.25 / N), 1e-11) == 1);
    }
  }
}

TEST_CASE("honeycomb: t = 1 gives the points of t = 0 shifted by one") {
  // With t = 1 the point on edge m is v_{m+1}, the t = 0 point of edge m + 1; as a_{n,m} depends on n - m
  // only, v'_n(t = 1) = v'_{n+1}(t = 0).
  const std::vector<glm::dvec3> v = {{0, 0, 0}, {2, 0, 0.1}, {2.5, 1.5, 0}, {1, 2.5, -0.2}, {-0.5, 1.2, 0.3}};
  const Mesh m = face_manifold(v);
  HoneycombParams p0, p1;
  p0.t = 0.0;
  p1.t = 1.0;
  const Mesh r0 = honeycomb(m, p0), r1 = honeycomb(m, p1);
  int checked = 0;
  for (FaceId f : r0.faces()) {
    if (r0.size(f) != 5) continue;
    const auto a = face_positions(r0, f), b = face_positions(r1, f);
    for (int n = 0; n < 5; ++n) CHECK(close(b[n], a[(n + 1) % 5], 1e-12));
    ++checked;
  }
  CHECK(checked == 2);
}

TEST_CASE("honeycomb: affine maps commute with the subdivision") {
  std::mt19937 rng(12345);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  double A[3][3];
  glm::dvec3 b;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) A[i][j] = u(rng) + (i == j ? 2.0 : 0.0);
    b[i] = 5.0 * u(rng);
  }
  auto apply = [&](const glm::dvec3& p) {
    glm::dvec3 q = b;
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) q[i] += A[i][j] * p[j];
    }
    return q;
  };
  for (const Mesh& m : {test::cube(), build_mesh(test::torus_soup(8, 6))}) {
    Mesh moved = m;
    for (VertexId v : moved.vertices()) moved.set_position(v, apply(m.position(v)));
    const Mesh r = honeycomb(m);
    const Mesh r_moved = honeycomb(moved);
    Mesh r_then_moved = r;
    for (VertexId v : r.vertices()) {
      const glm::dvec3 expected = apply(r.position(v));
      const double scale = std::max(1.0, glm::length(expected));
      CHECK(close(r_moved.position(v), expected, 1e-12 * scale));
      r_then_moved.set_position(v, r_moved.position(v));
    }
    // Same topology and handles: with the positions copied over, the meshes are identical.
    CHECK(r_then_moved == r_moved);
  }
}

TEST_CASE("honeycomb: coefficients are positive and each row sums to one") {
  for (int N = 2; N <= 20; ++N) {
    for (double a : {1e-6, 0.1, 0.45 + 1.25 / N, 0.5, 0.9, 1 - 1e-6}) {
      if (!(a > 0 && a < 1)) continue;  // the default tension leaves (0, 1) for N = 2
      CAPTURE(N);
      CAPTURE(a);
      for (int n = 0; n < N; ++n) {
        double sum = 0;
        for (int m = 0; m < N; ++m) {
          const double c = honeycomb_coefficient(N, n, m, a);
          CHECK(c > 0.0);
          CHECK(std::abs(c - honeycomb_coefficient(N, m, n, a)) <= 1e-15);  // beta is even in n - m
          sum += c;
        }
        CHECK(std::abs(sum - 1.0) <= 1e-14);
        CHECK(honeycomb_coefficient(N, n, n, a) == a);
      }
    }
  }
  // Hand values. N = 3: beta = 3 + 2 cos(2 pi/3) = 2, 3N - 5 = 4, so a_{n,m} = (1 - a)/2.
  CHECK(honeycomb_coefficient(3, 0, 1, 0.6) == doctest::Approx(0.2).epsilon(1e-15));
  CHECK(honeycomb_coefficient(3, 2, 0, 0.6) == doctest::Approx(0.2).epsilon(1e-15));
  // N = 6: beta = 4, 2, 1 for n - m = 1, 2, 3 (cos = 1/2, -1/2, -1), 3N - 5 = 13 (= 4 + 4 + 2 + 2 + 1).
  CHECK(honeycomb_coefficient(6, 0, 1, 0.35) == doctest::Approx(4 * 0.65 / 13).epsilon(1e-15));
  CHECK(honeycomb_coefficient(6, 5, 3, 0.35) == doctest::Approx(2 * 0.65 / 13).epsilon(1e-15));
  CHECK(honeycomb_coefficient(6, 1, 4, 0.35) == doctest::Approx(1 * 0.65 / 13).epsilon(1e-15));
  // N = 2: beta = 3 + 2 cos(pi) = 1, 3N - 5 = 1, so a_{0,1} = 1 - a.
  CHECK(honeycomb_coefficient(2, 0, 1, 0.25) == doctest::Approx(0.75).epsilon(1e-15));
  CHECK_THROWS_AS(honeycomb_coefficient(1, 0, 0, 0.5), InvalidArgument);
  CHECK_THROWS_AS(honeycomb_coefficient(4, 4, 0, 0.5), InvalidArgument);
  CHECK_THROWS_AS(honeycomb_coefficient(4, 0, -1, 0.5), InvalidArgument);
}

TEST_CASE("honeycomb: the tension is a or a0 + a1 over N") {
  HoneycombParams p;
  CHECK(honeycomb_tension(p, 4) == doctest::Approx(0.7625).epsilon(1e-15));
  CHECK(honeycomb_tension(p, 5) == doctest::Approx(0.7).epsilon(1e-15));
  p.a0 = 0.2;
  p.a1 = 0.6;
  CHECK(honeycomb_tension(p, 3) == doctest::Approx(0.4).epsilon(1e-15));
  p.a = 0.3;
  CHECK(honeycomb_tension(p, 3) == 0.3);
  CHECK(honeycomb_tension(p, 17) == 0.3);
}

TEST_CASE("honeycomb: bad parameters throw InvalidArgument naming the parameter") {
  struct Case {
    HoneycombParams params;
    Mesh mesh;
    std::string message;  // a part of the expected message
  };
  auto with = [](auto set) {
    HoneycombParams p;
    set(p);
    return p;
  };
  const Mesh cube = test::cube();
  const Mesh mixed = test::mixed_polyhedron();
  const std::vector<Case> cases = {
      {with([](auto& p) { p.t = -0.1; }), cube, "honeycomb: parameter t = -0.1 is outside [0, 1]"},
      {with([](auto& p) { p.t = 1.5; }), cube, "honeycomb: parameter t = 1.5 is outside [0, 1]"},
      {with([](auto& p) { p.t = std::nan(""); }), cube, "parameter t = "},
      {with([](auto& p) { p.a = 0.0; }), cube, "honeycomb: parameter a = 0 is outside (0, 1)"},
      {with([](auto& p) { p.a = 1.0; }), cube, "honeycomb: parameter a = 1 is outside (0, 1)"},
      {with([](auto& p) { p.a = 1.2; }), cube, "honeycomb: parameter a = 1.2 is outside (0, 1)"},
      // 0.8 + 1/4 = 1.05 for the cube's quads.
      {with([](auto& p) {
         p.a0 = 0.8;
         p.a1 = 1.0;
       }),
       cube, "honeycomb: tension a0 + a1/N = 1.05 for a 4-sided face is outside (0, 1) (parameters a0, a1)"},
      // 0.5 + 1.6/3 = 1.0333 for the triangles; 0.9 for quads is fine (see below).
      {with([](auto& p) {
         p.a0 = 0.5;
         p.a1 = 1.6;
       }),
       mixed, "for a 3-sided face"},
      // -0.3 + 1.25/7 < 0 for the heptagon, while -0.3 + 1.25/3 > 0 for the triangles.
      {with([](auto& p) { p.a0 = -0.3; }), mixed, "for a 7-sided face is outside (0, 1) (parameters a0, a1)"},
      // The default tension of a 2-gon: 0.45 + 1.25/2 = 1.075.
      {HoneycombParams{}, face_manifold({{0, 0, 0}, {1, 0, 0}}),
       "honeycomb: tension a0 + a1/N = 1.075 for a 2-sided face is outside (0, 1) (parameters a0, a1)"},
  };
  for (const Case& c : cases) {
    CAPTURE(c.message);
    const Mesh before = c.mesh;
    std::string what;
    try {
      (void)honeycomb(c.mesh, c.params);
    } catch (const InvalidArgument& e) {
      what = e.what();
    }
    CHECK(what.find(c.message) != std::string::npos);
    CHECK_THROWS_AS(check_honeycomb_params(c.mesh, c.params), InvalidArgument);
    CHECK(c.mesh == before);
  }
  // Only the face sizes present matter: the parameters rejected for the mixed mesh's triangles are fine for
  // the cube (0.5 + 1.6/4 = 0.9), and a constant a overrides a0 and a1.
  HoneycombParams p = with([](auto& q) {
    q.a0 = 0.5;
    q.a1 = 1.6;
  });
  CHECK_NOTHROW(check_honeycomb_params(cube, p));
  p.a = 0.5;
  CHECK_NOTHROW(check_honeycomb_params(mixed, p));
  CHECK_NOTHROW(check_honeycomb_params(Mesh(), HoneycombParams{}));
}

TEST_CASE("honeycomb: under boundary=hole an open grid keeps its hole as a hole face") {
  // grid_soup(3, 2): V = 4 * 3 = 12, E = 3 * 3 + 4 * 2 = 17, F = 6 quads + 1 hole of 2 * (3 + 2) = 10 sides.
  const Mesh m = build_mesh(test::grid_soup(3, 2));
  REQUIRE(m.num_faces() == 7);
  REQUIRE(hole_sizes(m) == std::vector<std::uint32_t>{10});
  HoneycombParams hole;
  hole.boundary.rule = BoundaryRule::hole;
  const Mesh r = checked_step(m, hole);  // checks V' = 34, E' = 51, F' = 19 and the hole's size and flag
  CHECK(r.num_vertices() == 34);
  CHECK(r.num_edges() == 51);
  CHECK(r.num_faces() == 19);
  CHECK(statistics(r).holes == 1);
  // The hole's new face is a flat 10-gon in the plane z = 0, inside the grid's bounding box.
  for (FaceId f : r.faces()) {
    if (!r.is_hole(f)) continue;
    for (const glm::dvec3& q : face_positions(r, f)) {
      CHECK(q.z == 0.0);
      CHECK((q.x > 0.0 && q.x < 3.0 && q.y > 0.0 && q.y < 2.0));
    }
  }
  checked_step(r, hole);
}

TEST_CASE("honeycomb: point spheres are copied through") {
  Mesh m = test::cube();
  const VertexId lone = m.create_vertex({5, 6, 7});
  const Mesh r = honeycomb(m);  // the default tension would be 1.7 for a 1-corner face: it is not checked
  require_valid(r);
  // Cube: V' = 2 * 12 = 24, E' = 36, F' = 6 + 8 = 14; plus the point sphere.
  CHECK(r.num_vertices() == 25);
  CHECK(r.num_edges() == 36);
  CHECK(r.num_faces() == 15);
  const MeshStatistics s = statistics(r);
  CHECK(s.point_spheres == 1);
  CHECK(s.face_sizes == Histogram{{1, 1}, {4, 6}, {6, 8}});
  int found = 0;
  for (VertexId v : r.vertices()) {
    if (r.is_point_sphere(v)) found += r.position(v) == m.position(lone);
  }
  CHECK(found == 1);

  Mesh single;
  single.create_vertex({1, 2, 3});
  const Mesh rs = honeycomb(single);
  CHECK(rs == single);
}

TEST_CASE("honeycomb: 2-gons work with a constant tension") {
  HoneycombParams p;
  p.a = 0.5;
  // Two 2-gons on two vertices: V' = 2E = 4, E' = 6, F' = 2 + 2 (two 2-gons and two quads).
  const Mesh r = checked_step(face_manifold({{0, 0, 0}, {1, 0, 0}}), p);
  CHECK(statistics(r).face_sizes == Histogram{{2, 2}, {4, 2}});
  // A 2-gon next to larger faces: split a cube face between two adjacent corners.
  Mesh m = test::cube();
  const FaceId f(0);  // (0, 2, 3, 1)
  CornerId c0, c2;
  for (CornerId c : m.corners(f)) {
    if (m.vertex(c) == VertexId(0)) c0 = c;
    if (m.vertex(c) == VertexId(2)) c2 = c;
  }
  m.insert_edge(c0, c2);
  REQUIRE(statistics(m).face_sizes.count(2) == 1);
  checked_step(checked_step(m, p), p);
}

TEST_CASE("honeycomb: the result is deterministic and ignores tombstones of the input") {
  const Mesh cube = test::cube();
  Mesh with_tombstones = cube;
  CornerId c0, c3;
  for (CornerId c : with_tombstones.corners(FaceId(0))) {
    if (with_tombstones.vertex(c) == VertexId(0)) c0 = c;
    if (with_tombstones.vertex(c) == VertexId(3)) c3 = c;
  }
  const InsertEdgeResult ins = with_tombstones.insert_edge(c0, c3);
  with_tombstones.delete_edge(ins.edge);
  REQUIRE(with_tombstones == cube);
  REQUIRE(with_tombstones.corner_capacity() > cube.corner_capacity());
  const Mesh r = honeycomb(cube);
  CHECK(honeycomb(cube) == r);
  CHECK(honeycomb(with_tombstones) == r);
  // The result's own tombstones (faces merged away) do not disturb the next step either.
  CHECK(r.face_capacity() > r.num_faces());
  CHECK(honeycomb(r) == honeycomb(r));
}
