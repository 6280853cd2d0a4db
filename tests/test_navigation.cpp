// Navigation (dlfl/navigation.h): the ranges around vertices and faces, find_edge, corner_in_face,
// boundaries, surface faces and hole counts, on meshes whose answers follow from their construction.

#include <doctest/doctest.h>

#include <algorithm>
#include <set>
#include <vector>

#include <dlfl/errors.h>
#include <dlfl/navigation.h>
#include <dlfl/validate.h>
#include "test_meshes.h"

using namespace dlfl;

namespace {

template <class Range>
auto collect(const Range& range) {
  std::vector<std::decay_t<decltype(*range.begin())>> out;
  for (auto x : range) out.push_back(x);
  return out;
}

// Cube vertices are (+-1, +-1, +-1): two are joined by an edge exactly when they differ in one coordinate.
bool cube_adjacent(const Mesh& m, VertexId a, VertexId b) {
  const glm::dvec3 d = m.position(a) - m.position(b);
  return (d.x != 0) + (d.y != 0) + (d.z != 0) == 1;
}

}  // namespace

TEST_CASE("navigation: neighbours of a vertex, in rotation order") {
  const Mesh m = test::cube();
  for (VertexId v : m.vertices()) {
    const std::vector<VertexId> around = collect(neighbours(m, v));
    REQUIRE(around.size() == 3);
    for (VertexId w : around) CHECK(cube_adjacent(m, v, w));
    CHECK(std::set<VertexId>(around.begin(), around.end()).size() == 3);
    // Rotation order: each neighbour and the next share a face with v (the corner between their edges).
    const std::vector<FaceId> between = collect(faces(m, v));
    REQUIRE(between.size() == 3);
    for (std::size_t i = 0; i < 3; ++i) {
      const std::vector<VertexId> f = collect(vertices(m, between[(i + 1) % 3]));
      CHECK(std::count(f.begin(), f.end(), around[i]) == 1);
      CHECK(std::count(f.begin(), f.end(), around[(i + 1) % 3]) == 1);
    }
    CHECK(collect(edges(m, v)).size() == 3);
    for (EdgeId e : edges(m, v)) CHECK((m.from(e) == v || m.to(e) == v));
  }
  const Mesh t = test::tetrahedron();
  for (VertexId v : t.vertices()) {
    std::set<VertexId> expected;
    for (VertexId w : t.vertices())
      if (w != v) expected.insert(w);
    const std::vector<VertexId> around = collect(neighbours(t, v));
    CHECK(std::set<VertexId>(around.begin(), around.end()) == expected);
    CHECK(around.size() == 3);
  }
}

TEST_CASE("navigation: the vertices, edges and neighbours of a face") {
  const Mesh m = test::cube();
  const PolygonSoup soup = test::cube_soup();
  for (FaceId f : m.faces()) {
    // build_mesh keeps each polygon's vertex order, starting at its first vertex.
    const std::vector<VertexId> along = collect(vertices(m, f));
    std::vector<VertexId> expected;
    for (std::uint32_t k = soup.offsets[f.index()]; k < soup.offsets[f.index() + 1]; ++k)
      expected.push_back(VertexId(soup.indices[k]));
    CHECK(along == expected);
    const std::vector<EdgeId> sides = collect(edges(m, f));
    REQUIRE(sides.size() == 4);
    for (std::size_t i = 0; i < 4; ++i) {
      const VertexId a = along[i], b = along[(i + 1) % 4];
      CHECK(
          ((m.from(sides[i]) == a && m.to(sides[i]) == b) || (m.from(sides[i]) == b && m.to(sides[i]) == a)));
    }
    // Across each edge a different face, sharing exactly that edge's two vertices; never f itself.
    const std::vector<FaceId> across = collect(neighbours(m, f));
    REQUIRE(across.size() == 4);
    CHECK(std::set<FaceId>(across.begin(), across.end()).size() == 4);
    for (std::size_t i = 0; i < 4; ++i) {
      CHECK(across[i] != f);
      const std::vector<VertexId> g = collect(vertices(m, across[i]));
      std::size_t shared = 0;
      for (VertexId v : g) shared += std::count(along.begin(), along.end(), v);
      CHECK(shared == 2);
      CHECK(std::count(g.begin(), g.end(), along[i]) == 1);
    }
  }
}

