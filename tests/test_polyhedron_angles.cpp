// The angle measurements of Meng-Prautzsch definition 2.3 (dlfl/analysis/polyhedron_angles.h): exact
// spherical diameters of Gaussian-image polygons and of unions of them. Expected values are derived by hand
// in the comments, or computed here independently: normals from cross products of the test's own, Gaussian
// polygons walked by the test, and diameters by brute force over densely sampled points of the arcs.

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <glm/geometric.hpp>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include <dlfl/analysis/polyhedron_angles.h>
#include <dlfl/build_mesh.h>
#include <dlfl/errors.h>
#include "convex_meshes.h"
#include "test_meshes.h"

using namespace dlfl;
using test::angle;
using test::normal_of;

namespace {

constexpr double pi = std::numbers::pi;
constexpr double deg = pi / 180.0;

// ---- meshes ---------------------------------------------------------------------------------------------

// The regular octahedron, vertices +-e_i; one triangle per octant, counter-clockwise seen from outside.
Mesh octahedron() {
  PolygonSoup s;
  s.positions = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
  for (std::uint32_t x : {0u, 1u}) {
    for (std::uint32_t y : {2u, 3u}) {
      for (std::uint32_t z : {4u, 5u}) {
        // (x, y, z) turns counter-clockwise around the octant's direction when it has an even number of minus
        // signs (the (+,+,+) octant: (e2 - e1) x (e3 - e1) = (1,1,1)); odd: reversed.
        const bool even = ((x == 1) + (y == 3) + (z == 5)) % 2 == 0;
        if (even) {
          s.add_face({x, y, z});
        } else {
          s.add_face({x, z, y});
        }
      }
    }
  }
  return build_mesh(s);
}

// A regular pentagonal pyramid without its base (the base is a hole face, FaceId(5)): base vertices
// (cos 72k, sin 72k, 0) = VertexId(k), apex VertexId(5) at height h = cos 36 * tan 30, so that every side
// face tilts 30 degrees from the vertical (tan(tilt) = h / inradius, inradius cos 36).
Mesh open_pentagonal_pyramid() {
  PolygonSoup s;
  for (int k = 0; k < 5; ++k) s.positions.push_back({std::cos(72 * k * deg), std::sin(72 * k * deg), 0.0});
  s.positions.push_back({0.0, 0.0, std::cos(36 * deg) * std::tan(30 * deg)});
  for (std::uint32_t k = 0; k < 5; ++k) s.add_face({k, (k + 1) % 5, 5});
  return build_mesh(s);
}

// The convex hull of points in general position (tests/convex_meshes.h).
Mesh hull(const std::vector<glm::dvec3>& points) { return build_mesh(test::hull_soup(points)); }

// `count` random points on the sphere, squashed to an ellipsoid: few points give wide Gaussian polygons.
Mesh random_hull(std::uint64_t seed, int count) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> gauss;
  std::vector<glm::dvec3> p;
  for (int i = 0; i < count; ++i) {
    const glm::dvec3 d = glm::normalize(glm::dvec3(gauss(rng), gauss(rng), gauss(rng)));
    p.push_back(d * glm::dvec3(1.0, 0.7, 0.4));
  }
  return hull(p);
}

// ---- brute force ------------------------------------------------------------------------------------------

// Points of v's Gaussian polygon: its normals, and `samples` steps along each great-circle arc between the
// normals of consecutive non-hole faces around v (slerp, endpoints included). Returns the longest arc.
double sample_polygon(const Mesh& m, VertexId v, int samples, std::vector<glm::dvec3>& out) {
  double longest = 0.0;
  for (CornerId c : m.corners(v)) {
    const FaceId f = m.face(c), g = m.face(m.next_around_vertex(c));
    if (m.is_hole(f)) continue;
    const glm::dvec3 a = normal_of(m, f);
    out.push_back(a);
    if (m.is_hole(g)) continue;
    const glm::dvec3 b = normal_of(m, g);
    const double w = angle(a, b);
    if (w < 1e-12) continue;
    longest = std::max(longest, w);
    for (int k = 1; k < samples; ++k) {
      const double t = double(k) / samples;
      out.push_back((std::sin((1 - t) * w) * a + std::sin(t * w) * b) / std::sin(w));
    }
  }
  return longest;
}

double sampled_diameter(const std::vector<glm::dvec3>& points) {
  double widest = 0.0;  // largest |p - q|^2: enough to pick the pair
  for (std::size_t i = 0; i < points.size(); ++i) {
    for (std::size_t j = i + 1; j < points.size(); ++j) {
      const glm::dvec3 d = points[i] - points[j];
      widest = std::max(widest, glm::dot(d, d));
    }
  }
  return 2.0 * std::asin(std::min(1.0, std::sqrt(widest) / 2.0));
}

