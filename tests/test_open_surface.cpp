// The open surface of a mesh with holes: what `statistics` counts and what polygon files hold. A scheme that
// subdivides a hole like a face covers one boundary loop with several hole faces; their inner edges and
// vertices belong to no polygon, so they are neither counted nor written.

#include <doctest/doctest.h>

#include <filesystem>

#include <dlfl/build_mesh.h>
#include <dlfl/io/mesh_io.h>
#include <dlfl/schemes/catmull_clark.h>
#include <dlfl/schemes/loop.h>
#include <dlfl/statistics.h>
#include <dlfl/validate.h>
#include "test_helpers.h"

using namespace dlfl;
using test::require_valid;

namespace {

// Two unit squares side by side: 6 vertices, 7 edges, 2 quads, one boundary loop of 6 edges.
PolygonSoup two_squares() {
  PolygonSoup s;
  s.positions = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {0, 1, 0}, {1, 1, 0}, {2, 1, 0}};
  s.add_face({0, 1, 4, 3});
  s.add_face({1, 2, 5, 4});
  return s;
}

// A ring of 4 quads (an open cylinder): 8 vertices, 12 edges, 4 quads, two boundary loops of 4 edges.
PolygonSoup cylinder() {
  PolygonSoup s;
  for (int z = 0; z < 2; ++z) {
    s.positions.insert(s.positions.end(),
                       {{1, 0, double(z)}, {0, 1, double(z)}, {-1, 0, double(z)}, {0, -1, double(z)}});
  }
  for (std::uint32_t i = 0; i < 4; ++i) s.add_face({i, (i + 1) % 4, 4 + (i + 1) % 4, 4 + i});
  return s;
}

// A tetrahedron without its bottom face: 4 vertices, 6 edges, 3 triangles, one triangular boundary loop.
PolygonSoup open_tetrahedron() {
  PolygonSoup s;
  s.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  s.add_face({0, 1, 3});
  s.add_face({1, 2, 3});
  s.add_face({2, 0, 3});
  return s;
}

struct Counts {
  std::size_t vertices, edges, faces, holes;
};

void check_surface(const Mesh& m, const Counts& expected) {
  require_valid(m);
  const MeshStatistics s = statistics(m);
  CHECK(s.vertices == expected.vertices);
  CHECK(s.edges == expected.edges);
  CHECK(s.faces == expected.faces);
  CHECK(s.holes == expected.holes);
  CHECK(s.point_spheres == 0);
  // What a polygon file gets is that same surface, and reading it back gives the same figures.
  const PolygonSoup soup = to_polygons(m);
  CHECK(soup.positions.size() == expected.vertices);
  CHECK(soup.num_faces() == expected.faces);
  const MeshStatistics back = statistics(build_mesh(soup));
  CHECK(back.vertices == expected.vertices);
  CHECK(back.edges == expected.edges);
  CHECK(back.faces == expected.faces);
  CHECK(back.holes == expected.holes);
  CHECK(back.point_spheres == 0);
}

}  // namespace

TEST_CASE("open surface: a loaded open mesh has one hole face per loop and all of its elements") {
  const Mesh m = build_mesh(two_squares());
  check_surface(m, {6, 7, 2, 1});
  CHECK(m.num_vertices() == 6);
  CHECK(m.num_faces() == 3);  // the hole face
  check_surface(build_mesh(cylinder()), {8, 12, 4, 2});
}

TEST_CASE(
    "open surface: catmull-clark with boundary=hole covers a hole with quads, the surface leaves them out") {
  // Two squares: V + E + F = 6 + 7 + 3 (the hole counts as a face) = 16 vertices in the mesh; the hole's face
  // point is inside the hole, so the surface has 15. Edges: 2E + corners = 14 + 14 = 28, of which the 6 from
  // the hole's face point to its edge points lie between two hole quads: 22. Faces: 8 quads.
  // Check: 15 - 22 + 8 = 1, a disc. One boundary loop of 12 edges.
  const BoundaryOptions hole{BoundaryRule::hole};
  const Mesh cc = catmull_clark(build_mesh(two_squares()), hole);
  CHECK(cc.num_vertices() == 16);
  CHECK(cc.num_edges() == 28);
  check_surface(cc, {15, 22, 8, 1});
  // Cylinder: 8 + 12 + 6 = 26 vertices, 2 inside holes: 24. Edges 24 + 24 = 48, 4 inside each hole: 40.
  // Faces 16. 24 - 40 + 16 = 0, an annulus with its two loops.
  check_surface(catmull_clark(build_mesh(cylinder()), hole), {24, 40, 16, 2});
  // A second step: every vertex of the hole region stays out, the loops stay two.
  // V: 26 + 48 + 24 = 98 in the mesh; the hole region of each loop is now 4 x 4 = 16 quads around ...
  // (counted from the surface side instead): surface faces 4 x 16 = 64; the surface is a 16 x 4 grid of quads
  // on a cylinder: 16 x 5 = 80 vertices, 16 x 4 + 16 x 5 = 144 edges; 80 - 144 + 64 = 0.
  check_surface(catmull_clark(catmull_clark(build_mesh(cylinder()), hole), hole), {80, 144, 64, 2});
}

TEST_CASE(
    "open surface: loop with boundary=hole covers a triangular hole with 4 triangles, counts one loop") {
  // V + E = 4 + 6 = 10, all on the surface (the hole's inner triangle has the hole's edge points as corners).
  // Edges 2E + 3F = 12 + 12 = 24, of which the inner triangle's 3 lie between hole faces: 21. Faces 4 x 3
  // = 12. 10 - 21 + 12 = 1, a disc.
  const Mesh once = loop(build_mesh(open_tetrahedron()), {BoundaryRule::hole});
  CHECK(once.num_edges() == 24);
  check_surface(once, {10, 21, 12, 1});
}

TEST_CASE("open surface: a written catmull-clark step (boundary=hole) reads back without stray vertices") {
  const auto path = test::scratch("cc.obj");
  write_mesh(catmull_clark(build_mesh(two_squares()), {BoundaryRule::hole}), path);
  const MeshStatistics s = statistics(read_mesh(path));
  CHECK(s.vertices == 15);
  CHECK(s.point_spheres == 0);
  CHECK(s.holes == 1);
}
