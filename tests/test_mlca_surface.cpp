// MLCA on DLFL quad surfaces (dlfl/schemes/mlca_polygons.h): equality with Catmull-Clark on 4-valent quad
// meshes, the composite weights of formula (2) re-derived from the combinatorics, counts, the split to quads,
// open boundaries as crease curves, point spheres, affine invariance.

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <map>
#include <utility>
#include <vector>

#include <dlfl/build_mesh.h>
#include <dlfl/geometry.h>
#include <dlfl/schemes/catmull_clark.h>
#include <dlfl/schemes/mlca_polygons.h>
#include <dlfl/schemes/scheme_registry.h>
#include <dlfl/validate.h>
#include "scheme_meshes.h"
#include "test_helpers.h"
#include "test_meshes.h"

using namespace dlfl;
using test::require_valid;

namespace {

double max_distance(const Mesh& a, const Mesh& b) {
  REQUIRE(a.num_vertices() == b.num_vertices());
  double d = 0;
  for (VertexId v : a.vertices()) d = std::max(d, glm::length(a.position(v) - b.position(v)));
  return d;
}

// An n-gonal prism: two n-gons and n side quads (closed, genus 0).
PolygonSoup prism_soup(int n) {
  PolygonSoup s;
  for (int z = 0; z < 2; ++z) {
    for (int i = 0; i < n; ++i) {
      const double u = 2 * std::numbers::pi * i / n;
      s.positions.push_back({std::cos(u), std::sin(u), z == 0 ? -1.0 : 1.0});
    }
  }
  test::add_prism_faces(s, n);
  return s;
}

// Formula (2) for d = 2 at vertex v of a quad mesh, derived from the quads around v alone: the weight of u
// is 3^(2 - dim[u,v]) val[u,v] / (16 val[v]), with dim 0 for u = v, 1 for a vertex sharing an edge of a quad
// with v, 2 for the opposite vertex of a quad.
std::map<std::uint32_t, double> formula_2_weights(const Mesh& m, VertexId v) {
  std::map<std::uint32_t, int> val_uv, dim_uv;
  int val_v = 0;
  for (FaceId f : m.faces()) {
    std::vector<std::uint32_t> q;
    for (CornerId c : m.corners(f)) q.push_back(m.vertex(c).index());
    REQUIRE(q.size() == 4);
    const auto at = std::find(q.begin(), q.end(), v.index());
    if (at == q.end()) continue;
    ++val_v;
    const int i = int(at - q.begin());
    for (int k = 0; k < 4; ++k) {
      const int cyclic = std::min((k - i + 4) % 4, (i - k + 4) % 4);  // 0, 1 (edge) or 2 (diagonal)
      ++val_uv[q[k]];
      dim_uv[q[k]] = cyclic;
    }
  }
  std::map<std::uint32_t, double> w;
  for (auto [u, val] : val_uv) w[u] = std::pow(3.0, 2 - dim_uv[u]) * val / (16.0 * val_v);
  return w;
}

// The weight of every vertex u in the new position of v, measured by giving u the x coordinate 1 and every
// other vertex 0 (the step is linear in positions, coordinate by coordinate).
void check_weights(const Mesh& quads, VertexId v, std::size_t valence) {
  REQUIRE(quads.valence(v) == valence);
  const auto expected = formula_2_weights(quads, v);
  double sum = 0;
  for (auto [u, w] : expected) sum += w;
  CHECK(sum == doctest::Approx(1.0).epsilon(1e-14));                            // formula (4)
  CHECK(expected.at(v.index()) == doctest::Approx(9.0 / 16.0).epsilon(1e-15));  // (3/4)^d
  for (VertexId u : quads.vertices()) {
    Mesh probe = quads;
    for (VertexId x : probe.vertices()) {
      glm::dvec3 p = probe.position(x);
      p.x = x == u ? 1.0 : 0.0;
      probe.set_position(x, p);
    }
    const Mesh out = mlca(probe);
    const auto it = expected.find(u.index());
    const double want = it == expected.end() ? 0.0 : it->second;
    CHECK(out.position(v).x == doctest::Approx(want).epsilon(1e-14));
  }
}

PolygonSoup soup_of(const Mesh& m) { return to_polygons(m); }

std::vector<glm::dvec3> sorted_positions(const Mesh& m) {
  std::vector<glm::dvec3> p;
  for (VertexId v : m.vertices()) p.push_back(m.position(v));
  std::sort(p.begin(), p.end(), [](const glm::dvec3& a, const glm::dvec3& b) {
    return a.x != b.x ? a.x < b.x : a.y != b.y ? a.y < b.y : a.z < b.z;
  });
  return p;
}

}  // namespace

