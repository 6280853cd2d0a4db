// convex_hull and dual_hull (docs/modeling.md, "Hulls"): against a brute-force hull written here (every
// plane through three points that has all the points on one side, O(n^4)) for small sets, generic and
// degenerate; the invariants on clouds of 10 to 100,000 points (valid, closed, genus 0, planar strictly
// convex faces passing the convexity check, every point inside or on, vertices taken from the points); the
// hand-derived hulls of the cube with points on its faces and edges, prisms and duplicated points; the
// dual's counts (V and F swapped, E kept) and its poles; every refusal; and the editor round trip (undo,
// redo, log replay).

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <limits>
#include <numbers>
#include <random>
#include <set>
#include <string>
#include <tuple>
#include <vector>

#include <dlfl/analysis/convex_polyhedron.h>
#include <dlfl/build_mesh.h>
#include <dlfl/errors.h>
#include <dlfl/navigation.h>
#include <dlfl/operations/convex_hull.h>
#include <dlfl/operations/dual_hull.h>

#include "brute_force_hull.h"
#include "modeling_checks.h"
#include "modeling_meshes.h"
#include "test_helpers.h"
#include "test_meshes.h"

using namespace dlfl;

namespace {

using Points = std::vector<glm::dvec3>;
using test::brute_force_planes;
using test::brute_force_vertices;
using test::Key;
using test::key;
using test::Plane;

double diagonal(const Points& points) {
  glm::dvec3 lo(std::numeric_limits<double>::max()), hi(-std::numeric_limits<double>::max());
  for (const glm::dvec3& p : points) lo = glm::min(lo, p), hi = glm::max(hi, p);
  return glm::length(hi - lo);
}

// The hull agrees with the brute force: the same face planes, one face per plane, the same corners.
void check_against_brute_force(const Points& points, const Mesh& hull, double tol) {
  const std::vector<Plane> planes = brute_force_planes(points, tol);
  CHECK(hull.num_faces() == planes.size());
  for (FaceId f : hull.faces()) {
    const FacePlane fp = face_plane(hull, f);
    const long matches = std::count_if(planes.begin(), planes.end(), [&](const Plane& q) {
      return glm::length(q.normal - fp.normal) < 1e-9 && std::abs(q.offset - fp.offset) < 1e-9;
    });
    CAPTURE(f);
    CHECK(matches == 1);
  }
  std::set<Key> corners;
  for (VertexId v : hull.vertices()) corners.insert(key(hull.position(v)));
  CHECK(corners.size() == hull.num_vertices());  // no two vertices at one point
  CHECK(corners == brute_force_vertices(points, planes, std::max(tol, 1e-12)));
}

// ---- invariants ------------------------------------------------------------------------------------------

// One component, closed, genus 0, passing the convexity check around the vertex centroid (planar, strictly
// convex faces, no coplanar neighbours, convex edges); every vertex one of the points; the points inside or
// on (`samples` of them, all if 0), within `outside` times the diagonal.
void check_hull(const Points& points, const Mesh& hull, std::size_t samples = 0, double outside = 1e-12) {
  test::require_valid(hull);
  CHECK(hull.num_hole_faces() == 0);
  CHECK(test::euler_characteristic(hull) == 2);
  const auto violation = convexity_violation(hull, vertex_centroid(hull));
  CHECK_MESSAGE(!violation, (violation ? violation->message : ""));
  CHECK(test::signed_volume(hull) > 0);
  // One component: a search along the edges reaches every vertex.
  std::vector<char> seen(hull.vertex_capacity(), 0);
  std::vector<VertexId> stack{*hull.vertices().begin()};
  seen[stack[0].index()] = 1;
  std::size_t reached = 1;
  while (!stack.empty()) {
    const VertexId v = stack.back();
    stack.pop_back();
    for (VertexId w : neighbours(hull, v)) {
      if (!seen[w.index()]) seen[w.index()] = 1, ++reached, stack.push_back(w);
    }
  }
  CHECK(reached == hull.num_vertices());
  const std::set<Key> input = [&] {
    std::set<Key> s;
    for (const glm::dvec3& p : points) s.insert(key(p));
    return s;
  }();
  for (VertexId v : hull.vertices()) CHECK(input.count(key(hull.position(v))) == 1);
  std::vector<FacePlane> planes;
  for (FaceId f : hull.faces()) planes.push_back(face_plane(hull, f));
  const double tol = outside * diagonal(points);
  std::mt19937_64 rng(7);
  const std::size_t count = samples == 0 ? points.size() : samples;
  double worst = -std::numeric_limits<double>::max();
  for (std::size_t i = 0; i < count; ++i) {
    const glm::dvec3& p = samples == 0 ? points[i] : points[rng() % points.size()];
    for (const FacePlane& plane : planes) worst = std::max(worst, plane.distance(p));
  }
  CAPTURE(worst);
  CHECK(worst <= tol);
}

// The dual: V and F swapped, E kept, valid, convex; each face of the hull's dual vertex set lies on the
// plane polar to its hull vertex.
void check_dual(const Mesh& hull, const Mesh& dual) {
  test::require_valid(dual);
  CHECK(dual.num_vertices() == hull.num_faces());
  CHECK(dual.num_faces() == hull.num_vertices());
  CHECK(dual.num_edges() == hull.num_edges());
  CHECK(test::euler_characteristic(dual) == 2);
  const auto violation = convexity_violation(dual, vertex_centroid(dual));
  CHECK_MESSAGE(!violation, (violation ? violation->message : ""));
  CHECK(test::signed_volume(dual) > 0);
}

// ---- point sets ------------------------------------------------------------------------------------------

Points in_ball(std::size_t n, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Points out;
  while (out.size() < n) {
    const glm::dvec3 p(u(rng), u(rng), u(rng));
    if (glm::dot(p, p) <= 1.0) out.push_back(p);
  }
  return out;
}

Points on_sphere(std::size_t n, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> g;
  Points out;
  while (out.size() < n) {
    const glm::dvec3 p(g(rng), g(rng), g(rng));
    if (glm::length(p) > 1e-3) out.push_back(glm::normalize(p));
  }
  return out;
}

// Small integer coordinates in [-r, r]: full of coplanar, collinear and repeated points, and exact in
// double arithmetic.
Points integer_points(std::size_t n, int r, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_int_distribution<int> u(-r, r);
  Points out;
  for (std::size_t i = 0; i < n; ++i) out.push_back(glm::dvec3(u(rng), u(rng), u(rng)));
  return out;
}

// The corners of [-1, 1]^3, then points on its faces and edges (one coordinate, or two, exactly +-1) and
// inside it.
Points cube_with_surface_points(std::size_t n, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Points out;
  for (int i = 0; i < 8; ++i) out.push_back({i & 1 ? 1.0 : -1.0, i & 2 ? 1.0 : -1.0, i & 4 ? 1.0 : -1.0});
  for (std::size_t i = 0; i < n; ++i) {
    glm::dvec3 p(u(rng), u(rng), u(rng));
    const int kind = int(i % 3);  // 0: on a face, 1: on an edge, 2: inside
    const int axis = int(rng() % 3);
    if (kind <= 1) p[axis] = rng() % 2 ? 1.0 : -1.0;
    if (kind == 1) p[(axis + 1) % 3] = rng() % 2 ? 1.0 : -1.0;
    out.push_back(p);
  }
  return out;
}

std::string refusal_of(const Points& points, bool dual = false) {
  std::string message;
  try {
    if (dual) {
      dual_hull(points);
    } else {
      convex_hull(points);
    }
  } catch (const ParameterError& e) {
    CHECK(e.parameter() == "points");
    message = e.what();
  }
  return message;
}

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

}  // namespace

