// Euler operators: exact counts and face sizes after each, a clean validator, and exact inverses.

#include <doctest/doctest.h>

#include <algorithm>
#include <vector>

#include <dlfl/create_face_manifold.h>
#include <dlfl/errors.h>
#include <dlfl/validate.h>
#include "test_helpers.h"
#include "test_meshes.h"

using namespace dlfl;
using test::require_valid;

namespace {

std::vector<std::uint32_t> face_sizes(const Mesh& m) {
  std::vector<std::uint32_t> s;
  for (FaceId f : m.faces()) s.push_back(m.size(f));
  std::sort(s.begin(), s.end());
  return s;
}

long genus_of_single_component(const Mesh& m) {
  auto r = validate(m);
  REQUIRE(r.valid());
  REQUIRE(r.components.size() == 1);
  return r.components[0].genus;
}

// The corner of face f at vertex v (f must visit v once).
// Applies `inverse` to `m`: true when that gives `before` back exactly.
bool restores(Mesh& m, const Step& inverse, const Mesh& before) {
  m.apply(inverse);
  return m == before;
}

CornerId corner_at(const Mesh& m, FaceId f, VertexId v) {
  for (CornerId c : m.corners(f)) {
    if (m.vertex(c) == v) return c;
  }
  FAIL("vertex not on face");
  return {};
}

}  // namespace

TEST_CASE("kernel: create_vertex makes a point sphere and delete_vertex removes it") {
  Mesh m;
  const Mesh empty = m;
  VertexId v = m.create_vertex({1, 2, 3});
  CHECK(m.num_vertices() == 1);
  CHECK(m.num_faces() == 1);
  CHECK(m.num_edges() == 0);
  CHECK(m.num_corners() == 1);
  CHECK(m.is_point_sphere(v));
  CHECK(m.valence(v) == 0);
  CHECK(m.position(v) == glm::dvec3(1, 2, 3));
  CornerId c = m.corner(v);
  CHECK(m.next(c) == c);
  CHECK(m.prev(c) == c);
  CHECK(m.size(m.face(c)) == 1);
  auto r = validate(m);
  REQUIRE(r.valid());
  REQUIRE(r.components.size() == 1);
  CHECK(r.components[0].euler_characteristic == 2);
  m.delete_vertex(v);
  CHECK(m == empty);
  CHECK_FALSE(m.is_alive(v));
  CHECK_THROWS_AS(m.delete_vertex(v), InvalidArgument);
  CHECK_THROWS_AS(m.create_vertex({0, std::nan(""), 0}), InvalidArgument);
}

TEST_CASE("kernel: insert_edge between two point spheres gives one edge on one face") {
  Mesh m;
  VertexId a = m.create_vertex({0, 0, 0});
  VertexId b = m.create_vertex({1, 0, 0});
  const Mesh before = m;
  InsertEdgeResult r = m.insert_edge(m.corner(a), m.corner(b));
  CHECK(m.num_vertices() == 2);
  CHECK(m.num_edges() == 1);
  CHECK(m.num_faces() == 1);
  CHECK(m.num_corners() == 2);  // the point spheres' corners are reused
  CHECK_FALSE(r.split());
  CHECK(r.removed_face == before.face(before.corner(b)));  // tie: the face of c1 survives
  CHECK(m.from(r.edge) == a);
  CHECK(m.to(r.edge) == b);
  CHECK(face_sizes(m) == std::vector<std::uint32_t>{2});
  CHECK(genus_of_single_component(m) == 0);
  CHECK(restores(m, r.inverse, before));
  require_valid(m);
}

TEST_CASE("kernel: insert_edge inside a face splits it and the larger part keeps the handle") {
  Mesh m = test::cube();
  const Mesh before = m;
  // Face 0 is (0, 2, 3, 1): a diagonal from vertex 0 to vertex 3 gives two triangles.
  const FaceId f(0);
  CornerId c1 = corner_at(m, f, VertexId(0));
  CornerId c2 = corner_at(m, f, VertexId(3));
  InsertEdgeResult r = m.insert_edge(c1, c2);
  REQUIRE(r.split());
  CHECK(m.num_faces() == 7);
  CHECK(m.num_edges() == 13);
  CHECK(m.num_vertices() == 8);
  CHECK(face_sizes(m) == std::vector<std::uint32_t>{3, 3, 4, 4, 4, 4, 4});
  CHECK(m.face(c1) == f);               // a tie: the part of c1 keeps the handle
  CHECK(m.face(c2) == r.created_face);  // the part of c2 is new
  CHECK(r.created_face == FaceId(6));   // appended after the six cube faces
  CHECK(m.vertex(m.corner(r.edge, 0)) == VertexId(0));
  CHECK(m.vertex(m.corner(r.edge, 1)) == VertexId(3));
  // c1, c2 keep their outgoing edges; the new corners sit just before c2 and c1.
  CHECK(m.edge(c1) == before.edge(c1));
  CHECK(m.edge(c2) == before.edge(c2));
  CHECK(m.next(m.corner(r.edge, 0)) == c2);
  CHECK(m.next(m.corner(r.edge, 1)) == c1);
  CHECK(genus_of_single_component(m) == 0);
  require_valid(m);
  CHECK(restores(m, r.inverse, before));
}