TEST_CASE("mlca surface: equals Catmull-Clark on a closed quad mesh with all vertices 4-valent") {
  for (auto [n, m] : {std::pair{8, 6}, std::pair{5, 9}}) {
    const Mesh torus = build_mesh(test::torus_soup(n, m));
    for (VertexId v : torus.vertices()) REQUIRE(torus.valence(v) == 4);
    const Mesh a = mlca(torus), b = catmull_clark(torus);
    CHECK(max_distance(a, b) < 1e-12);
    // Two steps: the result is again a 4-valent quad torus.
    CHECK(max_distance(mlca(a), catmull_clark(b)) < 1e-12);
  }
}

TEST_CASE("mlca surface: differs from Catmull-Clark at an extraordinary vertex (the cube)") {
  // Valence 3: MLCA gives 9/16 to the vertex; Catmull-Clark (Q + 2R)/3 gives it (4/9)(3/4)... they differ,
  // so the equality above is not vacuous.
  const Mesh cube = test::cube();
  CHECK(max_distance(mlca(cube), catmull_clark(cube)) > 1e-3);
}

TEST_CASE("mlca surface: the weights at a vertex of valence n are formula (2)") {
  // The cube: every vertex has valence 3, neighbours along 3 edges, 3 diagonal vertices.
  check_weights(test::cube(), VertexId(0), 3);
  // Quads around a vertex of valence 5 and 6: the split prism, whose top face's centroid has valence n.
  for (int n : {5, 6}) {
    const Mesh quads = split_to_quads(build_mesh(prism_soup(n)));
    // split numbering: vertices, edge midpoints, then face centroids; face 1 of the prism is its top.
    const Mesh prism = build_mesh(prism_soup(n));
    const VertexId top_centre(std::uint32_t(prism.num_vertices() + prism.num_edges() + 1));
    check_weights(quads, top_centre, std::size_t(n));
  }
}

TEST_CASE("mlca surface: on the cube, the hand computation") {
  // Vertex (-1,-1,-1): 9/16 of itself, 3/(8*3) = 1/8 of each of its three neighbours (one coordinate +1),
  // 1/48 of each of the three diagonal vertices (two coordinates +1). x: 9/16(-1) + 1/8(1 - 1 - 1) + 1/48(1 +
  // 1 - 1) = -9/16 - 1/8 + 1/48 = -2/3.
  const Mesh out = mlca(test::cube());
  const glm::dvec3 p = out.position(VertexId(0));
  for (double c : {p.x, p.y, p.z}) CHECK(c == doctest::Approx(-2.0 / 3.0).epsilon(1e-15));
  // Edge points: 3/8 of each end, 1/16 of the other four: edge (-1,-1,-1)-(1,-1,-1) has ends averaging to
  // (0,-1,-1) and the others (+-1, 1, -1), (+-1, -1, 1): (0, -3/4 + 1/4 (0), ...) = (0, -3/4, -3/4).
  // Face points stay at the face centres.
  const Mesh cube = test::cube();
  for (EdgeId e : cube.edges()) {
    const glm::dvec3 a = cube.position(cube.from(e)), b = cube.position(cube.to(e));
    const glm::dvec3 mid = 0.5 * (a + b);
    const glm::dvec3 q = out.position(VertexId(std::uint32_t(8 + e.index())));
    for (int k = 0; k < 3; ++k) {
      // Along the edge the coordinate is 0; across it, 3/4 of +-1 (two quads, the far side pulls 1/4 back).
      CHECK(q[k] == doctest::Approx(mid[k] == 0.0 ? 0.0 : 0.75 * mid[k]).epsilon(1e-15));
    }
  }
  for (FaceId f : cube.faces()) {
    CHECK(glm::length(out.position(VertexId(std::uint32_t(8 + 12 + f.index()))) - face_centroid(cube, f)) <
          1e-15);
  }
}

