// Meng-Prautzsch H, P and MHP: hand-computed cubes and icosahedra, the paper's claims checked numerically
// (theorems 3.1 / remark 2.5 and 4.2), the convexity check, the angle measurements and every error.
// Expected values are derived here independently: closed-form positions, brute-force convex hulls, and
// brute-force vertices of Delta_F and convexity tests that share no code with the schemes.

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <limits>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include <dlfl/analysis/convex_polyhedron.h>
#include <dlfl/analysis/polyhedron_angles.h>
#include <dlfl/build_mesh.h>
#include <dlfl/errors.h>
#include <dlfl/schemes/meng_prautzsch_honeycomb.h>
#include <dlfl/schemes/meng_prautzsch_mixed.h>
#include <dlfl/schemes/meng_prautzsch_pushing.h>
#include <dlfl/schemes/scheme_registry.h>
#include <dlfl/validate.h>
#include "convex_meshes.h"
#include "scheme_meshes.h"
#include "test_helpers.h"
#include "test_meshes.h"

using namespace dlfl;
using test::angle;
using test::hull_soup;
using test::normal_of;
using test::require_valid;

namespace {

// The vertex, edge and face counts of a result.
void check_counts(const Mesh& m, std::size_t vertices, std::size_t edges, std::size_t faces) {
  CHECK(m.num_vertices() == vertices);
  CHECK(m.num_edges() == edges);
  CHECK(m.num_faces() == faces);
}

constexpr double pi = std::numbers::pi;
constexpr double phi = std::numbers::phi;

// ---- meshes ---------------------------------------------------------------------------------------------

// The regular icosahedron: the 12 points (0, +-1, +-phi) and their cyclic permutations, edge length 2.
Mesh icosahedron() {
  std::vector<glm::dvec3> p;
  for (double a : {-1.0, 1.0}) {
    for (double b : {-phi, phi}) {
      p.push_back({0, a, b});
      p.push_back({a, b, 0});
      p.push_back({b, 0, a});
    }
  }
  return build_mesh(hull_soup(p));
}

// A random convex polyhedron: the hull of 16 random points on an ellipsoid (radii 1, 0.8, 0.6), shifted off
// the origin. Triangles only, all edges strictly convex (points in general position).
Mesh random_polyhedron(std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  auto unit = [&] { return double(rng() >> 11) * 0x1.0p-53; };
  std::vector<glm::dvec3> p;
  while (p.size() < 16) {
    const glm::dvec3 d(2 * unit() - 1, 2 * unit() - 1, 2 * unit() - 1);
    const double l = glm::length(d);
    if (l < 0.1 || l > 1.0) continue;
    p.push_back(glm::dvec3(1.0, 0.8, 0.6) * (d / l) + glm::dvec3(0.3, -0.2, 0.1));
  }
  return build_mesh(hull_soup(p));
}

// A box with half-sides 1, 0.5, 0.25: faces of different sizes meet at every vertex.
Mesh cuboid() {
  PolygonSoup s = test::cube_soup();
  for (auto& p : s.positions) p *= glm::dvec3(1.0, 0.5, 0.25);
  return build_mesh(s);
}

// The octahedron with its top vertex pushed down to z = -0.5: planar triangles, concave at the equator.
Mesh dented_octahedron() {
  PolygonSoup s;
  s.positions = {{1, 0, 0}, {0, 1, 0}, {-1, 0, 0}, {0, -1, 0}, {0, 0, -0.5}, {0, 0, -1}};
  for (std::uint32_t i = 0; i < 4; ++i) {
    s.add_face({i, (i + 1) % 4, 4});
    s.add_face({(i + 1) % 4, i, 5});
  }
  return build_mesh(s);
}

// ---- independent geometry -------------------------------------------------------------------------------

// Largest distance of a face's vertices from the plane through its first three.
double planarity_error(const Mesh& m, FaceId f) {
  const glm::dvec3 n = normal_of(m, f);
  const glm::dvec3 p0 = m.position(m.vertex(m.first_corner(f)));
  double worst = 0.0;
  for (CornerId c : m.corners(f))
    worst = std::max(worst, std::abs(glm::dot(n, m.position(m.vertex(c)) - p0)));
  return worst;
}

// The definition, by brute force: every vertex strictly inside the plane of every face it is not on.
bool strictly_convex_brute(const Mesh& m) {
  for (FaceId f : m.faces()) {
    const glm::dvec3 n = normal_of(m, f);
    const glm::dvec3 p0 = m.position(m.vertex(m.first_corner(f)));
    std::vector<bool> on_face(m.vertex_capacity(), false);
    for (CornerId c : m.corners(f)) on_face[m.vertex(c).index()] = true;
    for (VertexId v : m.vertices()) {
      if (!on_face[v.index()] && !(glm::dot(n, m.position(v) - p0) < -1e-12)) return false;
    }
  }
  return true;
}

// The height above face f of the nearest vertex of Delta_f off f, by brute force over triples of edge planes.
// Edge planes pass through their edge; `edge_normal` gives their normals by edge handle.
double delta_height(const Mesh& m, FaceId f, const std::vector<glm::dvec3>& edge_normal) {
  struct Plane {
    glm::dvec3 n;
    double d;
  };
  std::vector<Plane> planes;
  for (CornerId c : m.corners(f)) {
    const glm::dvec3 n = edge_normal[m.edge(c).index()];
    planes.push_back({n, glm::dot(n, m.position(m.vertex(c)))});
  }
  const glm::dvec3 nf = normal_of(m, f);
  const double df = glm::dot(nf, m.position(m.vertex(m.first_corner(f))));
  double best = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < planes.size(); ++i) {
    for (std::size_t j = i + 1; j < planes.size(); ++j) {
      for (std::size_t k = j + 1; k < planes.size(); ++k) {
        const glm::dvec3 a = planes[i].n, b = planes[j].n, c = planes[k].n;
        const double det = glm::dot(a, glm::cross(b, c));
        if (std::abs(det) < 1e-12) continue;
        const glm::dvec3 x = (planes[i].d * glm::cross(b, c) + planes[j].d * glm::cross(c, a) +
                              planes[k].d * glm::cross(a, b)) /
                             det;
        const double height = glm::dot(nf, x) - df;
        if (height < 1e-9) continue;
        bool inside = true;
        for (const Plane& p : planes) inside = inside && glm::dot(p.n, x) - p.d < 1e-9;
        if (inside) best = std::min(best, height);
      }
    }
  }
  return best;
}