TEST_CASE("kernel: an uneven split gives the handle to the larger part") {
  Mesh m;
  std::vector<glm::dvec3> hexagon;
  for (int i = 0; i < 6; ++i) hexagon.push_back({std::cos(i * 1.0), std::sin(i * 1.0), 0});
  std::vector<CornerId> front(6), back(6);
  FaceManifold fm = create_face_manifold(m, hexagon, {}, front, back);
  // Corners 0 and 2 of the front hexagon: the part of c1 is (0, 1) + new corner = a triangle; the other part
  // (2, 3, 4, 5) + new corner is a pentagon and keeps the handle.
  InsertEdgeResult r = m.insert_edge(front[0], front[2]);
  CHECK(m.face(front[2]) == fm.front);
  CHECK(m.face(front[0]) == r.created_face);
  CHECK(m.size(fm.front) == 5);
  CHECK(m.size(r.created_face) == 3);
  require_valid(m);
}

TEST_CASE("kernel: insert_edge between adjacent corners makes a 2-gon") {
  Mesh m = test::cube();
  const Mesh before = m;
  const CornerId c = m.first_corner(FaceId(0));
  InsertEdgeResult r = m.insert_edge(c, m.next(c));
  CHECK(face_sizes(m) == std::vector<std::uint32_t>{2, 4, 4, 4, 4, 4, 4});
  CHECK(m.num_edges() == 13);
  require_valid(m);
  CHECK(restores(m, r.inverse, before));
}

TEST_CASE("kernel: insert_edge between two faces of one component adds a handle") {
  Mesh m = test::cube();
  const Mesh before = m;
  // Bottom face 0 and top face 1 do not touch.
  InsertEdgeResult r = m.insert_edge(m.first_corner(FaceId(0)), m.first_corner(FaceId(1)));
  CHECK_FALSE(r.split());
  CHECK(m.num_faces() == 5);
  CHECK(m.num_edges() == 13);
  CHECK(face_sizes(m) == std::vector<std::uint32_t>{4, 4, 4, 4, 10});
  CHECK(genus_of_single_component(m) == 1);  // 8 - 13 + 5 = 0
  CHECK(restores(m, r.inverse, before));
  CHECK(genus_of_single_component(m) == 0);
}

TEST_CASE("kernel: insert_edge between two components joins them") {
  PolygonSoup s = test::cube_soup();
  PolygonSoup t = test::tetrahedron_soup();
  for (auto p : t.positions) s.positions.push_back(p + glm::dvec3(5, 0, 0));
  for (std::size_t i = 0; i < t.num_faces(); ++i) {
    std::vector<std::uint32_t> f;
    for (auto k : t.face(i)) f.push_back(k + 8);
    s.add_face(f);
  }
  Mesh m = build_mesh(s);
  REQUIRE(validate(m).components.size() == 2);
  const Mesh before = m;
  // Triangle face 6 (4 corners smaller than the quad) is absorbed by quad face 0.
  InsertEdgeResult r = m.insert_edge(m.first_corner(FaceId(0)), m.first_corner(FaceId(6)));
  CHECK(r.removed_face == FaceId(6));
  CHECK(m.num_faces() == 9);
  CHECK(m.num_edges() == 19);
  CHECK(m.size(FaceId(0)) == 4 + 3 + 2);
  CHECK(genus_of_single_component(m) == 0);  // 12 - 19 + 9 = 2
  CHECK(restores(m, r.inverse, before));
}

