// Loop: counts, valences, topology, the documented output order, positions derived by hand on the
// tetrahedron and the octahedron and re-derived from the published rules on an irregular mesh, affine
// invariance, the hole policy and the errors. (Agreement with CGAL's implementation is in tests/oracle.)

#include <doctest/doctest.h>

#include <cmath>
#include <numbers>

#include <dlfl/errors.h>
#include <dlfl/schemes/loop.h>
#include "test_helpers.h"
#include "triangle_meshes.h"

using namespace dlfl;
using namespace dlfl::test;

namespace {

// E new vertices (the edge points), E' = 2E + 3F (halves of old edges plus three inner edges per triangle),
// F' = 4F triangles; old vertices keep their valence, edge points have 6.
void check_counts(const Mesh& in, bool solid = true) {
  const std::size_t E = in.num_edges(), F = in.num_faces();
  check_triangle_step(
      in, [](const Mesh& m, Origins* o) { return loop(m, o); }, {E, 2 * E + 3 * F, 4 * F}, solid);
}

}  // namespace

TEST_CASE("loop: the tetrahedron and the octahedron by hand") {
  {
    // Regular tetrahedron centred at the origin: the other three vertices of v sum to -v. Valence 3:
    // cos(2 pi / 3) = -1/2, 3/8 - 1/8 = 1/4, beta = (5/8 - 1/16) / 3 = 3/16, so the vertex point is
    // (1 - 9/16) v + 3/16 (-v) = v / 4. The two far vertices c, d of edge ab sum to -(a + b), so the edge
    // point is 3/8 (a + b) - 1/8 (a + b) = (a + b) / 4, e.g. (1/2, 0, 0) for (1,1,1) and (1,-1,-1).
    const Mesh in = test::tetrahedron();
    const Mesh out = loop(in);
    for (VertexId v : in.vertices()) CHECK(close(out.position(v), in.position(v) / 4.0, 1e-15));
    for (EdgeId e : in.edges()) {
      CHECK(close(out.position(VertexId(4 + e.index())),
                  (in.position(in.from(e)) + in.position(in.to(e))) / 4.0, 1e-15));
    }
  }
  {
    // Octahedron: valence 4, cos(pi/2) = 0, beta = (5/8 - 9/64) / 4 = 31/256; the four neighbours of an axis
    // point sum to 0, so it moves to (1 - 124/256) v = 33/64 v. The far vertices of an edge between two axis
    // points are the two opposite axis points of the third axis, summing to 0: the edge point is 3/8 (a + b).
    const Mesh in = build_mesh(octahedron_soup());
    const Mesh out = loop(in);
    for (VertexId v : in.vertices()) CHECK(close(out.position(v), 33.0 / 64.0 * in.position(v), 1e-15));
    for (EdgeId e : in.edges()) {
      CHECK(close(out.position(VertexId(6 + e.index())),
                  3.0 / 8.0 * (in.position(in.from(e)) + in.position(in.to(e))), 1e-15));
    }
  }
}

TEST_CASE("loop: the published rules and the documented output order on an irregular mesh") {
  const Mesh in = irregular_torus();
  const Mesh out = loop(in);
  const std::uint32_t V = in.num_vertices(), C = in.num_corners();
  for (VertexId v : in.vertices()) {
    const double n = in.valence(v), beta = loop_beta(n);
    CHECK(close(out.position(v), (1.0 - n * beta) * in.position(v) + beta * neighbour_sum(in, v)));
  }
  for (EdgeId e : in.edges()) {
    const CornerId c0 = in.corner(e, 0), c1 = in.corner(e, 1);
    const glm::dvec3 expected =
        3.0 / 8.0 * (in.position(in.from(e)) + in.position(in.to(e))) +
        1.0 / 8.0 * (in.position(in.vertex(in.prev(c0))) + in.position(in.vertex(in.prev(c1))));
    CHECK(close(out.position(VertexId(V + e.index())), expected));
  }
  // Triangle k < C: (vertex(k), edge point of edge(k), edge point of edge(prev(k))); triangle C + f: the edge
  // points of the edges of f's first, second and third corners.
  for (CornerId c : in.corners()) {
    const auto t = face_vertices(out, FaceId(c.index()));
    CHECK(t == std::vector<VertexId>{in.vertex(c), VertexId(V + in.edge(c).index()),
                                     VertexId(V + in.edge(in.prev(c)).index())});
  }
  for (FaceId f : in.faces()) {
    const CornerId c0 = in.first_corner(f);
    const auto t = face_vertices(out, FaceId(C + f.index()));
    CHECK(t == std::vector<VertexId>{VertexId(V + in.edge(c0).index()),
                                     VertexId(V + in.edge(in.next(c0)).index()),
                                     VertexId(V + in.edge(in.prev(c0)).index())});
  }
}

TEST_CASE("loop: counts, valences and genus on triangle meshes of several genera") {
  for (const PolygonSoup& soup : closed_triangle_soups()) check_counts(build_mesh(soup));
}

TEST_CASE("loop: affine invariance") {
  check_affine_invariance(build_mesh(icosahedron_soup()), [](const Mesh& m) { return loop(m); });
  check_affine_invariance(build_mesh(triangulated(torus_soup(6, 4))), [](const Mesh& m) { return loop(m); });
}

