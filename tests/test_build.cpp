// Polygon soup <-> DLFL: predictable handles, hole faces, point spheres, and every rejected input.

#include <doctest/doctest.h>

#include <vector>

#include <dlfl/validate.h>
#include "test_meshes.h"

using namespace dlfl;

namespace {
PolygonError::Element build_error(const PolygonSoup& s, std::size_t* index) {
  try {
    build_mesh(s);
  } catch (const PolygonError& e) {
    *index = e.index();
    return e.element();
  }
  FAIL("build_mesh accepted a bad soup");
  return PolygonError::Element::face;
}
}  // namespace

TEST_CASE("build: soup indices become handles") {
  PolygonSoup s = test::cube_soup();
  Mesh m = build_mesh(s);
  CHECK(m.num_vertices() == 8);
  CHECK(m.num_edges() == 12);
  CHECK(m.num_faces() == 6);
  CHECK(m.num_corners() == 24);
  for (std::uint32_t f = 0; f < 6; ++f) {
    auto face = s.face(f);
    std::size_t j = 0;
    for (CornerId c : m.corners(FaceId(f))) {
      CHECK(c == CornerId(s.offsets[f] + std::uint32_t(j)));
      CHECK(m.vertex(c) == VertexId(face[j]));
      ++j;
    }
    CHECK(j == 4);
  }
  for (EdgeId e : m.edges()) CHECK(m.corner(e, 0) < m.corner(e, 1));
  CHECK(validate(m).valid());
}

TEST_CASE("build: each boundary loop becomes one hole face running the other way") {
  Mesh m = build_mesh(test::grid_soup(3, 2));
  CHECK(m.num_faces() == 7);
  const FaceId hole(6);
  REQUIRE(m.is_alive(hole));
  CHECK(m.is_hole(hole));
  CHECK(m.size(hole) == 10);  // perimeter of a 3 x 2 grid
  for (CornerId c : m.corners(hole)) {
    // The hole walks the boundary clockwise: across each of its edges lies a grid quad.
    CHECK_FALSE(m.is_hole(m.face(m.opposite(c))));
  }
  // A grid with a missing middle cell has two loops.
  PolygonSoup s = test::grid_soup(3, 3);
  PolygonSoup t;
  t.positions = s.positions;
  for (std::size_t i = 0; i < s.num_faces(); ++i) {
    if (i != 4) t.add_face(s.face(i));
  }
  Mesh ring = build_mesh(t);
  auto r = validate(ring);
  REQUIRE(r.valid());
  CHECK(r.components[0].holes == 2);
  CHECK(r.components[0].genus == 0);  // an annulus closed by two discs is a sphere
}

TEST_CASE("build: unused vertices become point spheres") {
  PolygonSoup s = test::tetrahedron_soup();
  s.positions.push_back({7, 7, 7});
  Mesh m = build_mesh(s);
  CHECK(m.num_vertices() == 5);
  CHECK(m.num_faces() == 5);
  CHECK(m.is_point_sphere(VertexId(4)));
  auto r = validate(m);
  REQUIRE(r.valid());
  CHECK(r.components.size() == 2);
}

TEST_CASE("build: every malformed soup is rejected with the offending element") {
  std::size_t index = 0;
  {
    PolygonSoup s = test::tetrahedron_soup();
    s.indices[4] = 9;  // face 1 uses a vertex that does not exist
    CHECK(build_error(s, &index) == PolygonError::Element::face);
    CHECK(index == 1);
  }
  {
    PolygonSoup s = test::cube_soup();
    s.add_face({0, 1, 1, 5});
    CHECK(build_error(s, &index) == PolygonError::Element::face);
    CHECK(index == 6);
  }
  {
    PolygonSoup s = test::tetrahedron_soup();
    s.add_face({0, 1, 2});  // the same triangle twice: each of its edges used twice in one direction
    CHECK(build_error(s, &index) == PolygonError::Element::face);
    CHECK(index == 4);
  }
  {
    // Three triangles on edge 0-1: a fin.
    PolygonSoup s;
    s.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}};
    s.add_face({0, 1, 2});
    s.add_face({1, 0, 3});
    s.add_face({1, 0, 4});
    CHECK(build_error(s, &index) == PolygonError::Element::face);
    CHECK(index == 2);
  }
  {
    // Two triangles that share only vertex 0 (a bowtie): two boundary fans meet there.
    PolygonSoup s;
    s.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {-1, 0, 0}, {-1, -1, 0}};
    s.add_face({0, 1, 2});
    s.add_face({0, 3, 4});
    CHECK(build_error(s, &index) == PolygonError::Element::vertex);
    CHECK(index == 0);
  }
  {
    // Two closed tetrahedra sharing a tip: a pinch with no boundary.
    PolygonSoup s = test::tetrahedron_soup();
    s.positions.push_back({-1, 5, 5});
    s.positions.push_back({1, 7, 5});
    s.positions.push_back({1, 5, 7});
    s.add_face({0, 4, 5});
    s.add_face({0, 6, 4});
    s.add_face({0, 5, 6});
    s.add_face({4, 6, 5});
    CHECK(build_error(s, &index) == PolygonError::Element::vertex);
    CHECK(index == 0);
  }
  {
    PolygonSoup s = test::tetrahedron_soup();
    s.add_face({0, 1});
    CHECK(build_error(s, &index) == PolygonError::Element::face);
    CHECK(index == 4);
  }
  {
    PolygonSoup s = test::tetrahedron_soup();
    s.positions[2].y = std::numeric_limits<double>::infinity();
    CHECK(build_error(s, &index) == PolygonError::Element::vertex);
    CHECK(index == 2);
  }
}

TEST_CASE("build: offsets that decrease are refused before a face is read") {
  PolygonSoup s = test::tetrahedron_soup();  // offsets 0 3 6 9 12
  REQUIRE(s.offsets.size() == 5);
  s.offsets[2] = 10;  // face 1 would run from 3 to 10, face 2 from 10 back to 9
  CHECK_THROWS_WITH_AS(build_mesh(s), doctest::Contains("decrease at face 2"), InvalidArgument);
}

TEST_CASE("build: to_polygons gives back the soup's faces and refuses what a soup cannot hold") {
  PolygonSoup s = test::grid_soup(2, 2);
  Mesh m = build_mesh(s);
  PolygonSoup back = to_polygons(m);
  CHECK(back.positions == s.positions);
  CHECK(back.offsets == s.offsets);
  CHECK(back.indices == s.indices);

  Mesh two = test::cube();
  CornerId c = two.first_corner(FaceId(0));
  two.insert_edge(c, two.next(c));  // a 2-gon beside an edge: also a double edge
  CHECK_THROWS_AS(to_polygons(two), TopologyError);
}