// Bisecting edge planes (ratio 1): their normals bisect the two face normals.
std::vector<glm::dvec3> bisecting_normals(const Mesh& m) {
  std::vector<glm::dvec3> n(m.edge_capacity());
  for (EdgeId e : m.edges())
    n[e.index()] = glm::normalize(normal_of(m, m.face(e, 0)) + normal_of(m, m.face(e, 1)));
  return n;
}

double max_vertex_angle(const Mesh& m) { return polyhedron_angles(m).vertex.max; }
double max_face_angle(const Mesh& m) { return polyhedron_angles(m).face.max; }

// The claims of the issue for one H step: counts, valences, planar e-faces, f-faces parallel to their old
// faces, old vertices in place, convex; and with bisecting planes, f-face f at tau times the height of v_F.
void check_honeycomb_step(const Mesh& in, const MpHoneycombParams& params, bool bisecting = true) {
  const Mesh out = mp_honeycomb(in, params);
  require_valid(out);
  const std::size_t V = in.num_vertices(), E = in.num_edges(), F = in.num_faces();
  check_counts(out, V + 2 * E, 4 * E, F + E);
  for (VertexId v : in.vertices()) {
    CHECK(out.valence(v) == in.valence(v));
    CHECK(out.position(v) == in.position(v));  // bit for bit: old vertices stay
  }
  for (std::uint32_t v = std::uint32_t(V); v < out.num_vertices(); ++v) CHECK(out.valence(VertexId(v)) == 3);
  double scale = 0.0;
  for (VertexId v : in.vertices()) scale = std::max(scale, glm::length(in.position(v)));
  const auto normals = bisecting_normals(in);
  for (FaceId f : in.faces()) {
    CHECK(out.size(f) == in.size(f));
    CHECK(glm::length(glm::cross(normal_of(out, f), normal_of(in, f))) < 1e-12);  // parallel
    CHECK(glm::dot(normal_of(out, f), normal_of(in, f)) > 0.0);                   // same side
    if (bisecting && !params.random.enabled) {
      const double offset = glm::dot(normal_of(in, f), out.position(out.vertex(out.first_corner(f))) -
                                                           in.position(in.vertex(in.first_corner(f))));
      CHECK(offset == doctest::Approx(params.tau * delta_height(in, f, normals)).epsilon(1e-10));
    }
  }
  for (std::uint32_t e = 0; e < E; ++e) {
    const FaceId hexagon(std::uint32_t(F) + e);
    CHECK(out.size(hexagon) == 6);
    CHECK(planarity_error(out, hexagon) < 1e-12 * scale);
  }
  CHECK(is_convex_polyhedron(out, vertex_centroid(out)));
  CHECK(strictly_convex_brute(out));
}

// The claims for one P step: counts, valences, convex, old vertices moved straight towards the centre.
void check_pushing_step(const Mesh& in, const MpPushingParams& params) {
  const Mesh out = mp_pushing(in, params);
  require_valid(out);
  const std::size_t V = in.num_vertices(), E = in.num_edges(), F = in.num_faces();
  check_counts(out, V + E, 4 * E, F + 2 * E);
  const glm::dvec3 centre = params.center.value_or(vertex_centroid(in));
  for (VertexId v : in.vertices()) {
    CHECK(out.valence(v) == in.valence(v));
    const glm::dvec3 before = in.position(v) - centre, after = out.position(v) - centre;
    CHECK(glm::length(after) < glm::length(before));
    CHECK(glm::length(glm::cross(before, after)) < 1e-12 * glm::dot(before, before));
    CHECK(glm::dot(before, after) > 0.0);
  }
  for (std::uint32_t v = std::uint32_t(V); v < out.num_vertices(); ++v) CHECK(out.valence(VertexId(v)) == 6);
  for (std::size_t f = 0; f < F; ++f)
    CHECK(out.size(FaceId(std::uint32_t(f))) == in.size(FaceId(std::uint32_t(f))));
  for (std::size_t k = F; k < out.num_faces(); ++k) CHECK(out.size(FaceId(std::uint32_t(k))) == 3);
  CHECK(is_convex_polyhedron(out, centre));
  CHECK(strictly_convex_brute(out));
}

MpHoneycombParams h_params(double tau, double ratio = 1.0) {
  MpHoneycombParams p;
  p.tau = tau;
  p.ratio = ratio;
  return p;
}

MpPushingParams p_params(double tau, double ratio = 1.0) {
  MpPushingParams p;
  p.tau = tau;
  p.ratio = ratio;
  return p;
}

// Parameters drawn at random from `seed` (per-edge ratios, per-vertex taus).
template <class Params>
Params random_params(std::uint64_t seed) {
  Params p;
  p.random.enabled = true;
  p.random.seed = seed;
  return p;
}

// Three steps of `scheme` from each start with each parameter set: `measure` never grows; returns the
// largest ratio of the last measure to the first, for a check that it also shrinks.
template <class Params, class Scheme, class Measure>
double check_never_grows(std::initializer_list<Mesh> starts, std::initializer_list<Params> params,
                         Scheme scheme, Measure measure) {
  double worst = 0;
  for (const Mesh& start : starts) {
    for (const Params& p : params) {
      Mesh m = start;
      const double first = measure(m);
      double previous = first;
      for (int step = 0; step < 3; ++step) {
        m = scheme(m, p);
        const double now = measure(m);
        CHECK(now <= previous + 1e-12);
        previous = now;
      }
      worst = std::max(worst, previous / first);
    }
  }
  return worst;
}

}  // namespace

// ---- the convexity check --------------------------------------------------------------------------------