TEST_CASE("mlca surface: counts, valid result and kept genus") {
  for (const Mesh& quads :
       {test::cube(), build_mesh(test::torus_soup(6, 4)), build_mesh(test::genus_soup(3))}) {
    const Mesh out = mlca(quads);
    const auto before = validate(quads), after = validate(out);
    REQUIRE(after.valid());
    CHECK(out.num_faces() == 4 * quads.num_faces());
    CHECK(out.num_vertices() == quads.num_vertices() + quads.num_edges() + quads.num_faces());
    CHECK(out.num_edges() == 2 * quads.num_edges() + 4 * quads.num_faces());
    REQUIRE(after.components.size() == before.components.size());
    for (std::size_t i = 0; i < before.components.size(); ++i) {
      CHECK(after.components[i].genus == before.components[i].genus);
    }
  }
  // Triangles: split into 3F quads (V1 = V + E + F, E1 = 2E + 3F), then one step.
  const Mesh tet = test::tetrahedron();
  const Mesh out = mlca(tet);
  require_valid(out);
  const std::size_t v1 = 4 + 6 + 4, e1 = 2 * 6 + 3 * 4, f1 = 3 * 4;
  CHECK(out.num_faces() == 4 * f1);
  CHECK(out.num_vertices() == v1 + e1 + f1);
  CHECK(out.num_edges() == 2 * e1 + 4 * f1);
  for (FaceId f : out.faces()) CHECK(out.size(f) == 4);
  // Mixed faces (3 to 7 sides).
  const Mesh mixed = test::mixed_polyhedron();
  const Mesh mixed_out = mlca(mixed);
  require_valid(mixed_out);
  CHECK(mixed_out.num_faces() == 4 * mixed.num_corners());
}

TEST_CASE("mlca surface: a triangle mesh is split by section 3.3, then stepped") {
  // The split built by hand here: each triangle (a, b, c) into quads (a, ab, centre, ca) and so on.
  const PolygonSoup tri = test::tetrahedron_soup();
  PolygonSoup quads;
  quads.positions = tri.positions;
  std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> midpoint;
  auto mid = [&](std::uint32_t a, std::uint32_t b) {
    const auto key = std::minmax(a, b);
    auto [it, fresh] = midpoint.try_emplace({key.first, key.second}, std::uint32_t(quads.positions.size()));
    if (fresh) quads.positions.push_back(0.5 * (tri.positions[a] + tri.positions[b]));
    return it->second;
  };
  for (std::size_t f = 0; f < tri.num_faces(); ++f) {
    const auto face = tri.face(f);
    const auto centre = std::uint32_t(quads.positions.size());
    quads.positions.push_back((tri.positions[face[0]] + tri.positions[face[1]] + tri.positions[face[2]]) /
                              3.0);
    for (int i = 0; i < 3; ++i) {
      const std::uint32_t a = face[i], next = face[(i + 1) % 3], prev = face[(i + 2) % 3];
      quads.add_face({a, mid(a, next), centre, mid(prev, a)});
    }
  }
  const auto expected = sorted_positions(mlca(build_mesh(quads)));
  const auto got = sorted_positions(mlca(test::tetrahedron()));
  REQUIRE(got.size() == expected.size());
  for (std::size_t i = 0; i < got.size(); ++i) CHECK(glm::length(got[i] - expected[i]) < 1e-14);
}

TEST_CASE("mlca surface: affine invariance") {
  const glm::dmat3 a(1.5, 0.2, -0.3, 0.1, 0.8, 0.4, -0.2, 0.3, 1.1);
  const glm::dvec3 t(0.7, -1.2, 2.5);
  for (const Mesh& m :
       {test::mixed_polyhedron(), build_mesh(test::genus_soup(2)), build_mesh(test::grid_soup(3, 2))}) {
    Mesh moved = m;
    for (VertexId v : moved.vertices()) moved.set_position(v, a * m.position(v) + t);
    const Mesh out = mlca(m), out_moved = mlca(moved);
    for (VertexId v : out.vertices()) {
      CHECK(glm::length(out_moved.position(v) - (a * out.position(v) + t)) < 1e-12);
    }
  }
}