TEST_CASE("convex_hull agrees with the brute-force hull on small generic sets") {
  for (std::size_t n : {4u, 5u, 10u, 20u, 40u}) {
    for (std::uint64_t seed : {1u, 2u}) {
      for (const Points& points : {in_ball(n, seed), on_sphere(n, seed)}) {
        CAPTURE(n);
        CAPTURE(seed);
        const Mesh hull = convex_hull(points);
        check_hull(points, hull);
        check_against_brute_force(points, hull, 1e-12);
        // Generic points: every face a triangle.
        for (FaceId f : hull.faces()) CHECK(hull.size(f) == 3);
      }
    }
  }
}

TEST_CASE("convex_hull agrees with the brute-force hull on degenerate integer sets") {
  // Coplanar faces, points inside faces and on edges, repeated points: exact arithmetic, tolerance 0.
  for (std::size_t n : {8u, 20u, 40u}) {
    for (int r : {1, 2, 4}) {
      for (std::uint64_t seed : {3u, 4u, 5u}) {
        const Points points = integer_points(n, r, seed);
        CAPTURE(n);
        CAPTURE(r);
        CAPTURE(seed);
        const Mesh hull = convex_hull(points);
        check_hull(points, hull);
        check_against_brute_force(points, hull, 0.0);
      }
    }
  }
}