TEST_CASE("convex polyhedron: the check agrees with the brute-force definition") {
  const Mesh accepted[] = {test::tetrahedron(), test::cube(),         test::dodecahedron(),
                           icosahedron(),       random_polyhedron(7), cuboid()};
  for (const Mesh& m : accepted) {
    CHECK(strictly_convex_brute(m));
    CHECK(is_convex_polyhedron(m, vertex_centroid(m)));
  }
  const Mesh rejected[] = {dented_octahedron(), test::mixed_polyhedron()};
  for (const Mesh& m : rejected) {
    CHECK_FALSE(strictly_convex_brute(m));
    CHECK_FALSE(is_convex_polyhedron(m, vertex_centroid(m)));
  }
  // The random hull really is a hull of triangles: V - E + F = 2 and 3F = 2E.
  const Mesh r = random_polyhedron(7);
  CHECK(long(r.num_vertices()) - long(r.num_edges()) + long(r.num_faces()) == 2);
  CHECK(3 * r.num_faces() == 2 * r.num_edges());
}

TEST_CASE("convex polyhedron: every violated precondition names the face, edge or vertex") {
  auto message = [](const Mesh& m, glm::dvec3 centre) {
    const auto v = convexity_violation(m, centre);
    REQUIRE(v.has_value());
    return v->message;
  };
  // Open mesh: the grid's boundary loop is hole face 6.
  const Mesh grid = build_mesh(test::grid_soup(3, 2));
  CHECK(message(grid, {0, 0, 0}).find("f6 is a hole") != std::string::npos);
  CHECK_THROWS_AS(require_convex_polyhedron(grid, {0, 0, 0}, "test"), TopologyError);
  // A point sphere.
  Mesh sphere = test::cube();
  sphere.create_vertex({0, 0, 0});
  CHECK(message(sphere, {0, 0, 0}).find("v8 is a point sphere") != std::string::npos);
  CHECK_THROWS_AS(require_convex_polyhedron(sphere, {0, 0, 0}, "test"), TopologyError);
  // A face bent out of its plane: vertex 7 = (1,1,1) moved outwards lies on faces 1, 3 and 5; face 1 comes
  // first.
  Mesh bent = test::cube();
  bent.set_position(VertexId(7), {1.1, 1.1, 1.1});
  CHECK(message(bent, {0, 0, 0}).find("f1 is not planar") != std::string::npos);
  CHECK_THROWS_AS(require_convex_polyhedron(bent, {0, 0, 0}, "test"), InvalidArgument);
  // Coplanar neighbours: a diagonal splits cube face 0 into two triangles; the new edge is e12, the new face
  // f6.
  Mesh split = test::cube();
  const CornerId c0 = split.first_corner(FaceId(0));
  split.insert_edge(c0, split.next(split.next(c0)));
  const std::string coplanar = message(split, {0, 0, 0});
  CHECK(coplanar.find("coplanar") != std::string::npos);
  CHECK(coplanar.find("e12") != std::string::npos);
  CHECK(coplanar.find("f6") != std::string::npos);
  // A concave edge: the dented octahedron folds in along its equator.
  CHECK(message(dented_octahedron(), {0, 0, -0.8}).find("is concave") != std::string::npos);
  // The centre outside, or on the boundary: face 5 is x = +1.
  CHECK(message(test::cube(), {5, 0, 0}).find("not strictly inside the plane of f5") != std::string::npos);
  CHECK(message(test::cube(), {1, 0, 0}).find("f5") != std::string::npos);
  CHECK_THROWS_AS(require_convex_polyhedron(test::cube(), {5, 0, 0}, "test"), InvalidArgument);
  CHECK_NOTHROW(require_convex_polyhedron(test::cube(), {0.99, 0.5, -0.9}, "test"));
}

// ---- measurements ---------------------------------------------------------------------------------------

TEST_CASE("angles: the cube, the tetrahedron and the icosahedron by hand") {
  // Cube: adjacent normals are perpendicular (edge and vertex angles 90 degrees); a face shares a vertex with
  // both faces of an opposite pair, whose normals are 180 degrees apart.
  const PolyhedronAngles cube = polyhedron_angles(test::cube());
  CHECK(cube.edge.max == doctest::Approx(pi / 2));
  CHECK(cube.edge.mean == doctest::Approx(pi / 2));
  CHECK(cube.edge.count == 12);
  CHECK(cube.vertex.max == doctest::Approx(pi / 2));
  CHECK(cube.vertex.count == 8);
  CHECK(cube.face.max == doctest::Approx(pi));
  CHECK(cube.face.mean == doctest::Approx(pi));
  // Regular tetrahedron: any two face normals make arccos(-1/3), the edge angle. The vertex and face angles
  // reach inside the Gaussian arcs (derived in test_polyhedron_angles.cpp): a normal and the midpoint of the
  // opposite arc make arccos(-1/sqrt3); a face's 1-ring holds the midpoints of two opposite arcs, 180 apart.
  const PolyhedronAngles tet = polyhedron_angles(test::tetrahedron());
  for (double a : {tet.edge.max, tet.edge.mean}) CHECK(a == doctest::Approx(std::acos(-1.0 / 3.0)));
  for (double a : {tet.vertex.max, tet.vertex.mean})
    CHECK(a == doctest::Approx(std::acos(-1 / std::sqrt(3.0))));
  for (double a : {tet.face.max, tet.face.mean}) CHECK(a == doctest::Approx(pi));
  // Icosahedron: adjacent normals make arccos(sqrt(5)/3) (the dihedral angle is arccos(-sqrt(5)/3)).
  const Mesh ico = icosahedron();
  const PolyhedronAngles a = polyhedron_angles(ico);
  CHECK(a.edge.max == doctest::Approx(std::acos(std::sqrt(5.0) / 3.0)));
  CHECK(a.edge.mean == doctest::Approx(std::acos(std::sqrt(5.0) / 3.0)));
  // Around a vertex v the five face normals make the same angle beta with v, 72 degrees apart in azimuth;
  // the widest pair is 144 degrees apart: cos = cos^2 beta + sin^2 beta cos 144. cos beta = r / R, inradius
  // r = phi^2 / sqrt 3 over circumradius R = sqrt(1 + phi^2) (edge length 2).
  const double cos_beta = phi * phi / std::sqrt(3.0) / std::sqrt(1.0 + phi * phi);
  const double widest =
      std::acos(cos_beta * cos_beta + (1 - cos_beta * cos_beta) * std::cos(144.0 * pi / 180.0));
  CHECK(vertex_angle(ico, VertexId(0)) == doctest::Approx(widest));
  CHECK(a.vertex.max == doctest::Approx(widest));
  CHECK(a.vertex.mean == doctest::Approx(widest));
  CHECK(edge_angle(ico, EdgeId(0)) == doctest::Approx(std::acos(std::sqrt(5.0) / 3.0)));
}