// The largest angle between two normals only: what the measure was before arcs were searched.
double normal_pairs_diameter(const Mesh& m, const std::vector<VertexId>& vertices) {
  std::vector<glm::dvec3> normals;
  for (VertexId v : vertices) sample_polygon(m, v, 1, normals);
  return sampled_diameter(normals);
}

std::vector<VertexId> vertices_of(const Mesh& m, FaceId f) {
  std::vector<VertexId> out;
  for (CornerId c : m.corners(f)) out.push_back(m.vertex(c));
  return out;
}

struct SamplingReport {
  int elements = 0;
  int above_normal_pairs = 0;  // elements where a point inside an arc gives the diameter
};

// Every vertex and face angle against the diameter of densely sampled polygons. Samples lie at most h / 2
// along an arc from any of its points (h = longest arc / samples), so the widest sampled pair is at most h
// short of the widest pair (angles are 1-Lipschitz in each point), and normals are sampled exactly:
// sampled <= exact <= sampled + h. (Inside one arc a maximum below 180 degrees is smooth and the gap is
// O(h^2), but an antipodal pair where two arcs cross is a corner, and the gap is of order h.)
SamplingReport check_against_sampling(const Mesh& m, int samples = 96) {
  SamplingReport report;
  const auto check = [&](double exact, const std::vector<VertexId>& vertices) {
    std::vector<glm::dvec3> points;
    double longest = 0.0;
    for (VertexId v : vertices) longest = std::max(longest, sample_polygon(m, v, samples, points));
    const double h = longest / samples;
    const double sampled = sampled_diameter(points);
    CHECK(sampled <= exact + 1e-9);
    CHECK(exact <= sampled + h + 1e-9);
    ++report.elements;
    if (exact > normal_pairs_diameter(m, vertices) + 1e-6) ++report.above_normal_pairs;
  };
  for (VertexId v : m.vertices()) {
    CAPTURE(v.index());
    check(vertex_angle(m, v), {v});
  }
  for (FaceId f : m.faces()) {
    if (m.is_hole(f)) continue;
    CAPTURE(f.index());
    check(face_angle(m, f), vertices_of(m, f));
  }
  return report;
}

// polyhedron_angles (cached vertex angles, per-edge cross diameters) agrees with the functions one by one.
void check_summary_matches(const Mesh& m) {
  const PolyhedronAngles a = polyhedron_angles(m);
  double vmax = 0, vsum = 0, fmax = 0, fsum = 0;
  std::size_t vcount = 0, fcount = 0;
  for (VertexId v : m.vertices()) {
    const double x = vertex_angle(m, v);
    vmax = std::max(vmax, x), vsum += x, ++vcount;
  }
  for (FaceId f : m.faces()) {
    if (m.is_hole(f)) continue;
    const double x = face_angle(m, f);
    fmax = std::max(fmax, x), fsum += x, ++fcount;
  }
  CHECK(a.vertex.count == vcount);
  CHECK(a.face.count == fcount);
  CHECK(a.vertex.max == doctest::Approx(vmax).epsilon(1e-14));
  CHECK(a.vertex.mean == doctest::Approx(vsum / double(vcount)).epsilon(1e-14));
  CHECK(a.face.max == doctest::Approx(fmax).epsilon(1e-14));
  CHECK(a.face.mean == doctest::Approx(fsum / double(fcount)).epsilon(1e-14));
}

}  // namespace