TEST_CASE("convex_hull of the cube's corners with points on its faces and edges is the cube") {
  for (std::size_t n : {0u, 10u, 1000u, 100000u}) {
    const Points points = cube_with_surface_points(n, 11);
    CAPTURE(n);
    const Mesh hull = convex_hull(points);
    check_hull(points, hull, n > 20000 ? 1000 : 0);
    CHECK(test::counts(hull) == test::Counts{8, 12, 6});
    for (FaceId f : hull.faces()) CHECK(hull.size(f) == 4);
    if (n <= 10) check_against_brute_force(points, hull, 0.0);
  }
}

TEST_CASE("convex_hull of a lattice, of prisms and of repeated points") {
  SUBCASE("a 5 x 5 x 5 lattice is the cube") {
    Points points;
    for (int x = 0; x < 5; ++x)
      for (int y = 0; y < 5; ++y)
        for (int z = 0; z < 5; ++z) points.push_back(glm::dvec3(x, y, z));
    const Mesh hull = convex_hull(points);
    check_hull(points, hull);
    CHECK(test::counts(hull) == test::Counts{8, 12, 6});
  }
  SUBCASE("the n-gonal prisms: V 2n, E 3n, F n + 2, caps of n sides") {
    for (int n : {3, 5, 8, 50}) {
      const PolygonSoup soup = test::prism_soup(n);
      const Mesh hull = convex_hull(soup.positions);
      check_hull(soup.positions, hull);
      CHECK(test::counts(hull) == test::Counts{2 * n, 3 * n, n + 2});
      long caps = 0;
      for (FaceId f : hull.faces()) caps += hull.size(f) == std::uint32_t(n) ? 1 : 0;
      CHECK(caps == (n == 4 ? 6 : 2));
    }
  }
  SUBCASE("every point three times: the hull of the points once") {
    const Points once = on_sphere(500, 21);
    Points thrice;
    for (int k = 0; k < 3; ++k) thrice.insert(thrice.end(), once.begin(), once.end());
    const Mesh a = convex_hull(once), b = convex_hull(thrice);
    check_hull(thrice, b);
    CHECK(test::counts(a) == test::counts(b));
    std::set<Key> pa, pb;
    for (VertexId v : a.vertices()) pa.insert(key(a.position(v)));
    for (VertexId v : b.vertices()) pb.insert(key(b.position(v)));
    CHECK(pa == pb);
    CHECK(pa.size() == once.size());  // points on a sphere: all of them corners
  }
}