TEST_CASE("angles: one H step on the cube by hand") {
  // f-face normals are the axes, e-face normals (1,1,0)/sqrt2 and the like. f|e edges: 45 degrees (24 of
  // them), e|e edges at the old vertices: 60 degrees (24). Every vertex sees normals 60 degrees apart at
  // most. An f-face's vertices see the axis and four e-normals: widest (1,1,0) vs (1,-1,0) = 90; an e-face's
  // see e.g. (1,0,1) vs (0,1,-1): 120. Means: edges (24*45 + 24*60)/48, faces (6*90 + 12*120)/18.
  const Mesh out = mp_honeycomb(test::cube());
  const PolyhedronAngles a = polyhedron_angles(out);
  const double deg = pi / 180;
  CHECK(a.edge.max == doctest::Approx(60 * deg));
  CHECK(a.edge.mean == doctest::Approx(52.5 * deg));
  CHECK(a.vertex.max == doctest::Approx(60 * deg));
  CHECK(a.vertex.mean == doctest::Approx(60 * deg));
  CHECK(a.face.max == doctest::Approx(120 * deg));
  CHECK(a.face.mean == doctest::Approx(110 * deg));
  CHECK(face_angle(out, FaceId(0)) == doctest::Approx(90 * deg));
  CHECK(face_angle(out, FaceId(6)) == doctest::Approx(120 * deg));
}

// ---- H ----------------------------------------------------------------------------------------------------

TEST_CASE("mp-honeycomb: the cube by hand") {
  // Bisecting planes of the cube's edges are x + y = 2 and the like. Over face x = 1 they bound the pyramid
  // with apex v_F = (2,0,0) at height 1; the f-face at height tau is the square x = 1 + tau, |y|, |z| <= 1 -
  // tau.
  for (double tau : {0.5, 0.2, 0.8}) {
    CAPTURE(tau);
    const Mesh out = mp_honeycomb(test::cube(), h_params(tau));
    CHECK(out.num_vertices() == 32);
    CHECK(out.num_edges() == 48);
    std::size_t quads = 0, hexagons = 0;
    for (FaceId f : out.faces()) {
      quads += out.size(f) == 4;
      hexagons += out.size(f) == 6;
    }
    CHECK(quads == 6);
    CHECK(hexagons == 12);
    for (std::uint32_t v = 8; v < 32; ++v) {
      glm::dvec3 a = glm::abs(out.position(VertexId(v)));
      std::sort(&a.x, &a.x + 3);
      CHECK(a[0] == doctest::Approx(1 - tau).epsilon(1e-14));
      CHECK(a[1] == doctest::Approx(1 - tau).epsilon(1e-14));
      CHECK(a[2] == doctest::Approx(1 + tau).epsilon(1e-14));
    }
    // Every e-face lies on its edge's bisecting plane, e.g. x + y = 2: for some pair of axes, every vertex
    // has |p_i| + |p_j| = 2.
    for (std::uint32_t e = 0; e < 12; ++e) {
      const FaceId hexagon(6 + e);
      int planes = 0;
      for (int i = 0; i < 3; ++i) {
        const int j = (i + 1) % 3;
        bool on = true;
        for (CornerId c : out.corners(hexagon)) {
          const glm::dvec3 p = glm::abs(out.position(out.vertex(c)));
          on = on && std::abs(p[i] + p[j] - 2.0) < 1e-14;
        }
        planes += on;
      }
      CHECK(planes == 1);
    }
    check_honeycomb_step(test::cube(), h_params(tau));
  }
}

TEST_CASE("mp-honeycomb: icosahedron, dodecahedron, cuboid and random polyhedra") {
  for (double tau : {0.3, 0.5, 0.9}) {
    CAPTURE(tau);
    check_honeycomb_step(icosahedron(), h_params(tau));
    check_honeycomb_step(test::dodecahedron(), h_params(tau));
    check_honeycomb_step(cuboid(), h_params(tau));
    check_honeycomb_step(random_polyhedron(11), h_params(tau));
    check_honeycomb_step(test::tetrahedron(), h_params(tau));
  }
  // Two steps: the input of the second has hexagons and 3-valent vertices.
  check_honeycomb_step(mp_honeycomb(random_polyhedron(5)), h_params(0.4));
}

TEST_CASE("mp-honeycomb: the ratio divides each exterior angle from the side-0 face") {
  // e-face F + e's normal n: angle(n0, n) : angle(n, n1) = ratio : 1, with n0, n1 the normals of the faces on
  // side 0 and side 1 of input edge e (the f-faces keep those normals).
  for (double ratio : {0.5, 2.0, 1.0}) {
    CAPTURE(ratio);
    const Mesh in = random_polyhedron(3);
    const Mesh out = mp_honeycomb(in, h_params(0.5, ratio));
    const std::uint32_t F = std::uint32_t(in.num_faces());
    for (EdgeId e : in.edges()) {
      const glm::dvec3 n = normal_of(out, FaceId(F + e.index()));
      const double a0 = angle(normal_of(in, in.face(e, 0)), n), a1 = angle(n, normal_of(in, in.face(e, 1)));
      CHECK(a0 / a1 == doctest::Approx(ratio).epsilon(1e-9));
    }
    check_honeycomb_step(in, h_params(0.5, ratio), false);
  }
}