TEST_CASE(
    "loop: with boundary=hole, a triangular hole is subdivided as if capped, its four triangles holes") {
  // The tetrahedron without its last face: an open mesh whose boundary loop is a triangular hole.
  PolygonSoup open = tetrahedron_soup();
  open.offsets.pop_back();
  open.indices.resize(9);
  const Mesh in = build_mesh(open);
  REQUIRE(count_holes(in) == 1);
  const Mesh out = loop(in, {BoundaryRule::hole});
  check_valid_same_genus(in, out);
  CHECK(out.num_faces() == 16);
  CHECK(count_holes(out) == 4);
  CHECK(to_polygons(out).num_faces() == 12);
  // Capping the hole by a face gives the closed tetrahedron, so the positions are those of its step: the
  // old vertices at v / 4 and the edge points at (a + b) / 4 (see the test by hand above).
  for (VertexId v : in.vertices()) CHECK(close(out.position(v), in.position(v) / 4.0, 1e-15));
  for (EdgeId e : in.edges()) {
    CHECK(close(out.position(VertexId(4 + e.index())),
                (in.position(in.from(e)) + in.position(in.to(e))) / 4.0, 1e-15));
  }
}

TEST_CASE(
    "loop: non-triangles, point spheres and (with boundary=hole) larger holes are refused, naming them") {
  // The octahedron with the edge between faces 0 and 1 removed (one of them is now a tombstone) and the
  // quad split again along its other diagonal (a new face at the end), then the edge between faces 4 and 5
  // removed: the only non-triangle comes after a tombstone, so its handle is not its compacted index.
  Mesh m = build_mesh(octahedron_soup());
  auto shared_edge = [&](FaceId a, FaceId b) {
    for (CornerId c : m.corners(a))
      if (m.face(m.opposite(c)) == b) return m.edge(c);
    return EdgeId();
  };
  const DeleteEdgeResult merged = m.delete_edge(shared_edge(FaceId(0), FaceId(1)));
  const FaceId survivor = merged.removed_face == FaceId(0) ? FaceId(1) : FaceId(0);
  REQUIRE(m.size(survivor) == 4);
  const CornerId c = m.first_corner(survivor);
  m.insert_edge(m.next(c), m.prev(c));
  m.delete_edge(shared_edge(FaceId(4), FaceId(5)));
  require_valid(m);
  FaceId quad;
  for (FaceId f : m.faces())
    if (m.size(f) == 4) quad = f;
  REQUIRE(quad.valid());
  const std::string message = error_message<TopologyError>([&] { loop(m); });
  CHECK(message == "loop: " + to_string(quad) + " has 4 corners; Loop subdivision needs triangles");

  // With boundary=hole, a hole of more than three corners: a triangulated grid's boundary loop. (The curve
  // rule takes it: tests/test_boundary_loop.cpp.)
  const Mesh grid = build_mesh(triangulated(grid_soup(2, 2)));
  const std::string hole = error_message<TopologyError>([&] { loop(grid, {BoundaryRule::hole}); });
  CHECK(hole.find("is a hole (a boundary loop) with 8 corners; Loop subdivision with boundary=hole needs "
                  "triangles, holes included (boundary=curve takes holes of any size)") != std::string::npos);

  Mesh sphere = test::tetrahedron();
  sphere.create_vertex({3, 3, 3});
  CHECK(error_message<TopologyError>([&] { loop(sphere); }) == "loop: v4 is a point sphere (no edge)");
}

TEST_CASE("loop: through the editor, its undo and the log") {
  const Mesh in = build_mesh(icosahedron_soup());
  check_editor_and_log(in, "loop", {}, loop(loop(in)), test::cube());
}

TEST_CASE("loop: the two-triangle pillow (valence 2) by hand, and the empty mesh") {
  // Two triangles on the same three vertices, back to back: every vertex has valence 2, and both triangles
  // of an edge have the same third vertex. n = 2: cos(pi) = -1, beta = (5/8 - (1/8)^2) / 2 = 39/128, so a
  // vertex moves to 25/64 S + 39/128 (sum of its two neighbours); the edge point of ab is 3/8 (a + b) + 1/4
  // c.
  const Mesh in = build_mesh(pillow_soup());
  check_counts(in, false);
  const Mesh out = loop(in);
  for (VertexId v : in.vertices()) {
    glm::dvec3 others(0.0);
    for (VertexId w : in.vertices())
      if (w != v) others += in.position(w);
    CHECK(close(out.position(v), 25.0 / 64.0 * in.position(v) + 39.0 / 128.0 * others, 1e-15));
  }
  for (EdgeId e : in.edges()) {
    const glm::dvec3 a = in.position(in.from(e)), b = in.position(in.to(e));
    const glm::dvec3 c = in.position(in.vertex(in.prev(in.corner(e, 0))));
    CHECK(close(out.position(VertexId(3 + e.index())), 3.0 / 8.0 * (a + b) + 0.25 * c, 1e-15));
  }
  CHECK(loop(Mesh{}).empty());
}

#ifdef DLFL_TOOL
#include <filesystem>

#include "tool_runner.h"

TEST_CASE("loop: the tool refuses a quad mesh with one error line naming the face, and writes nothing") {
  const auto out = scratch("loop.obj");
  const Run r = run("subdivide " + example("cube.obj") + " -s loop -o '" + out.string() + "'");
  CHECK(r.exit_code == 1);
  CHECK(r.err == "error: loop: f0 has 4 corners; Loop subdivision needs triangles\n");
  CHECK_FALSE(std::filesystem::exists(out));
}
#endif