TEST_CASE("kernel: insert_edge from a point sphere makes a dangling edge") {
  Mesh m = test::cube();
  VertexId p = m.create_vertex({0, 0, 3});
  const Mesh before = m;
  InsertEdgeResult r = m.insert_edge(m.first_corner(FaceId(1)), m.corner(p));
  CHECK(m.num_faces() == 6);
  CHECK(m.num_edges() == 13);
  CHECK(m.size(FaceId(1)) == 6);
  CHECK(m.valence(p) == 1);
  CHECK(genus_of_single_component(m) == 0);
  // Deleting a dangling edge gives the vertex back its point sphere.
  DeleteEdgeResult d = m.delete_edge(r.edge);
  CHECK(m.is_point_sphere(p));
  CHECK(m.num_faces() == 7);
  CHECK(d.created_face.valid());
  CHECK(m.size(m.face(m.corner(p))) == 1);
  require_valid(m);
  m.apply(d.inverse);
  require_valid(m);
  CHECK(restores(m, r.inverse, before));
}

TEST_CASE("kernel: insert_edge rejects self-loops and removed corners and leaves the mesh unchanged") {
  Mesh m = test::cube();
  const Mesh before = m;
  CornerId c = m.first_corner(FaceId(0));
  CornerId same_vertex = m.next_around_vertex(c);
  REQUIRE(m.vertex(same_vertex) == m.vertex(c));
  CHECK_THROWS_AS(m.insert_edge(c, same_vertex), TopologyError);
  CHECK_THROWS_AS(m.insert_edge(c, c), TopologyError);
  CHECK_THROWS_AS(m.insert_edge(c, CornerId(999)), InvalidArgument);
  CHECK_THROWS_AS(m.insert_edge(CornerId(), c), InvalidArgument);
  CHECK(m == before);
}

TEST_CASE("kernel: delete_edge merges two faces and its inverse splits them back") {
  Mesh m = test::cube();
  const Mesh before = m;
  DeleteEdgeResult r = m.delete_edge(EdgeId(0));
  CHECK(m.num_edges() == 11);
  CHECK(m.num_faces() == 5);
  CHECK(face_sizes(m) == std::vector<std::uint32_t>{4, 4, 4, 4, 6});
  CHECK(r.removed_face.valid());
  CHECK_FALSE(m.is_alive(EdgeId(0)));
  CHECK(genus_of_single_component(m) == 0);
  CHECK(restores(m, r.inverse, before));
  CHECK_THROWS_AS(m.delete_edge(EdgeId(12)), InvalidArgument);
}

TEST_CASE("kernel: is_alive by element kind agrees with the typed handles") {
  Mesh m = test::cube();
  // Two quads merge: edge 0, one face and two corners become tombstones.
  const DeleteEdgeResult r = m.delete_edge(EdgeId(0));
  REQUIRE(r.removed_face.valid());
  for (ElementKind kind : {ElementKind::vertex, ElementKind::edge, ElementKind::face, ElementKind::corner}) {
    CAPTURE(to_string(kind));
    std::size_t live = 0;
    for (std::uint32_t i = 0; i < m.capacity(kind) + 3; ++i) live += m.is_alive(kind, i);
    const std::size_t expected[] = {8, 11, 5, 22};  // V, E - 1, F - 1, C - 2
    CHECK(live == expected[std::size_t(kind)]);
  }
  CHECK_FALSE(m.is_alive(ElementKind::edge, 0));
  CHECK_FALSE(m.is_alive(ElementKind::face, r.removed_face.index()));
  CHECK(m.is_alive(ElementKind::corner, 23) == m.is_alive(CornerId(23)));
  CHECK_FALSE(m.is_alive(ElementKind::vertex, 0xFFFFFFFFu));
}

TEST_CASE("kernel: delete_vertex refuses a vertex with edges") {
  Mesh m = test::cube();
  CHECK_THROWS_AS(m.delete_vertex(VertexId(0)), TopologyError);
  CHECK(validate(m).valid());
}

TEST_CASE("kernel: subdivide_edge adds a 2-valent vertex and grows both faces") {
  Mesh m = test::cube();
  const Mesh before = m;
  const EdgeId e(3);
  const VertexId a = m.from(e), b = m.to(e);
  const FaceId f0 = m.face(e, 0), f1 = m.face(e, 1);
  VertexId v = m.subdivide_edge(e, {0.5, 0.5, 0.5});
  CHECK(m.num_vertices() == 9);
  CHECK(m.num_edges() == 13);
  CHECK(m.num_faces() == 6);
  CHECK(m.size(f0) == 5);
  CHECK(m.size(f1) == 5);
  CHECK(m.valence(v) == 2);
  CHECK(m.position(v) == glm::dvec3(0.5, 0.5, 0.5));
  CHECK(m.from(e) == a);
  CHECK(m.to(e) == v);
  require_valid(m);
  m.unsubdivide_edge(v);
  CHECK(m == before);
  CHECK(m.from(e) == a);
  CHECK(m.to(e) == b);
  CHECK_THROWS_AS(m.unsubdivide_edge(VertexId(0)), TopologyError);  // valence 3
  CHECK_THROWS_AS(m.subdivide_edge(e, {1, INFINITY, 0}), InvalidArgument);
}