TEST_CASE("mp-honeycomb: random per-edge ratios and per-face offsets, reproducible from the seed") {
  MpHoneycombParams p;
  p.random.enabled = true;
  p.random.epsilon = 0.2;
  p.random.seed = 42;
  const Mesh in = icosahedron();
  const Mesh a = mp_honeycomb(in, p);
  const Mesh b = mp_honeycomb(in, p);
  CHECK(a == b);
  p.random.seed = 43;
  const Mesh c = mp_honeycomb(in, p);
  CHECK_FALSE(a == c);
  CHECK_FALSE(a == mp_honeycomb(in));
  check_honeycomb_step(in, p);
  // Every ratio and offset lies inside the tolerance: fractions of the exterior angle in [0.2, 0.8] ...
  const std::uint32_t F = std::uint32_t(in.num_faces());
  std::vector<glm::dvec3> planes(in.edge_capacity());
  double lowest = 1.0, highest = 0.0;
  for (EdgeId e : in.edges()) {
    const glm::dvec3 n = normal_of(a, FaceId(F + e.index()));
    planes[e.index()] = n;
    const double a0 = angle(normal_of(in, in.face(e, 0)), n), a1 = angle(n, normal_of(in, in.face(e, 1)));
    lowest = std::min(lowest, a0 / (a0 + a1));
    highest = std::max(highest, a0 / (a0 + a1));
  }
  CHECK(lowest >= 0.2 - 1e-9);
  CHECK(highest <= 0.8 + 1e-9);
  CHECK(highest - lowest > 0.2);  // really spread out
  // ... and offsets, as a fraction of the height of v_F over the actual edge planes, in [0.2, 0.8].
  for (FaceId f : in.faces()) {
    const double offset = glm::dot(normal_of(in, f), a.position(a.vertex(a.first_corner(f))) -
                                                         in.position(in.vertex(in.first_corner(f))));
    const double fraction = offset / delta_height(in, f, planes);
    CHECK(fraction >= 0.2 - 1e-9);
    CHECK(fraction <= 0.8 + 1e-9);
  }
}

TEST_CASE("mp-honeycomb: the maximum vertex angle never grows and shrinks over several steps") {
  // Remark 2.5 (faces of the Gaussian image only get subdivided) and theorem 3.1 (geometric decrease). The
  // tetrahedron's vertex angles (125.26 degrees) are attained inside Gaussian arcs, which the measure sees.
  const double shrink = check_never_grows(
      {test::cube(), test::tetrahedron(), icosahedron(), cuboid(), random_polyhedron(21)},
      {h_params(0.5), h_params(0.2, 2.0), h_params(0.8, 0.5), random_params<MpHoneycombParams>(9)},
      [](const Mesh& m, const MpHoneycombParams& p) { return mp_honeycomb(m, p); }, max_vertex_angle);
  CHECK(shrink < 0.9);
}

// ---- P ----------------------------------------------------------------------------------------------------

TEST_CASE("mp-pushing: the cube by hand") {
  // Edge points are the midpoints. The three around (1,1,1) span the plane x + y + z = 2, which the vertex
  // (1-s)(1,1,1) reaches at s = 1/3: the extreme position. With tau the vertex lands at (1 - tau/3)(1,1,1).
  for (double tau : {0.5, 0.2, 0.9}) {
    CAPTURE(tau);
    const Mesh out = mp_pushing(test::cube(), p_params(tau));
    check_counts(out, 20, 48, 30);
    const Mesh cube = test::cube();
    for (VertexId v : cube.vertices()) {
      const glm::dvec3 expected = (1 - tau / 3) * cube.position(v);
      CHECK(glm::length(out.position(v) - expected) < 1e-15);
    }
    for (EdgeId e : cube.edges()) {
      const glm::dvec3 mid = 0.5 * (cube.position(cube.from(e)) + cube.position(cube.to(e)));
      CHECK(out.position(VertexId(8 + e.index())) == mid);
    }
    check_pushing_step(cube, p_params(tau));
  }
  // Off-centre: the vertices still move along the lines to the given centre.
  MpPushingParams p = p_params(0.5);
  p.center = glm::dvec3(0.3, -0.2, 0.5);
  check_pushing_step(test::cube(), p);
}

TEST_CASE("mp-pushing: the icosahedron by hand, and other polyhedra") {
  // The five midpoints around a vertex v lie on a plane perpendicular to v at height (|v|^2 - 1)/|v| (each
  // neighbour w has v.w = |v|^2 - 2, as |v - w| = 2). (1-s) v reaches it at s = 1/|v|^2 = 1/(1 + phi^2).
  const Mesh ico = icosahedron();
  const Mesh out = mp_pushing(ico, p_params(0.5));
  const double s = 1.0 / (1.0 + phi * phi);
  for (VertexId v : ico.vertices()) {
    CHECK(glm::length(out.position(v) - (1 - 0.5 * s) * ico.position(v)) < 1e-14);
  }
  check_pushing_step(ico, p_params(0.5));
  for (double tau : {0.2, 0.8}) {
    check_pushing_step(ico, p_params(tau, 2.0));
    check_pushing_step(test::dodecahedron(), p_params(tau));
    check_pushing_step(cuboid(), p_params(tau, 0.5));
    check_pushing_step(random_polyhedron(13), p_params(tau));
    check_pushing_step(test::tetrahedron(), p_params(tau));
  }
  // The ratio is measured from side 0: the point on edge e divides from(e) .. to(e) as ratio : 1.
  const Mesh r = mp_pushing(ico, p_params(0.5, 3.0));
  for (EdgeId e : ico.edges()) {
    const glm::dvec3 m = r.position(VertexId(12 + e.index()));
    const double a = glm::length(m - ico.position(ico.from(e))), b = glm::length(ico.position(ico.to(e)) - m);
    CHECK(a / b == doctest::Approx(3.0));
  }
}