TEST_CASE("convex_hull of random clouds from 10 to 100,000 points") {
  for (std::size_t n : {10u, 100u, 1000u, 10000u, 100000u}) {
    CAPTURE(n);
    const std::size_t samples = n > 2000 ? 500 : 0;
    const Points ball = in_ball(n, 31), sphere = on_sphere(n, 32);
    const Mesh a = convex_hull(ball);
    check_hull(ball, a, samples);
    const Mesh b = convex_hull(sphere);
    check_hull(sphere, b, samples);
    // Random points on a sphere are all corners of their hull; its faces are triangles.
    CHECK(b.num_vertices() == n);
    CHECK(b.num_faces() == 2 * n - 4);
    if (n <= 10000) {
      check_dual(a, dual_hull(ball));
      check_dual(b, dual_hull(sphere));
    }
  }
}

TEST_CASE("convex_hull merges nearly coplanar faces and drops nearly straight corners") {
  SUBCASE("a square pyramid with one base corner raised by 1e-12: the base stays one quad") {
    const Points points = {{-1, -1, 0}, {1, -1, 0}, {-1, 1, 0}, {1, 1, 1e-12}, {0, 0, 1}};
    const Mesh hull = convex_hull(points);
    check_hull(points, hull);
    CHECK(test::counts(hull) == test::Counts{5, 8, 5});
  }
  SUBCASE("a point 1e-13 outside the middle of a cube's edge is left out, within that distance") {
    Points points = cube_with_surface_points(0, 1);
    points.push_back({1.0 + 1e-13, 1.0, 0.3});
    const Mesh hull = convex_hull(points);
    check_hull(points, hull, 0, 1e-13);
    CHECK(test::counts(hull) == test::Counts{8, 12, 6});
  }
}