TEST_CASE("kernel: navigation around faces and vertices and across edges") {
  Mesh m = test::cube();
  for (VertexId v : m.vertices()) {
    CHECK(m.valence(v) == 3);
    int n = 0;
    for (CornerId c : m.corners(v)) {
      CHECK(m.vertex(c) == v);
      CHECK(m.prev_around_vertex(m.next_around_vertex(c)) == c);
      ++n;
    }
    CHECK(n == 3);
  }
  for (CornerId c : m.corners()) {
    CHECK(m.opposite(m.opposite(c)) == c);
    CHECK(m.vertex(m.opposite(c)) == m.vertex(m.next(c)));
    CHECK(m.face(m.opposite(c)) != m.face(c));
  }
  for (FaceId f : m.faces()) {
    int n = 0;
    for (CornerId c : m.corners(f)) {
      CHECK(m.face(c) == f);
      ++n;
    }
    CHECK(n == 4);
  }
}

TEST_CASE("kernel: every insert_edge on a cube has the right counts and an exact inverse") {
  const Mesh cube = test::cube();
  int splits = 0, merges = 0;
  for (CornerId c1 : cube.corners()) {
    for (CornerId c2 : cube.corners()) {
      if (cube.vertex(c1) == cube.vertex(c2)) continue;
      Mesh m = cube;
      InsertEdgeResult r = m.insert_edge(c1, c2);
      const bool same_face = cube.face(c1) == cube.face(c2);
      CHECK(r.split() == same_face);
      CHECK(m.num_edges() == 13);
      CHECK(m.num_faces() == (same_face ? 7u : 5u));
      auto report = validate(m);
      REQUIRE(report.valid());
      CHECK(report.components[0].genus == (same_face ? 0 : 1));
      Step redo = m.apply(r.inverse);
      CHECK(m == cube);
      Mesh again = cube;
      again.insert_edge(c1, c2);
      m.apply(redo);
      CHECK(m == again);  // redo brings back the very same handles
      (same_face ? splits : merges) += 1;
    }
  }
  // Ordered corner pairs at different vertices: each of 24 corners with the 21 corners not at its own vertex.
  // Those on one face: 4 * 3 ordered pairs in each of the 6 quads.
  CHECK(splits == 6 * 4 * 3);
  CHECK(merges == 24 * 21 - 6 * 4 * 3);
}

TEST_CASE("kernel: every delete_edge on a genus-2 surface has an exact inverse") {
  const Mesh base = build_mesh(test::genus_soup(2));
  const auto before = validate(base);
  REQUIRE(before.valid());
  REQUIRE(before.components[0].genus == 2);
  for (EdgeId e : base.edges()) {
    Mesh m = base;
    DeleteEdgeResult r = m.delete_edge(e);
    CHECK(m.num_edges() == base.num_edges() - 1);
    CHECK(m.num_faces() == base.num_faces() - 1);  // no edge of this mesh has one face on both sides
    require_valid(m);
    m.apply(r.inverse);
    CHECK(m == base);
  }
}

TEST_CASE("kernel: compact renumbers densely and keeps the structure") {
  Mesh m = test::cube();
  m.delete_edge(EdgeId(0));
  VertexId v = m.subdivide_edge(EdgeId(5), {0, 0, 0});
  m.create_vertex({9, 9, 9});
  const auto sizes = face_sizes(m);
  Mesh::CompactMap map = m.compact();
  CHECK(m.vertex_capacity() == m.num_vertices());
  CHECK(m.edge_capacity() == m.num_edges());
  CHECK(m.face_capacity() == m.num_faces());
  CHECK(m.corner_capacity() == m.num_corners());
  CHECK(face_sizes(m) == sizes);
  CHECK_FALSE(map.edges[0].valid());
  CHECK(map.vertices[v.index()] == v);  // no vertex was removed, so vertex handles keep their places
  require_valid(m);
}