TEST_CASE("mp-pushing: the extreme position is where the 1-ring turns flat") {
  // At tau -> 1 the vertex reaches its extreme: two of its triangles become coplanar. Check it on a random
  // polyhedron: at s the vertex lies on a plane through three consecutive edge points, before it no ring is
  // flat.
  const Mesh m = random_polyhedron(17);
  const glm::dvec3 centre = vertex_centroid(m);
  for (VertexId v : m.vertices()) {
    std::vector<glm::dvec3> ring;
    for (CornerId c : m.corners(v)) {
      const EdgeId e = m.edge(c);
      ring.push_back(0.5 * (m.position(m.from(e)) + m.position(m.to(e))));
    }
    const glm::dvec3 p = m.position(v);
    const double s = pushing_extreme_fraction(p, ring, centre);
    CHECK(s > 0.0);
    CHECK(s <= 1.0);
    // Flatness of the ring at edge i for the apex x: signed volume of (m_i - x, m_(i-1) - x, m_(i+1) - x).
    auto volumes = [&](const glm::dvec3& x) {
      std::vector<double> vol;
      for (std::size_t i = 0; i < ring.size(); ++i) {
        const glm::dvec3 a = ring[(i + ring.size() - 1) % ring.size()], b = ring[i],
                         c = ring[(i + 1) % ring.size()];
        vol.push_back(glm::dot(b - x, glm::cross(a - x, c - x)));
      }
      return vol;
    };
    const auto start = volumes(p);
    const auto at = volumes(p + s * (centre - p));
    const auto before = volumes(p + 0.999 * s * (centre - p));
    double smallest = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < ring.size(); ++i) {
      smallest = std::min(smallest, std::abs(at[i]) / std::abs(start[i]));
      CHECK(before[i] * start[i] > 0.0);  // no edge has flipped before the extreme
    }
    if (s < 1.0) CHECK(smallest < 1e-9);  // at the extreme one edge is flat
  }
}

TEST_CASE("mp-pushing: the maximum face angle never grows (theorem 4.2)") {
  // The tetrahedron starts at 180 degrees (antipodal points inside two arcs of each face's 1-ring), so its
  // first step cannot grow; later steps compare measures attained inside arcs.
  check_never_grows(
      {test::cube(), test::tetrahedron(), icosahedron(), cuboid(), random_polyhedron(23)},
      {p_params(0.5), p_params(0.2, 2.0), p_params(0.8, 0.5), random_params<MpPushingParams>(5)},
      [](const Mesh& m, const MpPushingParams& p) { return mp_pushing(m, p); }, max_face_angle);
}

TEST_CASE("mp-pushing: random per-edge ratios and per-vertex taus, reproducible from the seed") {
  MpPushingParams p;
  p.random.enabled = true;
  p.random.seed = 77;
  const Mesh in = random_polyhedron(2);
  const Mesh a = mp_pushing(in, p);
  CHECK(a == mp_pushing(in, p));
  p.random.seed = 78;
  CHECK_FALSE(a == mp_pushing(in, p));
  check_pushing_step(in, p);
  // Edge points divide their edges in fractions inside [0.25, 0.75] (the default epsilon).
  for (EdgeId e : in.edges()) {
    const glm::dvec3 m = a.position(VertexId(std::uint32_t(in.num_vertices()) + e.index()));
    const double t = glm::length(m - in.position(in.from(e))) /
                     glm::length(in.position(in.to(e)) - in.position(in.from(e)));
    CHECK(t >= 0.25 - 1e-12);
    CHECK(t <= 0.75 + 1e-12);
  }
}

// ---- MHP --------------------------------------------------------------------------------------------------

TEST_CASE("mhp: patterns expand to the right steps") {
  CHECK(expand_mhp_pattern("H4P4") == "HHHHPPPP");
  CHECK(expand_mhp_pattern("P4H4") == "PPPPHHHH");
  CHECK(expand_mhp_pattern("(HP)4") == "HPHPHPHP");
  CHECK(expand_mhp_pattern("(H2P2)2") == "HHPPHHPP");
  CHECK(expand_mhp_pattern("(P2H2)2") == "PPHHPPHH");
  CHECK(expand_mhp_pattern("HP") == "HP");
  CHECK(expand_mhp_pattern("h2p") == "HHP");
  CHECK(expand_mhp_pattern("((HP)2P)2") == "HPHPPHPHPP");
  CHECK(expand_mhp_pattern("H10").size() == 10);
  CHECK(expand_mhp_pattern("(H)64").size() == 64);
}

TEST_CASE("mhp: a malformed pattern names the character where parsing fails") {
  auto failure = [](const char* pattern) {
    try {
      expand_mhp_pattern(pattern);
    } catch (const InvalidArgument& e) {
      return std::string(e.what());
    }
    FAIL("no error for pattern '" << pattern << "'");
    return std::string();
  };
  CHECK(failure("").find("at character 1") != std::string::npos);
  CHECK(failure("H4Q").find("at character 3 (H4^Q)") != std::string::npos);
  CHECK(failure("H4Q").find("not 'Q'") != std::string::npos);
  CHECK(failure("(HP").find("at character 4") != std::string::npos);
  CHECK(failure("(HP").find("expected ')'") != std::string::npos);
  CHECK(failure("HP)").find("at character 3") != std::string::npos);
  CHECK(failure("HP)").find("unmatched ')'") != std::string::npos);
  CHECK(failure("H0").find("at character 2") != std::string::npos);
  CHECK(failure("()").find("at character 2") != std::string::npos);
  CHECK(failure("4H").find("at character 1") != std::string::npos);
  CHECK(failure("H P").find("at character 2") != std::string::npos);
  CHECK(failure("H65").find("more than 64 steps") != std::string::npos);
  CHECK(failure("(H9)9").find("more than 64 steps") != std::string::npos);
  CHECK(failure("(H)99999999999999999999").find("more than 64 steps") != std::string::npos);
}

TEST_CASE("mhp: counts at every step, valid convex results, equal to the steps run one by one") {
  for (const char* pattern : {"H2P2", "P2H2", "(HP)2", "(PH)2"}) {
    CAPTURE(pattern);
    MhpParams params;
    params.pattern = pattern;
    params.honeycomb.tau = 0.3;
    params.pushing.tau = 0.7;
    const Mesh start = test::cube();
    const glm::dvec3 centre = vertex_centroid(start);
    std::size_t steps = 0;
    Mesh expected = start;
    std::size_t V = start.num_vertices(), E = start.num_edges(), F = start.num_faces();
    const Mesh result = mhp(start, params, [&](std::size_t i, char kind, const Mesh& m) {
      CHECK(i == steps++);
      CHECK(kind == expand_mhp_pattern(pattern)[i]);
      if (kind == 'H') {
        V += 2 * E, F += E;
        MpHoneycombParams h = params.honeycomb;
        h.center = centre;
        expected = mp_honeycomb(expected, h);
      } else {
        V += E, F += 2 * E;
        MpPushingParams p = params.pushing;
        p.center = centre;
        expected = mp_pushing(expected, p);
      }
      E *= 4;
      check_counts(m, V, E, F);
      CHECK(validate(m).valid());
      CHECK(is_convex_polyhedron(m, centre));
      CHECK(m == expected);
    });
    CHECK(steps == 4);
    CHECK(result == expected);
  }
}