TEST_CASE("mlca surface: open boundaries are cubic B-spline crease curves") {
  // A 4 x 4 grid in the plane z = 0, with z = 1 at one vertex: the new z values are that vertex's weights.
  PolygonSoup grid = test::grid_soup(4, 4);
  auto id = [](int i, int j) { return std::uint32_t(j * 5 + i); };
  grid.positions[id(2, 0)].z = 1.0;  // on the boundary, not a corner
  const Mesh m = build_mesh(grid);
  const Mesh out = mlca(m);
  require_valid(out);
  CHECK(out.num_faces() == 4 * 16 + 16);  // the 16-gon hole is split too: 16 quads that stay holes
  // Boundary vertex: 3/4 itself, 1/8 of each boundary neighbour; the interior is not involved.
  CHECK(out.position(VertexId(id(2, 0))).z == doctest::Approx(0.75));
  CHECK(out.position(VertexId(id(1, 0))).z == doctest::Approx(0.125));
  CHECK(out.position(VertexId(id(3, 0))).z == doctest::Approx(0.125));
  CHECK(out.position(VertexId(id(4, 0))).z == 0.0);
  CHECK(out.position(VertexId(id(0, 0))).z == 0.0);
  // Interior vertex of valence 4: formula (2), 3/(8*4) for an edge neighbour, 1/64 for a diagonal one.
  CHECK(out.position(VertexId(id(2, 1))).z == doctest::Approx(3.0 / 32.0));
  CHECK(out.position(VertexId(id(1, 1))).z == doctest::Approx(1.0 / 64.0));
  CHECK(out.position(VertexId(id(2, 2))).z == 0.0);
  // A boundary corner: 3/4 of itself and 1/8 of its two boundary neighbours (x).
  CHECK(out.position(VertexId(id(0, 0))).x == doctest::Approx(0.125));
  CHECK(out.position(VertexId(id(0, 0))).y == doctest::Approx(0.125));
  // Boundary edge points stay at the midpoints.
  for (EdgeId e : m.edges()) {
    if (m.is_hole(m.face(e, 0)) == m.is_hole(m.face(e, 1))) continue;
    const glm::dvec3 mid = 0.5 * (m.position(m.from(e)) + m.position(m.to(e)));
    CHECK(glm::length(out.position(VertexId(std::uint32_t(m.num_vertices() + e.index()))) - mid) < 1e-15);
  }
  // The output writes as the same open surface: 4 x 4 quads become 8 x 8, one boundary loop.
  const PolygonSoup written = soup_of(out);
  CHECK(written.num_faces() == 64);
  const auto report = validate(mlca(out));
  REQUIRE(report.valid());
}

TEST_CASE("mlca surface: point spheres are 0-cells, kept in place") {
  Mesh m = test::cube();
  const VertexId lone = m.create_vertex({5.0, 6.0, 7.0});
  REQUIRE(m.is_point_sphere(lone));
  const Mesh out = mlca(m);
  require_valid(out);
  CHECK(out.num_vertices() == 8 + 12 + 6 + 1);
  const VertexId last(std::uint32_t(out.vertex_capacity() - 1));
  CHECK(out.is_point_sphere(last));
  CHECK(out.position(last) == glm::dvec3(5.0, 6.0, 7.0));
  // The rest is as without the point sphere.
  const Mesh plain = mlca(test::cube());
  for (VertexId v : plain.vertices()) CHECK(out.position(v) == plain.position(v));
  // Only point spheres: copied.
  Mesh lonely;
  lonely.create_vertex({1.0, 2.0, 3.0});
  const Mesh lonely_out = mlca(lonely);
  CHECK(lonely_out.num_vertices() == 1);
  CHECK(lonely_out.num_faces() == 1);
  CHECK_THROWS_AS(split_to_quads(lonely), TopologyError);
}

TEST_CASE("mlca surface: registered as -s mlca") {
  const Mesh m = test::mixed_polyhedron();
  const Mesh a = apply_scheme(m, "mlca", resolve_scheme_params("mlca", {}));
  const Mesh b = mlca(m);
  CHECK(max_distance(a, b) == 0.0);
  CHECK_THROWS_AS(resolve_scheme_params("mlca", {{"t", 0.5}}), InvalidArgument);
}