TEST_CASE("polyhedron angles: the regular tetrahedron reaches inside its arcs") {
  // Normals n1..n4 with ni.nj = -1/3 and n1 + n2 + n3 + n4 = 0. Edge angle: acos(-1/3) = 109.47 degrees.
  // Vertex: its polygon is the spherical triangle n1 n2 n3. The normals are acos(-1/3) apart, but the point
  // of the great circle through n1, n2 farthest from n3 is the arc midpoint m = (n1 + n2) / |n1 + n2| (by the
  // symmetry swapping n1 and n2 it is +-m, and n3.m < 0): |n1 + n2|^2 = 2 - 2/3 = 4/3, n3.(n1 + n2) = -2/3,
  // so cos = (-2/3) / sqrt(4/3) = -1/sqrt(3): 125.26 degrees. No point pair does better: one point is then a
  // normal, and each normal's farthest point on the opposite arc is this midpoint.
  // Face: every edge has an end on a given face, so the 1-ring is the whole Gaussian image; it holds the
  // midpoints (n1 + n2)/.. and (n3 + n4)/.. = -(n1 + n2)/.., antipodal: 180 degrees.
  const Mesh tet = test::tetrahedron();
  const double vertex = std::acos(-1.0 / std::sqrt(3.0));
  for (VertexId v : tet.vertices()) CHECK(vertex_angle(tet, v) == doctest::Approx(vertex).epsilon(1e-14));
  for (FaceId f : tet.faces()) CHECK(face_angle(tet, f) == doctest::Approx(pi).epsilon(1e-14));
  for (EdgeId e : tet.edges()) CHECK(edge_angle(tet, e) == doctest::Approx(std::acos(-1.0 / 3.0)));
  const PolyhedronAngles a = polyhedron_angles(tet);
  CHECK(a.vertex.max == doctest::Approx(vertex));
  CHECK(a.vertex.mean == doctest::Approx(vertex));
  CHECK(a.vertex.count == 4);
  CHECK(a.face.max == doctest::Approx(pi));
  CHECK(a.face.mean == doctest::Approx(pi));
  CHECK(a.face.count == 4);
  CHECK(a.edge.count == 6);
  // 180 degrees comes out to the last bits, not just approximately.
  CHECK(a.face.max > pi - 1e-12);
}

TEST_CASE("polyhedron angles: the cube") {
  // Vertex: three orthogonal normals, say e1, e2, e3, joined by quarter circles. The arc e1 e2 lies on the
  // great circle with pole e3, so every point of it is 90 degrees from e3; likewise for the other two arcs.
  // So 90 degrees, attained all along the opposite arc.
  // Face: the top face's vertices see the top normal and all four side normals; +x and -x are 180 apart.
  const Mesh cube = test::cube();
  for (VertexId v : cube.vertices()) CHECK(vertex_angle(cube, v) == doctest::Approx(pi / 2).epsilon(1e-14));
  for (FaceId f : cube.faces()) CHECK(face_angle(cube, f) == doctest::Approx(pi).epsilon(1e-14));
  const PolyhedronAngles a = polyhedron_angles(cube);
  CHECK(a.edge.max == doctest::Approx(pi / 2));
  CHECK(a.vertex.max == doctest::Approx(pi / 2));
  CHECK(a.face.mean == doctest::Approx(pi));
}

TEST_CASE("polyhedron angles: the octahedron, widest at two normals above 90 degrees") {
  // Vertex e3: its polygon is the spherical square of (+-1, +-1, 1)/sqrt3, the central projection of the
  // square |x|, |y| <= 1 at z = 1. From q = (1,1,1)/sqrt3, a boundary point (x, y, 1) has cos = (x + y + 1) /
  // (sqrt3 sqrt(x^2 + y^2 + 1)). On the side x = -1 that is y / (sqrt3 sqrt(y^2 + 2)), increasing in y, so
  // smallest at y = -1: -1/3; the side y = -1 alike, and the sides x = 1, y = 1 keep cos > 0. So the
  // farthest point is the opposite corner and the vertex angle is acos(-1/3) = 109.47 degrees (the arcs do
  // not reach further here, though the angle is above 90).
  // Face: the face in the (+,+,+) octant touches every face with some positive sign, among them (1,-1,-1) and
  // (-1,1,1), antipodal: 180 degrees.
  const Mesh oct = octahedron();
  for (VertexId v : oct.vertices()) {
    CHECK(vertex_angle(oct, v) == doctest::Approx(std::acos(-1.0 / 3.0)).epsilon(1e-14));
  }
  for (FaceId f : oct.faces()) CHECK(face_angle(oct, f) == doctest::Approx(pi).epsilon(1e-14));
  for (EdgeId e : oct.edges()) CHECK(edge_angle(oct, e) == doctest::Approx(std::acos(1.0 / 3.0)));
  check_against_sampling(oct);
}