TEST_CASE(
    "mhp: the maximum face angle shrinks and the vertex angle stays bounded (theorem 5.4, corollary 5.3)") {
  // (HP)2 from the icosahedron: H keeps vertex angles from growing, P keeps face angles from growing.
  MhpParams params;
  params.pattern = "(HP)2";
  const Mesh start = icosahedron();
  double face = max_face_angle(start), vertex = max_vertex_angle(start);
  const double first_face = face;
  mhp(start, params, [&](std::size_t, char kind, const Mesh& m) {
    const double f = max_face_angle(m), v = max_vertex_angle(m);
    if (kind == 'H') CHECK(v <= vertex + 1e-12);
    if (kind == 'P') CHECK(f <= face + 1e-12);
    CHECK(v < pi);
    face = f, vertex = v;
  });
  CHECK(face < first_face);
}

// ---- errors and the registry ------------------------------------------------------------------------------

TEST_CASE("meng-prautzsch: bad input and bad parameters get their errors") {
  const Mesh cube = test::cube();
  for (double tau : {0.0, 1.0, -0.5, 1.5, std::nan("")}) {
    CAPTURE(tau);
    CHECK_THROWS_WITH_AS(mp_honeycomb(cube, h_params(tau)), doctest::Contains("parameter tau"),
                         InvalidArgument);
    CHECK_THROWS_WITH_AS(mp_pushing(cube, p_params(tau)), doctest::Contains("parameter tau"),
                         InvalidArgument);
  }
  for (double ratio : {0.0, -1.0, std::numeric_limits<double>::infinity()}) {
    CHECK_THROWS_WITH_AS(mp_honeycomb(cube, h_params(0.5, ratio)), doctest::Contains("parameter ratio"),
                         InvalidArgument);
    CHECK_THROWS_WITH_AS(mp_pushing(cube, p_params(0.5, ratio)), doctest::Contains("parameter ratio"),
                         InvalidArgument);
  }
  // A rejected value is shown as it is, not rounded to an allowed one.
  CHECK_THROWS_WITH_AS(mp_honeycomb(cube, h_params(1.000000001)),
                       "mp-honeycomb: parameter tau must be in (0, 1), not 1.000000001", InvalidArgument);
  MpPushingParams off_centre;
  off_centre.center = glm::dvec3(0.1, 0, 5);
  CHECK_THROWS_WITH_AS(mp_pushing(cube, off_centre), doctest::Contains("the centre (0.1, 0, 5) is not"),
                       InvalidArgument);
  MpHoneycombParams eps;
  eps.random.enabled = true;
  eps.random.epsilon = 0.6;
  CHECK_THROWS_WITH_AS(mp_honeycomb(cube, eps), doctest::Contains("epsilon"), InvalidArgument);
  // Non-convex, coplanar neighbours, centre outside, open: each scheme refuses with the check's message.
  MpHoneycombParams outside;
  outside.center = glm::dvec3(0, 0, 3);
  CHECK_THROWS_WITH_AS(mp_honeycomb(cube, outside), doctest::Contains("f1"), InvalidArgument);
  MpPushingParams outside_p;
  outside_p.center = glm::dvec3(0, 0, 3);
  CHECK_THROWS_WITH_AS(mp_pushing(cube, outside_p), doctest::Contains("f1"), InvalidArgument);
  CHECK_THROWS_WITH_AS(mp_honeycomb(dented_octahedron()), doctest::Contains("concave"), InvalidArgument);
  CHECK_THROWS_WITH_AS(mp_pushing(test::mixed_polyhedron()), doctest::Contains("not a strictly convex"),
                       InvalidArgument);
  CHECK_THROWS_AS(mp_pushing(build_mesh(test::grid_soup(2, 2))), TopologyError);
  MhpParams bad;
  bad.pattern = "H(P";
  CHECK_THROWS_WITH_AS(mhp(cube, bad), doctest::Contains("at character 4"), InvalidArgument);
  MhpParams concave;
  CHECK_THROWS_WITH_AS(mhp(dented_octahedron(), concave), doctest::Contains("mhp step 0 (H)"),
                       InvalidArgument);
}