TEST_CASE("convex_hull and dual_hull refuse degenerate point sets, saying why") {
  for (bool dual : {false, true}) {
    CAPTURE(dual);
    CHECK(contains(refusal_of({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, dual), "only 3 points"));
    CHECK(contains(refusal_of(Points(10, glm::dvec3(1, 2, 3)), dual), "all 10 points coincide"));
    Points line;
    for (int i = 0; i < 10; ++i) line.push_back(glm::dvec3(i, 2 * i, -3 * i));
    CHECK(contains(refusal_of(line, dual), "lie on one line"));
    Points plane;
    for (int i = 0; i < 30; ++i) plane.push_back(glm::dvec3(i % 7, i % 5, 2.0));
    CHECK(contains(refusal_of(plane, dual), "lie in one plane"));
    // A tilted plane through points computed in floating point: coplanar up to rounding.
    Points tilted;
    std::mt19937_64 rng(5);
    std::uniform_real_distribution<double> u(-1.0, 1.0);
    for (int i = 0; i < 200; ++i) {
      const double s = u(rng), t = u(rng);
      tilted.push_back(glm::dvec3(0.1, 0.2, 0.3) + s * glm::dvec3(0.3, 0.7, 0.1) +
                       t * glm::dvec3(-0.2, 0.1, 0.9));
    }
    const std::string message = refusal_of(tilted, dual);
    CAPTURE(message);
    CHECK((contains(message, "nearly coplanar") || contains(message, "lie in one plane")));
    Points bad = in_ball(20, 1);
    bad[7].y = std::numeric_limits<double>::quiet_NaN();
    CHECK(contains(refusal_of(bad, dual), "point 7 is not finite"));
    bad[7].y = std::numeric_limits<double>::infinity();
    CHECK(contains(refusal_of(bad, dual), "point 7 is not finite"));
    CHECK(refusal_of(bad, dual).rfind(
              dual ? "dual_hull: parameter points: " : "convex_hull: parameter points: ", 0) == 0);
  }
}

TEST_CASE("convex_hull and dual_hull of the platonic solids and the prisms, by hand") {
  SUBCASE("cube -> octahedron of the same circumradius") {
    const Mesh cube = test::cube();
    const Mesh hull = convex_hull(cube);
    CHECK(test::counts(hull) == test::Counts{8, 12, 6});
    const Mesh dual = dual_hull(cube);
    CHECK(test::counts(dual) == test::Counts{6, 12, 8});
    // Face planes at distance 1, vertices at sqrt(3): r^2 = sqrt(3), poles at sqrt(3) along the axes.
    std::set<Key> expected;
    const double s = std::sqrt(3.0);
    for (int k = 0; k < 3; ++k) {
      for (double sign : {-1.0, 1.0}) {
        glm::dvec3 p(0.0);
        p[k] = sign * s;
        expected.insert(key(p));
      }
    }
    for (VertexId v : dual.vertices()) {
      const glm::dvec3 p = dual.position(v);
      const bool found = std::any_of(expected.begin(), expected.end(), [&](const Key& k) {
        return glm::length(p - glm::dvec3(std::get<0>(k), std::get<1>(k), std::get<2>(k))) < 1e-12;
      });
      CHECK(found);
    }
    check_dual(hull, dual);
  }
  SUBCASE("octahedron -> cube, tetrahedron -> tetrahedron, icosahedron -> dodecahedron") {
    const Mesh octa = build_mesh(test::octahedron_soup());
    CHECK(test::counts(convex_hull(octa)) == test::Counts{6, 12, 8});
    CHECK(test::counts(dual_hull(octa)) == test::Counts{8, 12, 6});
    const Mesh tetra = test::tetrahedron();
    CHECK(test::counts(dual_hull(tetra)) == test::Counts{4, 6, 4});
    const Mesh ico = build_mesh(test::icosahedron_soup());
    const Mesh dodeca = dual_hull(ico);
    CHECK(test::counts(dodeca) == test::Counts{20, 30, 12});
    for (FaceId f : dodeca.faces()) CHECK(dodeca.size(f) == 5);
    check_dual(convex_hull(ico), dodeca);
  }
}

TEST_CASE("convex_hull and dual_hull on the modeling meshes through the editor: undo, redo, replay") {
  for (const auto& [name, mesh] : test::modeling_meshes()) {
    const std::string& label = name;
    const Mesh& start = mesh;
    CAPTURE(label);
    Points points;
    for (VertexId v : start.vertices()) points.push_back(start.position(v));
    if (label == "open grid 3x2") {
      // Every vertex at z = 0.
      const std::string message = test::check_refusal(start, "convex_hull", {}, "mesh");
      CHECK(contains(message, "lie in one plane"));
      test::check_refusal(start, "dual_hull", {}, "mesh");
      continue;
    }
    const Mesh hull = test::check_editor_round_trip(start, "convex_hull", {});
    check_hull(points, hull);
    const Mesh dual = test::check_editor_round_trip(start, "dual_hull", {});
    check_dual(hull, dual);
    if (label == "tetrahedron" || label == "cube" || label == "octahedron" ||
        label.find("prism") != std::string::npos) {
      // Convex already: its own hull.
      CHECK(test::counts(hull) == test::counts(start));
    }
  }
}

TEST_CASE("convex_hull keeps the vertex attributes of the vertices it keeps and declares the others") {
  Mesh cube = test::cube();
  cube.add_vertex_attribute<double>("weight", 1.0);
  cube.add_face_attribute<int>("label", 7);
  cube.vertex_attribute<double>("weight")[VertexId(5)] = 2.5;
  const glm::dvec3 p5 = cube.position(VertexId(5));
  const Mesh hull = convex_hull(cube);
  REQUIRE(hull.has_vertex_attribute("weight"));
  REQUIRE(hull.has_face_attribute("label"));
  for (VertexId v : hull.vertices()) {
    CHECK(hull.vertex_attribute<double>("weight")[v] == (hull.position(v) == p5 ? 2.5 : 1.0));
  }
  for (FaceId f : hull.faces()) CHECK(hull.face_attribute<int>("label")[f] == 7);
  const Mesh dual = dual_hull(cube);
  CHECK(dual.has_vertex_attribute("weight"));
  CHECK(dual.has_face_attribute("label"));
}