TEST_CASE("polyhedron angles: an open pentagonal pyramid, all angles below 90 degrees") {
  // Side normals n_k at 30 degrees from +z, azimuths 36 + 72k: n_j.n_k = cos^2 30 + sin^2 30 cos(72 |j - k|)
  // = 3/4 + cos(72 |j - k|) / 4. Below 90 degrees a polygon's diameter is between two normals: a point inside
  // an arc that beats both ends is the circle's farthest point from q, and an arc shorter than 180 degrees
  // around it has an end more than 90 degrees from q.
  // Apex: the pentagon n_0..n_4, widest at 144 degrees of azimuth: acos(3/4 + cos 144 / 4) = 56.8 degrees.
  // Base vertex k: the base is a hole, so its polygon is the open chain n_(k-1) n_k, one arc of
  // acos(3/4 + cos 72 / 4) = 32.4 degrees. Side face: the apex's pentagon plus two of its own arcs: the
  // apex's value.
  const Mesh m = open_pentagonal_pyramid();
  const double apex = std::acos(0.75 + std::cos(144 * deg) / 4);
  const double base = std::acos(0.75 + std::cos(72 * deg) / 4);
  CHECK(vertex_angle(m, VertexId(5)) == doctest::Approx(apex).epsilon(1e-14));
  for (std::uint32_t k = 0; k < 5; ++k) {
    CHECK(vertex_angle(m, VertexId(k)) == doctest::Approx(base).epsilon(1e-14));
    CHECK(face_angle(m, FaceId(k)) == doctest::Approx(apex).epsilon(1e-14));
  }
  const PolyhedronAngles a = polyhedron_angles(m);
  CHECK(a.edge.count == 5);  // the lateral edges; base edges border the hole
  CHECK(a.vertex.count == 6);
  CHECK(a.face.count == 5);
  CHECK(a.vertex.mean == doctest::Approx((apex + 5 * base) / 6));
  CHECK(a.face.max == doctest::Approx(apex));
  const SamplingReport r = check_against_sampling(m);
  CHECK(r.above_normal_pairs == 0);
  check_summary_matches(m);
}

TEST_CASE("polyhedron angles: open chains at a boundary") {
  // The tetrahedron with face 3 made a hole. The vertex off the hole (v0) keeps its closed triangle n0 n1 n2:
  // 125.26 degrees as above. A vertex of the hole sees two faces, one arc: acos(-1/3). Every other face
  // touches v0, and the vertices of the hole add only arcs of v0's triangle, so its face angle is v0's: no
  // longer 180, as n3 and the arcs to it are gone.
  Mesh tet = test::tetrahedron();
  tet.set_hole(FaceId(3), true);
  const double closed = std::acos(-1.0 / std::sqrt(3.0));
  CHECK(vertex_angle(tet, VertexId(0)) == doctest::Approx(closed).epsilon(1e-14));
  for (std::uint32_t v = 1; v < 4; ++v) {
    CHECK(vertex_angle(tet, VertexId(v)) == doctest::Approx(std::acos(-1.0 / 3.0)).epsilon(1e-14));
  }
  for (std::uint32_t f = 0; f < 3; ++f) CHECK(face_angle(tet, FaceId(f)) == doctest::Approx(closed));
  check_against_sampling(tet);
  check_summary_matches(tet);

  // A lone triangle: each vertex sees one normal (a point), so every angle is 0, and no edge has two faces.
  PolygonSoup s;
  s.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
  s.add_face({0, 1, 2});
  const Mesh triangle = build_mesh(s);
  for (VertexId v : triangle.vertices()) CHECK(vertex_angle(triangle, v) == 0.0);
  CHECK(face_angle(triangle, FaceId(0)) == 0.0);
  const PolyhedronAngles a = polyhedron_angles(triangle);
  CHECK(a.edge.count == 0);
  CHECK(a.face.count == 1);
  CHECK(a.face.max == 0.0);
}

TEST_CASE("polyhedron angles: random convex hulls against dense sampling") {
  // Exact within the sampling bound and never below the sample; the hulls of few points have wide polygons,
  // so some diameters lie inside arcs and the test sees the arcs matter.
  int above = 0;
  for (std::uint64_t seed = 1; seed <= 6; ++seed) {
    for (int count : {6, 9, 14}) {
      CAPTURE(seed);
      CAPTURE(count);
      const Mesh m = random_hull(seed, count);
      REQUIRE(m.num_faces() == 2 * std::size_t(count) - 4);  // a triangulated sphere: F = 2V - 4
      above += check_against_sampling(m).above_normal_pairs;
      check_summary_matches(m);
    }
  }
  CHECK(above > 0);
}

TEST_CASE("polyhedron angles: hole faces are refused by name") {
  const Mesh m = open_pentagonal_pyramid();
  const FaceId hole(5);
  REQUIRE(m.is_hole(hole));
  CHECK_THROWS_WITH_AS(face_angle(m, hole), doctest::Contains("f5"), TopologyError);
  int refused = 0;
  for (EdgeId e : m.edges()) {
    const bool boundary = m.is_hole(m.face(e, 0)) || m.is_hole(m.face(e, 1));
    if (boundary) {
      const std::string name = to_string(e) + " ";  // "e1 " does not match inside "e12 "
      CHECK_THROWS_WITH_AS(edge_angle(m, e), doctest::Contains(name.c_str()), TopologyError);
      ++refused;
    } else {
      CHECK(edge_angle(m, e) > 0.0);
    }
  }
  CHECK(refused == 5);
}