TEST_CASE("meng-prautzsch: registry entries record every parameter and check them") {
  // Each parameter with its declared type: a boolean, an integer seed, the centre's keyword as text.
  const Params h = resolve_scheme_params("mp-honeycomb", {});
  CHECK(h == Params{{"tau", 0.5},
                    {"ratio", 1.0},
                    {"center", "centroid"},
                    {"random", false},
                    {"epsilon", 0.25},
                    {"seed", 1}});
  const Params p = resolve_scheme_params("mp-pushing", {{"tau", 0.3}});
  CHECK(p.number("tau") == 0.3);
  CHECK(p.size() == 6);
  const Params m = resolve_scheme_params("mhp", {{"pattern", std::string("H4P4")}});
  CHECK(m.text("pattern") == "H4P4");
  for (const char* name : {"tau_h", "ratio_h", "tau_p", "ratio_p", "center", "random", "epsilon", "seed"}) {
    CHECK(m.count(name) == 1);
  }
  // The values old logs hold (a centre as text, random and seed as doubles) resolve to the typed ones.
  const Params old = resolve_scheme_params(
      "mp-pushing", {{"center", "0.01,0,0"}, {"random", 1.0}, {"seed", 7.0}, {"epsilon", 0.25}});
  CHECK(old.point("center") == glm::dvec3(0.01, 0, 0));
  CHECK(old.boolean("random"));
  CHECK(old.integer("seed") == 7);
  // A centre given as text "x,y,z" is the centre.
  MpHoneycombParams direct;
  direct.center = glm::dvec3(0.25, 0, -0.5);
  CHECK(apply_scheme(test::cube(), "mp-honeycomb",
                     resolve_scheme_params("mp-honeycomb", {{"center", std::string("0.25,0,-0.5")}})) ==
        mp_honeycomb(test::cube(), direct));
  MhpParams twice;
  twice.pattern = "(PH)1";
  twice.pushing.tau = 0.25;
  CHECK(apply_scheme(test::tetrahedron(), "mhp",
                     resolve_scheme_params("mhp", {{"pattern", std::string("(PH)1")}, {"tau_p", 0.25}})) ==
        mhp(test::tetrahedron(), twice));
  // Bad values name the parameter.
  auto bad = [](const char* scheme, Params given, const char* needle) {
    CAPTURE(scheme);
    CAPTURE(needle);
    CHECK_THROWS_WITH_AS(resolve_scheme_params(scheme, given), doctest::Contains(needle), ParameterError);
  };
  bad("mp-honeycomb", {{"center", std::string("1,2")}}, "center");
  bad("mp-honeycomb", {{"center", 3.0}}, "center");
  bad("mp-honeycomb", {{"center", std::string("1,2,3,4")}}, "center");
  bad("mp-pushing", {{"random", 2.0}}, "random");
  bad("mp-pushing", {{"seed", -1.0}}, "seed");
  bad("mp-pushing", {{"seed", 1.5}}, "seed");
  bad("mp-pushing", {{"tau", 1.0}}, "tau");
  bad("mp-honeycomb", {{"tau", std::string("half")}}, "tau");
  bad("mhp", {{"pattern", 4.0}}, "pattern");
  bad("mhp", {{"pattern", std::string("HQ")}}, "at character 2");
  bad("mhp", {{"tau_h", 0.0}}, "tau_h");
  bad("mhp", {{"tau_p", 2.0}}, "tau_p");
  bad("mhp", {{"ratio_p", -1.0}}, "ratio_p");
  bad("mhp", {{"epsilon", 0.0}, {"random", 1.0}}, "epsilon");
  bad("mhp", {{"tau", 0.5}}, "unknown parameter 'tau'");
}

TEST_CASE("mp-pushing: a vertex whose ring never flattens before the centre stops short of the centre") {
  // Tetrahedron vertex (1,1,1), centre c = (0.6,0.6,0.6) (inside: on the inner side of x + y - z = 1 and the
  // like). The midpoints around the vertex span x + y + z = 1, which lies beyond c: the extreme position is
  // capped at the centre (s = 1), so the vertex lands at (1,1,1) + tau (c - (1,1,1)) = (0.8,0.8,0.8).
  MpPushingParams p = p_params(0.5);
  p.center = glm::dvec3(0.6);
  const Mesh in = test::tetrahedron();
  const Mesh out = mp_pushing(in, p);
  CHECK(glm::length(out.position(VertexId(0)) - glm::dvec3(0.8)) < 1e-15);
  check_pushing_step(in, p);
}

TEST_CASE("meng-prautzsch: removed elements in the input do not matter") {
  Mesh m = test::cube();
  m.delete_vertex(m.create_vertex({5, 5, 5}));  // a tombstone
  CHECK(mp_honeycomb(m) == mp_honeycomb(test::cube()));
  CHECK(mp_pushing(m) == mp_pushing(test::cube()));
}

TEST_CASE("mhp: the paper's patterns run their eight steps with the closed-form counts") {
  // Section 6: H4P4, P4H4, (HP)4, (H2P2)2 from the tetrahedron (V, E, F = 4, 6, 4). H: V + 2E, 4E, F + E;
  // P: V + E, 4E, F + 2E. Every intermediate result is checked convex by the next step; the small ones are
  // validated here too.
  for (const char* pattern : {"H4P4", "P4H4", "(HP)4", "(H2P2)2"}) {
    CAPTURE(pattern);
    MhpParams params;
    params.pattern = pattern;
    std::size_t V = 4, E = 6, F = 4, steps = 0;
    std::string kinds;
    const Mesh last = mhp(test::tetrahedron(), params, [&](std::size_t, char kind, const Mesh& m) {
      ++steps;
      kinds += kind;
      if (kind == 'H') {
        V += 2 * E, F += E;
      } else {
        V += E, F += 2 * E;
      }
      E *= 4;
      check_counts(m, V, E, F);
      if (E < 30000) CHECK(validate(m).valid());
    });
    CHECK(steps == 8);
    CHECK(kinds == expand_mhp_pattern(pattern));
    CHECK(last.num_edges() == 6 * 65536);
  }
}

TEST_CASE("meng-prautzsch: output handles follow the documented order") {
  const Mesh in = random_polyhedron(29);
  const std::uint32_t V = std::uint32_t(in.num_vertices()), F = std::uint32_t(in.num_faces());
  const Mesh h = mp_honeycomb(in);
  for (FaceId f : in.faces()) {
    CornerId out = h.first_corner(f);
    for (CornerId c : in.corners(f)) {
      CHECK(h.vertex(out) == VertexId(V + c.index()));  // the f-face vertex of input corner c
      out = h.next(out);
    }
  }
  for (EdgeId e : in.edges()) {
    const CornerId c0 = in.corner(e, 0), c1 = in.corner(e, 1);
    std::vector<VertexId> ring;
    for (CornerId c : h.corners(FaceId(F + e.index()))) ring.push_back(h.vertex(c));
    const std::vector<VertexId> expected = {
        in.from(e), VertexId(V + in.next(c1).index()), VertexId(V + c1.index()),
        in.to(e),   VertexId(V + in.next(c0).index()), VertexId(V + c0.index())};
    CHECK(ring == expected);
  }
  const Mesh p = mp_pushing(in);
  for (CornerId c : in.corners()) {
    const CornerId first = p.first_corner(FaceId(F + c.index()));
    CHECK(p.vertex(first) == in.vertex(c));
    CHECK(p.vertex(p.next(first)) == VertexId(V + in.edge(c).index()));
    CHECK(p.vertex(p.prev(first)) == VertexId(V + in.edge(in.prev(c)).index()));
  }
  for (FaceId f : in.faces()) {
    CornerId out = p.first_corner(f);
    for (CornerId c : in.corners(f)) {
      CHECK(p.vertex(out) == VertexId(V + in.edge(c).index()));
      out = p.next(out);
    }
  }
}