TEST_CASE("navigation: find_edge and corner_in_face") {
  const Mesh m = test::cube();
  std::size_t found = 0;
  for (VertexId u : m.vertices()) {
    for (VertexId v : m.vertices()) {
      const EdgeId e = find_edge(m, u, v);
      CHECK(e.valid() == (u != v && cube_adjacent(m, u, v)));
      if (!e.valid()) continue;
      ++found;
      CHECK(((m.from(e) == u && m.to(e) == v) || (m.from(e) == v && m.to(e) == u)));
    }
  }
  CHECK(found == 2 * 12);  // every edge, from both ends
  const PolygonSoup soup = test::cube_soup();
  for (FaceId f : m.faces()) {
    const auto first = soup.indices.begin() + soup.offsets[f.index()];
    const auto last = soup.indices.begin() + soup.offsets[f.index() + 1];
    for (VertexId v : m.vertices()) {
      const CornerId c = corner_in_face(m, v, f);
      CHECK(c.valid() == (std::find(first, last, v.index()) != last));
      if (c.valid()) {
        CHECK(m.vertex(c) == v);
        CHECK(m.face(c) == f);
      }
    }
  }
  Mesh removed = test::cube();
  const VertexId p = removed.create_vertex({3, 3, 3});
  removed.delete_vertex(p);
  CHECK_THROWS_AS(find_edge(removed, p, VertexId(0)), InvalidArgument);
  CHECK_THROWS_AS(corner_in_face(removed, VertexId(0), FaceId(6)), InvalidArgument);
  CHECK_THROWS_AS(is_boundary(removed, p), InvalidArgument);
  CHECK_THROWS_AS(is_boundary(removed, EdgeId(12)), InvalidArgument);
  // Two edges between the same vertices (a 2-gon): one of them is found.
  Mesh two = test::cube();
  const CornerId c = two.first_corner(FaceId(0));
  const EdgeId extra = two.insert_edge(c, two.next(c)).edge;
  const EdgeId e = find_edge(two, two.vertex(c), two.vertex(two.next(c)));
  CHECK((e == extra || e == two.edge(c)));
}

TEST_CASE("navigation: boundaries, surface faces and hole counts of an open grid") {
  // A 3 x 2 grid of unit quads: 12 vertices, 17 edges, 6 quads and one hole face around them.
  Mesh m = build_mesh(test::grid_soup(3, 2));
  CHECK(m.num_faces() == 7);
  CHECK(m.num_hole_faces() == 1);
  CHECK(m.num_surface_faces() == 6);
  const std::vector<FaceId> surface = collect(surface_faces(m));
  CHECK(surface.size() == 6);
  for (FaceId f : surface) CHECK_FALSE(m.is_hole(f));
  std::size_t boundary_vertices = 0, boundary_edges = 0;
  for (VertexId v : m.vertices()) {
    const glm::dvec3 p = m.position(v);
    const bool on_rim = p.x == 0 || p.x == 3 || p.y == 0 || p.y == 2;
    CHECK(is_boundary(m, v) == on_rim);
    boundary_vertices += is_boundary(m, v);
  }
  for (EdgeId e : m.edges()) boundary_edges += is_boundary(m, e);
  CHECK(boundary_vertices == 12 - 2);    // all but the two inner ones
  CHECK(boundary_edges == 2 * (3 + 2));  // the perimeter

  // A point sphere: a surface face of its own, no edges, no neighbours, not on a boundary.
  const VertexId p = m.create_vertex({9, 9, 9});
  CHECK(m.num_faces() == 8);
  CHECK(m.num_surface_faces() == 7);
  CHECK(collect(neighbours(m, p)).empty());
  CHECK(collect(edges(m, p)).empty());
  const std::vector<FaceId> own = collect(faces(m, p));
  REQUIRE(own.size() == 1);
  CHECK(collect(vertices(m, own[0])) == std::vector<VertexId>{p});
  CHECK(collect(neighbours(m, own[0])).empty());
  CHECK(collect(edges(m, own[0])).empty());
  CHECK_FALSE(is_boundary(m, p));
  CHECK(find_edge(m, p, VertexId(0)) == EdgeId());

  // Splitting the hole face makes two holes; the counts follow every operator and its inverse.
  FaceId hole;
  for (FaceId f : m.faces())
    if (m.is_hole(f)) hole = f;
  const CornerId c = m.first_corner(hole);
  const InsertEdgeResult split = m.insert_edge(c, m.next(m.next(m.next(c))));
  REQUIRE(split.split());
  CHECK(m.num_hole_faces() == 2);
  CHECK(m.num_surface_faces() == 7);
  CHECK(validate(m).valid());
  m.apply(split.inverse);
  CHECK(m.num_hole_faces() == 1);

  // set_hole as a step, with its inverse.
  Step fill{Step::Kind::set_hole};
  fill.face = hole;
  fill.hole = false;
  const Step unfill = m.apply(fill);
  CHECK(m.num_hole_faces() == 0);
  CHECK(m.num_surface_faces() == 8);
  CHECK_FALSE(is_boundary(m, VertexId(0)));
  CHECK(unfill.kind == Step::Kind::set_hole);
  CHECK(unfill.hole);
  m.apply(unfill);
  CHECK(m.is_hole(hole));
  CHECK(m.num_hole_faces() == 1);
  CHECK(validate(m).valid());
  Step bad{Step::Kind::set_hole};
  bad.face = FaceId(1000);
  CHECK_THROWS_AS(m.apply(bad), InvalidArgument);
}

TEST_CASE("navigation: the corner circulators are empty from an invalid corner") {
  const Mesh m = test::cube();
  CHECK(collect(Mesh::FaceCorners(&m, CornerId())).empty());
  CHECK(collect(Mesh::VertexCorners(&m, CornerId())).empty());
  CHECK(collect(m.corners(FaceId(0))).size() == 4);
  CHECK(collect(m.corners(VertexId(0))).size() == 3);
}