TEST_CASE("mlca surface: the reduced subdivision matrix (6) with a = 1/(16n) has eigenvalues 1, 1/4, 1/16") {
  for (int n : {3, 5, 7}) {
    const Mesh prism = build_mesh(prism_soup(n));
    const Mesh quads = split_to_quads(prism);
    const VertexId v(std::uint32_t(prism.num_vertices() + prism.num_edges() + 1));  // top centre, valence n
    const auto nv = std::uint32_t(quads.num_vertices()), ne = std::uint32_t(quads.num_edges());
    const CornerId c0 = quads.corner(v);
    // Rotationally symmetric data: x = s[0] at v, s[1] at the n edge neighbours, s[2] at the n diagonal ones.
    // The new v, the edge point of (v, e) and the face point of a quad at v depend on these alone.
    double m[3][3];
    for (int j = 0; j < 3; ++j) {
      Mesh probe = quads;
      for (VertexId x : probe.vertices())
        probe.set_position(x, {0.0, probe.position(x).y, probe.position(x).z});
      auto set_x = [&](VertexId x, double value) {
        probe.set_position(x, {value, probe.position(x).y, probe.position(x).z});
      };
      set_x(v, j == 0 ? 1.0 : 0.0);
      for (CornerId c : quads.corners(v)) {
        set_x(quads.vertex(quads.next(c)), j == 1 ? 1.0 : 0.0);
        set_x(quads.vertex(quads.next(quads.next(c))), j == 2 ? 1.0 : 0.0);
      }
      const Mesh out = mlca(probe);
      m[0][j] = out.position(v).x;
      m[1][j] = out.position(VertexId(nv + quads.edge(c0).index())).x;
      m[2][j] = out.position(VertexId(nv + ne + quads.face(c0).index())).x;
    }
    const double a = 1.0 / (16.0 * n);
    const double expected[3][3] = {
        {1 - 7 * n * a, 6 * n * a, n * a}, {3.0 / 8, 1.0 / 2, 1.0 / 8}, {1.0 / 4, 1.0 / 2, 1.0 / 4}};
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) CHECK(m[i][j] == doctest::Approx(expected[i][j]).epsilon(1e-14));
    }
    // det(M - lambda I) = 0 for each eigenvalue of the measured matrix.
    for (double lambda : {1.0, 0.25, 1.0 / 16}) {
      const double a00 = m[0][0] - lambda, a11 = m[1][1] - lambda, a22 = m[2][2] - lambda;
      const double det = a00 * (a11 * a22 - m[1][2] * m[2][1]) -
                         m[0][1] * (m[1][0] * a22 - m[1][2] * m[2][0]) +
                         m[0][2] * (m[1][0] * m[2][1] - a11 * m[2][0]);
      CHECK(std::abs(det) < 1e-14);
    }
  }
}

TEST_CASE("mlca surface: open triangle meshes and degenerate inputs give valid meshes") {
  // A triangulated 3 x 2 grid: split to quads (its hole too), then one step.
  PolygonSoup tri;
  const PolygonSoup grid = test::grid_soup(3, 2);
  tri.positions = grid.positions;
  for (std::size_t f = 0; f < grid.num_faces(); ++f) {
    const auto q = grid.face(f);
    tri.add_face({q[0], q[1], q[2]});
    tri.add_face({q[0], q[2], q[3]});
  }
  const Mesh open = build_mesh(tri);
  const Mesh out = mlca(open);
  require_valid(out);
  std::size_t real = 0;
  for (FaceId f : out.faces()) real += out.is_hole(f) ? 0 : 1;
  CHECK(real == 12 * 12);  // 12 triangles -> 36 quads -> 144
  // The boundary stays in the plane z = 0 and inside the grid's rectangle.
  for (VertexId v : out.vertices()) {
    const glm::dvec3 p = out.position(v);
    CHECK(p.z == 0.0);
    CHECK((p.x >= 0.0 && p.x <= 3.0 && p.y >= 0.0 && p.y <= 2.0));
  }
  // Two point spheres joined by an edge: one face of two corners (a 2-gon), split into two quads.
  Mesh segment;
  const VertexId a = segment.create_vertex({0, 0, 0}), b = segment.create_vertex({1, 0, 0});
  segment.insert_edge(segment.corner(a), segment.corner(b));
  const Mesh segment_out = mlca(segment);
  require_valid(segment_out);
  CHECK(segment_out.num_faces() == 4 * 2);
  // The empty mesh.
  CHECK(mlca(Mesh()).num_vertices() == 0);
}
