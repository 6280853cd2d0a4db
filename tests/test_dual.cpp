// The dual: counts, sizes and valences swapped, topology, orientation, the documented output order, the cube
// by hand, the dual of the dual (the connectivity back), affine invariance and the errors.

#include <doctest/doctest.h>

#include <dlfl/errors.h>
#include <dlfl/schemes/dual.h>
#include "test_helpers.h"
#include "triangle_meshes.h"

using namespace dlfl;
using namespace dlfl::test;

TEST_CASE("dual: counts, sizes and valences swap, genus kept, on meshes of several genera and face mixes") {
  for (const PolygonSoup& soup : closed_polygon_soups()) {
    CAPTURE(soup.num_faces());
    const Mesh in = build_mesh(soup);
    const Mesh out = dual(in);
    check_valid_same_genus(in, out);
    CHECK(out.num_vertices() == in.num_faces());
    CHECK(out.num_edges() == in.num_edges());
    CHECK(out.num_faces() == in.num_vertices());
    CHECK(face_size_histogram(out) == valence_histogram(in));
    CHECK(valence_histogram(out) == face_size_histogram(in));
    CHECK(signed_volume(out) > 0);  // the test meshes are convex or close to it, and outward
  }
  CHECK(dual(Mesh{}).empty());
}

TEST_CASE("dual: the cube by hand, and the documented output order") {
  // The dual of the cube is the octahedron on the face centres, the unit axis points; the face of cube vertex
  // v is the triangle of the centres of its three faces, counter-clockwise seen from outside.
  const Mesh in = test::cube();
  const Mesh out = dual(in);
  for (FaceId f : in.faces()) CHECK(close(out.position(VertexId(f.index())), centroid(in, f), 0.0));
  for (VertexId v : out.vertices()) CHECK(glm::length(out.position(v)) == 1.0);
  for (VertexId v : in.vertices()) {
    // Output face v lists the faces around input vertex v from corner(v), along prev_around_vertex.
    std::vector<VertexId> expected;
    CornerId c = in.corner(v);
    do {
      expected.push_back(VertexId(in.face(c).index()));
      c = in.prev_around_vertex(c);
    } while (c != in.corner(v));
    CHECK(face_vertices(out, FaceId(v.index())) == expected);
    // Outward: the triangle's normal points the way of the cube's corner.
    const auto t = face_vertices(out, FaceId(v.index()));
    const glm::dvec3 normal =
        glm::cross(out.position(t[1]) - out.position(t[0]), out.position(t[2]) - out.position(t[0]));
    CHECK(glm::dot(normal, in.position(v)) > 0);
  }
}

TEST_CASE("dual: the dual of the dual has the input's connectivity, and the cube comes back scaled by 1/3") {
  for (const PolygonSoup& soup : closed_polygon_soups()) {
    const Mesh in = build_mesh(soup);
    const Mesh twice = dual(dual(in));
    require_valid(twice);
    // Vertex v of the result stands for face v of the dual, which stands for vertex v of the input; face f
    // likewise for face f. Each face is the same cycle of vertices, perhaps from another first corner.
    REQUIRE(twice.num_faces() == in.num_faces());
    REQUIRE(twice.num_vertices() == in.num_vertices());
    for (FaceId f : in.faces()) {
      std::vector<std::uint32_t> a, b;
      for (VertexId v : face_vertices(in, f)) a.push_back(v.index());
      for (VertexId v : face_vertices(twice, f)) b.push_back(v.index());
      CHECK(canonical_cycle(a) == canonical_cycle(b));
    }
  }
  // Cube -> octahedron on the axis points -> the centroids of its triangles, (+-1, +-1, +-1) / 3.
  const Mesh in = test::cube();
  const Mesh twice = dual(dual(in));
  for (VertexId v : in.vertices()) CHECK(close(twice.position(v), in.position(v) / 3.0, 1e-15));
}

TEST_CASE("dual: a valence-2 vertex gives a 2-gon and a 2-gon gives a valence-2 vertex") {
  Mesh m = test::cube();
  const VertexId mid = m.subdivide_edge(EdgeId(0), {0.0, -1.0, -1.0});
  REQUIRE(m.valence(mid) == 2);
  const Mesh d = dual(m);
  require_valid(d);
  CHECK(d.size(FaceId(mid.index())) == 2);
  const Mesh back = dual(d);
  require_valid(back);
  CHECK(back.valence(mid) == 2);
}

TEST_CASE("dual: affine invariance") {
  check_affine_invariance(test::mixed_polyhedron(), [](const Mesh& m) { return dual(m); });
  check_affine_invariance(build_mesh(genus_soup(2)), [](const Mesh& m) { return dual(m); });
}

TEST_CASE(
    "dual: holes (under boundary=hole), point spheres and edges with one face on both sides are refused") {
  CHECK(error_message<TopologyError>([] { dual(build_mesh(grid_soup(2, 2)), {BoundaryRule::hole}); }) ==
        "dual: f4 is a hole: boundary=hole refuses open meshes (boundary=curve gives their dual)");

  Mesh m = test::cube();
  m.delete_vertex(m.create_vertex({9, 9, 9}));  // a tombstone v8 (and f6): the point sphere is v9, f7
  const VertexId sphere = m.create_vertex({5, 5, 5});
  CHECK(error_message<TopologyError>([&] { dual(m); }) == "dual: v9 is a point sphere (no edge)");

  // Joining the point sphere to the cube gives an edge with the cube's face on both sides.
  const InsertEdgeResult r = m.insert_edge(m.corner(VertexId(0)), m.corner(sphere));
  CHECK(error_message<TopologyError>([&] { dual(m); }) ==
        "dual: " + to_string(r.edge) + " has the same face on both sides (its dual would be a self-loop)");
}

TEST_CASE("dual: through the editor, its undo and the log") {
  const Mesh in = test::mixed_polyhedron();
  check_editor_and_log(in, "dual", {{"boundary", "hole"}}, dual(dual(in)), build_mesh(grid_soup(2, 1)));
}

#ifdef DLFL_TOOL
#include <filesystem>
#include <fstream>

#include "tool_runner.h"

TEST_CASE("dual: under boundary=hole the tool refuses an open mesh with one error line naming the hole") {
  const auto in = scratch("triangle.obj");
  std::ofstream(in) << "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
  const auto out = scratch("dual.obj");
  const Run r =
      run("subdivide '" + in.string() + "' -s dual --param boundary=hole -o '" + out.string() + "'");
  CHECK(r.exit_code == 1);
  CHECK(r.err ==
        "error: dual: f1 is a hole: boundary=hole refuses open meshes (boundary=curve gives their dual)\n");
  CHECK_FALSE(std::filesystem::exists(out));
}
#endif
