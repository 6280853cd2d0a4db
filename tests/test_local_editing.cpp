// The local editing operations (docs/modeling.md, "Local editing"): collapse_edge, splice_corners,
// divide_edge, flip_edge, make_hole and fill_hole. For each: the counts on the modeling meshes, a valid
// result with its orientation kept, exact undo and redo through the editor, a log that replays to the same
// mesh, and every refusal with its message, leaving the mesh as it was. Expected counts come from the closed
// forms of docs/modeling.md; which edges the link condition refuses, and the small meshes' results, are
// worked out by hand in the comments.

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <ostream>
#include <random>
#include <string>
#include <vector>

#include <dlfl/build_mesh.h>
#include <dlfl/errors.h>
#include <dlfl/history/editor.h>
#include <dlfl/history/oplog.h>
#include <dlfl/mesh_hash.h>
#include <dlfl/navigation.h>
#include <dlfl/operations/collapse_edge.h>
#include <dlfl/operations/divide_edge.h>
#include <dlfl/operations/fill_hole.h>
#include <dlfl/operations/flip_edge.h>
#include <dlfl/operations/make_hole.h>
#include <dlfl/operations/operation.h>
#include <dlfl/operations/splice_corners.h>
#include <dlfl/validate.h>

#include "modeling_checks.h"
#include "modeling_meshes.h"
#include "test_helpers.h"
#include "test_meshes.h"

using namespace dlfl;

namespace {

using test::Counts;
using test::counts;
using test::signed_volume;

Counts plus(const Counts& c, long dv, long de, long df) { return {c.v + dv, c.e + de, c.f + df}; }

bool closed(const Mesh& m) { return m.num_hole_faces() == 0; }

Mesh mesh_of(const PolygonSoup& soup) { return build_mesh(soup); }
VertexId V(std::uint32_t i) { return VertexId(i); }
EdgeId edge_between(const Mesh& m, std::uint32_t a, std::uint32_t b) {
  const EdgeId e = find_edge(m, V(a), V(b));
  REQUIRE(e.valid());
  return e;
}
CornerId corner_of(const Mesh& m, std::uint32_t v, std::uint32_t f) {
  const CornerId c = corner_in_face(m, V(v), FaceId(f));
  REQUIRE(c.valid());
  return c;
}
bool joined(const Mesh& m, VertexId a, VertexId b) { return find_edge(m, a, b).valid(); }

// Applies an operation through the shared editor round trip; `mesh` becomes the result and the operation's
// outputs are returned.
Params apply_exactly(Mesh& mesh, const std::string& op, const Params& params) {
  Params out;
  mesh = test::check_editor_round_trip(mesh, op, params, &out);
  return out;
}

// The result of an operation run directly (no editor) on a copy.
Mesh applied(const Mesh& mesh, const std::string& op, const Params& params, Params* out = nullptr) {
  Mesh m = mesh;
  Params outputs = apply_operation(m, op, params);
  if (out) *out = outputs;
  return m;
}

using test::Refusal;
using test::refusal;

// The same refusal from the library function, called in a transaction on `mesh`, which must not change.
template <class F>
Refusal library_refusal(Mesh& mesh, F&& run) {
  const Mesh before = mesh;
  Refusal r;
  try {
    Transaction tx(mesh);
    run(tx);
    tx.commit();
    FAIL("accepted");
  } catch (const ParameterError& e) {
    r = {true, e.parameter(), e.what()};
  }
  CHECK(mesh == before);
  return r;
}

bool refused(const auto& check) {
  try {
    check();
  } catch (const ParameterError&) {
    return true;
  }
  return false;
}

// ---- small meshes worked out by hand

// A triangle x y z on the equator with poles N and S: V 5, E 9, F 6.
PolygonSoup bipyramid_soup() {
  return test::triangle_soup({{1, 0, 0}, {-0.5, 0.866, 0}, {-0.5, -0.866, 0}, {0, 0, 1}, {0, 0, -1}},
                             {{0, 1, 3}, {1, 2, 3}, {2, 0, 3}, {1, 0, 4}, {2, 1, 4}, {0, 2, 4}});
}

// A triangular prism (bottom 0 1 2, top 3 4 5) whose side quads are split by the diagonals 0-4, 1-5 and
// 0-5 (not the rotational 2-3, which would make it an octahedron): V 6, E 12, F 8.
PolygonSoup triangulated_prism_soup() {
  return test::triangle_soup(
      {{1, 0, 0}, {-0.5, 0.866, 0}, {-0.5, -0.866, 0}, {1, 0, 1}, {-0.5, 0.866, 1}, {-0.5, -0.866, 1}},
      {{0, 2, 1}, {3, 4, 5}, {0, 1, 4}, {0, 4, 3}, {1, 2, 5}, {1, 5, 4}, {2, 0, 5}, {0, 3, 5}});
}

// A square pyramid: base 0 1 2 3, apex 4: V 5, E 8, F 5.
PolygonSoup square_pyramid_soup() {
  PolygonSoup s;
  s.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0.5, 0.5, 1}};
  s.add_face({0, 3, 2, 1});
  for (std::uint32_t i = 0; i < 4; ++i) s.add_face({i, (i + 1) % 4, 4});
  return s;
}

// Two triangles glued along all three edges: V 3, E 3, F 2.
PolygonSoup pillow_soup() {
  return test::triangle_soup({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}}, {{0, 1, 2}, {1, 0, 2}});
}

// A hexagon 0..5 whose vertices 0, 1 and 4 also span the triangle f1 = (1 0 4), closed by f2 = (2 1 4 3)
// and f3 = (5 4 0): V 6, E 8, F 4. Vertex 4 is on the hexagon and joined to 0 outside it.
PolygonSoup hexagon_with_chord_soup() {
  PolygonSoup s;
  s.positions = {{0, 0, 0}, {1, 0, 0}, {2, 1, 0}, {1, 2, 0}, {0.5, 1, 1}, {-1, 1, 0}};
  s.add_face({0, 1, 2, 3, 4, 5});
  s.add_face({1, 0, 4});
  s.add_face({2, 1, 4, 3});
  s.add_face({5, 4, 0});
  return s;
}

// A 3 x 3 grid (vertex (i, j) is 4j + i, cell (i, j) is face 3j + i) with the middle cell made a hole: two
// boundary loops.
Mesh grid_with_inner_hole() {
  Mesh m = mesh_of(test::grid_soup(3, 3));
  m.set_hole(FaceId(4), true);
  return m;
}

// A cube whose faces (0 1 5 4) and (2 6 7 3) are joined by an edge from 4 to 7: a handle, and an edge with
// the same face on both sides.
Mesh cube_with_handle(EdgeId* handle_edge) {
  Mesh m = mesh_of(test::cube_soup());
  *handle_edge = m.insert_edge(corner_of(m, 4, 2), corner_of(m, 7, 3)).edge;
  return m;
}

}  // namespace

// ---- collapse_edge --------------------------------------------------------------------------------------

TEST_CASE("collapse_edge: the declaration's names and defaults") {
  const OperationSpec& op = find_operation("collapse_edge");
  REQUIRE(op.params.size() == 3);
  CHECK(op.params[0].name == "edge");
  CHECK(op.params[1].name == "position");
  CHECK(op.params[1].is_optional);
  CHECK(op.params[2].name == "cleanup");
  CHECK(op.params[2].default_value == Value(false));
}

TEST_CASE(
    "collapse_edge: counts on every modeling mesh and every edge, the link condition worked out by hand") {
  // The link condition refuses exactly the edges of the torus's 3-rings (vertex 3i + j, j = 0..2): the ring
  // is a 3-cycle that bounds no face, so its third vertex is a common neighbour with no triangle beside the
  // edge. Elsewhere: the tetrahedron's and octahedron's common neighbours are the apexes of the two
  // triangles; the quad meshes (cube, prisms, 4-rings of the torus, slabs, grid) have none, and no face
  // visits both ends of an edge away from it; the grid's boundary vertices are never joined by an inner edge.
  test::for_each_modeling_mesh([&](const std::string& name, const Mesh& mesh) {
    const Counts before = counts(mesh);
    const double volume = signed_volume(mesh);
    for (EdgeId e : mesh.edges()) {
      CAPTURE(e);
      const VertexId u = mesh.from(e), v = mesh.to(e);
      const bool expect_refused = name == "torus 4x3" && u.index() / 3 == v.index() / 3;
      if (expect_refused) {
        const Refusal r = refusal(mesh, "collapse_edge", {{"edge", e}});
        CHECK(r.parameter == "edge");
        CHECK(r.message.find("share 1 neighbour, the link condition allows 0") != std::string::npos);
        continue;
      }
      int k = 0;
      for (int side : {0, 1}) {
        const FaceId f = mesh.face(e, side);
        k += mesh.size(f) == 3 && !mesh.is_hole(f);
      }
      for (bool cleanup : {false, true}) {
        CAPTURE(cleanup);
        Params out;
        const Mesh m = applied(mesh, "collapse_edge", {{"edge", e}, {"cleanup", cleanup}}, &out);
        test::require_valid(m);
        CHECK(counts(m) == (cleanup ? plus(before, -1, -1 - k, -k) : plus(before, -1, -1, 0)));
        CHECK(m.num_hole_faces() == mesh.num_hole_faces());
        // from(e) keeps its handle and moves to the midpoint; to(e) is gone.
        CHECK(out.handle<VertexId>("vertex") == u);
        CHECK_FALSE(m.is_alive(v));
        CHECK(glm::distance(m.position(u), 0.5 * (mesh.position(u) + mesh.position(v))) < 1e-15);
        if (cleanup) {
          CHECK(out.integer("two_gons_removed") == k);
          // With the 2-gons gone, the result is a polygon mesh that a file holds and reads back as a
          // manifold (build_mesh refuses pinched vertices and doubled edges): the link condition's promise.
          const Mesh back = build_mesh(to_polygons(m));
          CHECK(back.num_vertices() == m.num_vertices());
          CHECK(back.num_edges() == m.num_edges());
          CHECK(back.num_surface_faces() == m.num_surface_faces());
        }
        if (closed(mesh) && name != "tetrahedron") {
          CHECK(signed_volume(m) > 0);  // the orientation kept
          CHECK(volume > 0);
        }
        if (name == "tetrahedron") CHECK(std::abs(signed_volume(m)) < 1e-12);  // flattened: two triangles
      }
    }
  });
}

TEST_CASE("collapse_edge: undo, redo and log replay are exact on every modeling mesh") {
  test::for_each_modeling_mesh([&](const std::string& name, const Mesh& mesh) {
    // The first edge that is in no torus 3-ring (every edge elsewhere collapses).
    EdgeId e(0);
    while (name == "torus 4x3" && mesh.from(e).index() / 3 == mesh.to(e).index() / 3)
      e = EdgeId(e.index() + 1);
    for (bool cleanup : {false, true}) {
      Mesh m = mesh;
      apply_exactly(m, "collapse_edge",
                    {{"edge", e}, {"cleanup", cleanup}, {"position", glm::dvec3(0.1, 0.2, 0.3)}});
      CHECK(m.position(mesh.from(e)) == glm::dvec3(0.1, 0.2, 0.3));
    }
  });
}

TEST_CASE("collapse_edge: cleanup removes k = 0, 1, 2 two-gons") {
  SUBCASE("k = 0: a cube edge has two quads, which become triangles: V 7, E 11, F 6 either way") {
    const Mesh cube = mesh_of(test::cube_soup());
    for (bool cleanup : {false, true}) {
      Mesh m = cube;
      const Params out =
          apply_exactly(m, "collapse_edge", {{"edge", edge_between(cube, 0, 1)}, {"cleanup", cleanup}});
      CHECK(counts(m) == Counts{7, 11, 6});
      CHECK(out.integer("two_gons_removed") == 0);
      CHECK(signed_volume(m) > 0);
    }
  }
  SUBCASE("k = 1: a base edge of a square pyramid (the base and one triangle) gives a tetrahedron") {
    const Mesh pyramid = mesh_of(square_pyramid_soup());
    Mesh m = pyramid;
    apply_exactly(m, "collapse_edge", {{"edge", edge_between(pyramid, 0, 1)}});
    CHECK(counts(m) == Counts{4, 7, 5});  // the triangle 0 1 4 is a 2-gon, the base a triangle
    m = pyramid;
    const Params out =
        apply_exactly(m, "collapse_edge", {{"edge", edge_between(pyramid, 0, 1)}, {"cleanup", true}});
    CHECK(counts(m) == Counts{4, 6, 4});
    CHECK(out.integer("two_gons_removed") == 1);
    for (FaceId f : m.faces()) CHECK(m.size(f) == 3);
    CHECK(signed_volume(m) > 0);
  }
  SUBCASE("k = 2: an octahedron edge; with cleanup the octahedron becomes a triangular bipyramid") {
    const Mesh octahedron = mesh_of(test::octahedron_soup());
    Mesh m = octahedron;
    apply_exactly(m, "collapse_edge", {{"edge", edge_between(octahedron, 0, 2)}});
    CHECK(counts(m) == Counts{5, 11, 8});
    m = octahedron;
    const Params out =
        apply_exactly(m, "collapse_edge", {{"edge", edge_between(octahedron, 0, 2)}, {"cleanup", true}});
    CHECK(counts(m) == Counts{5, 9, 6});
    CHECK(out.integer("two_gons_removed") == 2);
    // The merged vertex, 1 and 3 are the bipyramid's equator (valence 4); 4 and 5, which lost one of their
    // two edges to the merged vertex, are its poles (valence 3).
    const VertexId merged = out.handle<VertexId>("vertex");
    CHECK(m.valence(merged) == 4);
    CHECK(m.valence(V(4)) == 3);
    CHECK(m.valence(V(5)) == 3);
    CHECK(m.valence(V(1)) == 4);
    CHECK(m.valence(V(3)) == 4);
    CHECK(signed_volume(m) > 0);
  }
  SUBCASE("k = 2 on a tetrahedron: the two other triangles are left, glued along their three edges") {
    Mesh m = mesh_of(test::tetrahedron_soup());
    const Params out = apply_exactly(m, "collapse_edge", {{"edge", EdgeId(0)}, {"cleanup", true}});
    CHECK(counts(m) == Counts{3, 3, 2});
    CHECK(out.integer("two_gons_removed") == 2);
  }
  SUBCASE("the pillow (two triangles sharing all three edges): one 2-gon is left to remove, k = 1") {
    const Mesh pillow = mesh_of(pillow_soup());
    Mesh m = pillow;
    apply_exactly(m, "collapse_edge", {{"edge", edge_between(pillow, 0, 1)}});
    CHECK(counts(m) == Counts{2, 2, 2});  // two 2-gons on the same two edges
    m = pillow;
    const Params out =
        apply_exactly(m, "collapse_edge", {{"edge", edge_between(pillow, 0, 1)}, {"cleanup", true}});
    CHECK(counts(m) == Counts{2, 1, 1});  // one edge, the same face on both sides
    CHECK(out.integer("two_gons_removed") == 1);
  }
}

TEST_CASE(
    "collapse_edge: a vertex between two triangles only (a lens in a tetrahedron's edge), and a dangling "
    "edge") {
  SUBCASE("the lens: cleanup removes both 2-gons, k = 2, and the tetrahedron is back") {
    // Edge 0 1 of the tetrahedron is doubled (a 2-gon in face f0), and a vertex v inside that 2-gon is joined
    // to 0 and 1: the triangles (v 0 1) and (v 1 0), on the two parallel edges. V 5, E 9, F 6.
    Mesh m = mesh_of(test::tetrahedron_soup());
    const CornerId at0 = corner_of(m, 0, 0);
    const CornerId at1 = corner_of(m, 1, 0);
    const InsertEdgeResult doubled = m.insert_edge(at0, at1);
    const CornerId two_gon_at1 = m.corner(doubled.edge, 1);  // in the 2-gon, before at0
    REQUIRE(m.size(m.face(at0)) == 2);
    const VertexId v = m.create_vertex(glm::dvec3(1, 0, 0));
    const EdgeId e = m.insert_edge(at0, m.corner(v)).edge;  // from 0
    m.insert_edge(m.corner(v), two_gon_at1);
    REQUIRE(counts(m) == (Counts{5, 9, 6}));
    REQUIRE(m.valence(v) == 2);
    for (int side : {0, 1}) REQUIRE(m.size(m.face(e, side)) == 3);
    const Params out = apply_exactly(m, "collapse_edge", {{"edge", e}, {"cleanup", true}});
    CHECK(counts(m) == (Counts{4, 6, 4}));
    CHECK(out.integer("two_gons_removed") == 2);
    CHECK(out.handle<VertexId>("vertex") == V(0));
    for (FaceId f : m.faces()) CHECK(m.size(f) == 3);
    CHECK(counts(build_mesh(to_polygons(m))) == (Counts{4, 6, 4}));
  }
  SUBCASE("a dangling edge to a point sphere: either end can go") {
    // The cube with a point sphere joined to vertex 7 by an edge: V 9, E 13, F 6.
    const Mesh cube = mesh_of(test::cube_soup());
    Mesh m = cube;
    VertexId sphere = m.create_vertex(glm::dvec3(2, 2, 2));
    const EdgeId from_cube = m.insert_edge(corner_of(m, 7, 1), m.corner(sphere)).edge;
    REQUIRE(counts(m) == (Counts{9, 13, 6}));
    apply_exactly(m, "collapse_edge", {{"edge", from_cube}, {"position", glm::dvec3(1, 1, 1)}});
    CHECK(counts(m) == (Counts{8, 12, 6}));  // the sphere's vertex is gone, the cube's shape back
    CHECK_FALSE(m.is_alive(sphere));
    CHECK(m.valence(V(7)) == 3);
    CHECK(signed_volume(m) == doctest::Approx(8.0));
    // The other way round, the point sphere's vertex takes vertex 7's three edges.
    m = cube;
    sphere = m.create_vertex(glm::dvec3(2, 2, 2));
    const EdgeId from_sphere = m.insert_edge(m.corner(sphere), corner_of(m, 7, 1)).edge;
    apply_exactly(m, "collapse_edge", {{"edge", from_sphere}});
    CHECK(counts(m) == (Counts{8, 12, 6}));
    CHECK_FALSE(m.is_alive(V(7)));
    CHECK(m.valence(sphere) == 3);
    CHECK(m.position(sphere) == glm::dvec3(1.5, 1.5, 1.5));
  }
}

TEST_CASE(
    "collapse_edge: hole faces keep their flags; a triangular hole becomes a 2-gon hole, not cleaned up") {
  // A tetrahedron with one face made a hole. Collapsing each edge of that hole: the hole triangle becomes a
  // 2-gon hole that stays, the surface triangle on the other side a 2-gon that cleanup removes: V 3, E 4,
  // F 3.
  Mesh open = mesh_of(test::tetrahedron_soup());
  open.set_hole(FaceId(0), true);
  std::vector<EdgeId> hole_edges;
  for (EdgeId e : edges(open, FaceId(0))) hole_edges.push_back(e);
  REQUIRE(hole_edges.size() == 3);
  for (EdgeId e : hole_edges) {
    CAPTURE(e);
    Mesh m = open;
    const Params out = apply_exactly(m, "collapse_edge", {{"edge", e}, {"cleanup", true}});
    CHECK(counts(m) == Counts{3, 4, 3});
    CHECK(out.integer("two_gons_removed") == 1);
    REQUIRE(m.num_hole_faces() == 1);
    for (FaceId f : m.faces()) CHECK(m.is_hole(f) == (m.size(f) == 2));
  }
  // On the open grid the boundary edges shrink the one hole by a corner.
  const Mesh grid = mesh_of(test::grid_soup(3, 2));
  const FaceId hole(6);
  REQUIRE(grid.is_hole(hole));
  for (EdgeId e : edges(grid, hole)) {
    const Mesh m = applied(grid, "collapse_edge", {{"edge", e}});
    CHECK(m.num_hole_faces() == 1);
    CHECK(m.is_hole(hole));
    CHECK(m.size(hole) == grid.size(hole) - 1);
  }
}

TEST_CASE("collapse_edge: refusals, each naming the edge, the mesh unchanged") {
  SUBCASE("an extra common neighbour: the bipyramid's equator edge") {
    // Equator x y (0, 1): triangles x y N and y x S beside it allow N and S; z (2) is joined to both too.
    const Mesh m = mesh_of(bipyramid_soup());
    const Refusal r = refusal(m, "collapse_edge", {{"edge", edge_between(m, 0, 1)}});
    CHECK(r.parameter == "edge");
    CHECK(r.message ==
          "collapse_edge: parameter edge: the result would not be a manifold (the end vertices share 3 "
          "neighbours, the link condition allows 2; the edges to v2 would double up)");
    // A pole edge (N, x) has only the two apexes y and z in common: allowed, and with cleanup the bipyramid
    // becomes a tetrahedron.
    const Mesh t = applied(m, "collapse_edge", {{"edge", edge_between(m, 3, 0)}, {"cleanup", true}});
    CHECK(counts(t) == Counts{4, 6, 4});
  }
  SUBCASE("an extra common neighbour: the triangulated prism") {
    // Edge 0 1: triangles (0 2 1) and (0 1 4) allow 2 and 4; the diagonals 0-5 and 1-5 make 5 common too.
    const Mesh m = mesh_of(triangulated_prism_soup());
    const Refusal r = refusal(m, "collapse_edge", {{"edge", edge_between(m, 0, 1)}});
    CHECK(r.parameter == "edge");
    CHECK(r.message.find("share 3 neighbours, the link condition allows 2; the edges to v5") !=
          std::string::npos);
  }
  SUBCASE("a parallel edge would become a self-loop") {
    // Splitting the cube's face (0 2 3 1) between the corners of 0 and 1 makes a 2-gon on 0 1.
    Mesh m = mesh_of(test::cube_soup());
    const EdgeId parallel = m.insert_edge(CornerId(0), CornerId(3)).edge;
    const EdgeId original = edge_between(mesh_of(test::cube_soup()), 0, 1);
    const Refusal r = refusal(m, "collapse_edge", {{"edge", original}});
    CHECK(r.parameter == "edge");
    CHECK(r.message == "collapse_edge: parameter edge: the collapse would make a self-loop of " +
                           to_string(parallel) + ", which also joins " + to_string(m.from(original)) +
                           " and " + to_string(m.to(original)));
    CHECK(refusal(m, "collapse_edge", {{"edge", parallel}})
              .message.find("self-loop of " + to_string(original)) != std::string::npos);
  }
  SUBCASE("a face that visits both ends away from the edge: the hole of a 2 x 1 grid") {
    // The middle edge 1 4 has both ends on the boundary: the hole would pass through the merged vertex twice.
    const Mesh m = mesh_of(test::grid_soup(2, 1));
    const Refusal r = refusal(m, "collapse_edge", {{"edge", edge_between(m, 1, 4)}});
    CHECK(r.parameter == "edge");
    CHECK(r.message ==
          "collapse_edge: parameter edge: the result would not be a manifold (f2 visits both v1 and v4 away "
          "from the edge; it would pass through the merged vertex twice)");
  }
  SUBCASE("a face that visits both ends away from the edge: a handle across a hexagonal prism's top") {
    // Top vertices 6 and 9 are opposite on the hexagon f1; an edge between them through the side quads.
    Mesh m = mesh_of(test::prism_soup(6));
    const EdgeId e = m.insert_edge(corner_of(m, 6, 2), corner_of(m, 9, 5)).edge;
    const Refusal r = refusal(m, "collapse_edge", {{"edge", e}});
    CHECK(r.parameter == "edge");
    CHECK(r.message.find("f1 visits both v6 and v9 away from the edge") != std::string::npos);
  }
  SUBCASE("two separate boundaries would meet at the merged vertex") {
    // Vertex 1 is on the outer boundary, 5 on the inner hole's; the edge 1 5 is between two cells.
    const Mesh m = grid_with_inner_hole();
    const Refusal r = refusal(m, "collapse_edge", {{"edge", edge_between(m, 1, 5)}});
    CHECK(r.parameter == "edge");
    CHECK(r.message ==
          "collapse_edge: parameter edge: the result would not be a manifold (the merged vertex would be on "
          "the boundary in 2 separate places, a pinch)");
    // An edge of the inner boundary itself is fine: the merged vertex is on that boundary only.
    CHECK(counts(applied(m, "collapse_edge", {{"edge", edge_between(m, 5, 6)}})) ==
          plus(counts(m), -1, -1, 0));
  }
  SUBCASE("a removed edge and a non-finite position, through the registry and the library function") {
    Mesh m = mesh_of(test::cube_soup());
    const EdgeId gone(40);
    CHECK(refusal(m, "collapse_edge", {{"edge", gone}}).parameter == "edge");
    const Refusal r = library_refusal(m, [&](Transaction& tx) { collapse_edge(tx, gone); });
    CHECK(r.parameter == "edge");
    CHECK(r.message == "collapse_edge: parameter edge: e40 does not exist (removed or never created)");
    CollapseEdgeOptions nan;
    nan.position = glm::dvec3(std::nan(""), 0, 0);
    CHECK(library_refusal(m, [&](Transaction& tx) { collapse_edge(tx, EdgeId(0), nan); }).message ==
          "collapse_edge: parameter position: is not finite");
    // And a refusal of the link condition from the library function too.
    Mesh torus = mesh_of(test::torus_soup(4, 3));
    CHECK(library_refusal(torus, [&](Transaction& tx) {
            collapse_edge(tx, edge_between(torus, 0, 1));
          }).parameter == "edge");
  }
}

// ---- splice_corners -------------------------------------------------------------------------------------

TEST_CASE("splice_corners: one face is split and pinched, two faces are merged") {
  SUBCASE("the diagonal of a cube's face: V 7, E 12, F 7, two 2-gons") {
    // insert_edge 0-3 splits (0 2 3 1) into the triangles (0 2 3) and (3 1 0), E 13, F 7; the collapse
    // makes them 2-gons: V 7, E 12, F 7.
    Mesh m = mesh_of(test::cube_soup());
    const Params out =
        apply_exactly(m, "splice_corners", {{"corner1", CornerId(0)}, {"corner2", CornerId(2)}});
    CHECK(counts(m) == Counts{7, 12, 7});
    CHECK(out.handle<VertexId>("vertex") == V(0));
    CHECK_FALSE(m.is_alive(V(3)));
    CHECK(m.position(V(0)) == glm::dvec3(0, 0, -1));  // the midpoint of (-1,-1,-1) and (1,1,-1)
    int two_gons = 0;
    for (FaceId f : m.faces()) two_gons += m.size(f) == 2;
    CHECK(two_gons == 2);
    CHECK(signed_volume(m) > 0);
  }
  SUBCASE("opposite corners of a hexagon: two triangles meeting at the merged vertex, V-1, E+0, F+1") {
    Mesh m = mesh_of(test::prism_soup(6));
    apply_exactly(m, "splice_corners", {{"corner1", corner_of(m, 6, 1)}, {"corner2", corner_of(m, 9, 1)}});
    CHECK(counts(m) == Counts{11, 18, 9});
    int triangles = 0;
    for (FaceId f : m.faces()) triangles += m.size(f) == 3;
    CHECK(triangles == 2);  // the hexagon's halves, quads, each lost a corner
    CHECK(signed_volume(m) > 0);
  }
  SUBCASE("a cube and a tetrahedron joined at a vertex: V-1, E+0, F-1, one component") {
    const Mesh both = test::modeling_meshes().back().mesh;
    REQUIRE(validate(both).components.size() == 2);
    Mesh m = both;
    // A corner of the cube's face 0 and one of the tetrahedron's face 6 (the cube has faces 0..5).
    apply_exactly(m, "splice_corners",
                  {{"corner1", m.first_corner(FaceId(0))}, {"corner2", m.first_corner(FaceId(6))}});
    CHECK(counts(m) == Counts{11, 18, 9});
    const ValidationReport report = validate(m);
    REQUIRE(report.components.size() == 1);
    CHECK(report.components[0].genus == 0);
  }
  SUBCASE("corners of two faces of one component add a handle (genus 1)") {
    // Cube corners of 0 in (0 1 5 4) and of 7 in (2 6 7 3): no common neighbour, no face with both.
    Mesh m = mesh_of(test::cube_soup());
    apply_exactly(m, "splice_corners", {{"corner1", corner_of(m, 0, 2)}, {"corner2", corner_of(m, 7, 3)}});
    CHECK(counts(m) == Counts{7, 12, 5});
    CHECK(validate(m).components.at(0).genus == 1);
  }
  SUBCASE("a point sphere spliced onto a cube's vertex takes its place") {
    Mesh m = mesh_of(test::cube_soup());
    const VertexId sphere = m.create_vertex(glm::dvec3(3, 3, 3));
    apply_exactly(m, "splice_corners", {{"corner1", m.corner(sphere)}, {"corner2", corner_of(m, 7, 1)}});
    CHECK(counts(m) == Counts{8, 12, 6});
    CHECK(m.valence(sphere) == 3);
    CHECK(m.position(sphere) == glm::dvec3(2, 2, 2));
    CHECK(signed_volume(m) > 0);
  }
}

TEST_CASE("splice_corners: counts on the modeling meshes, for the corner pairs it accepts") {
  // Closed forms: corners of one face V-1, E+0, F+1; of two faces V-1, E+0, F-1.
  test::for_each_modeling_mesh([&](const std::string& name, const Mesh& mesh) {
    const Counts before = counts(mesh);
    int accepted = 0;
    for (CornerId c1 : mesh.corners()) {
      for (CornerId c2 : mesh.corners()) {
        if ((c1.index() * 7 + c2.index()) % 11 != 0) continue;  // a sample of the pairs
        if (refused([&] { check_splice_corners(mesh, c1, c2); })) continue;
        ++accepted;
        const Mesh m = applied(mesh, "splice_corners", {{"corner1", c1}, {"corner2", c2}});
        test::require_valid(m);
        const bool one_face = mesh.face(c1) == mesh.face(c2);
        CHECK(counts(m) == plus(before, -1, 0, one_face ? 1 : -1));
      }
    }
    // Every two vertices of a tetrahedron are joined, and those of an octahedron that are not (antipodes)
    // share all four others: nothing to splice there.
    if (name != "tetrahedron" && name != "octahedron") CHECK(accepted > 0);
  });
}

TEST_CASE("splice_corners: its checks predict those of the collapse of the edge it draws") {
  // For every pair of corners at two vertices (but a hole with a surface face, refused by splice alone): the
  // splice is accepted exactly when, once the edge is drawn, collapse_edge would accept that edge.
  std::vector<test::ModelingMesh> meshes = test::modeling_meshes();
  meshes.push_back({"grid with an inner hole", grid_with_inner_hole()});
  meshes.push_back({"hexagon with a chord", mesh_of(hexagon_with_chord_soup())});
  meshes.push_back({"bipyramid", mesh_of(bipyramid_soup())});
  Mesh with_sphere = mesh_of(test::cube_soup());
  with_sphere.create_vertex(glm::dvec3(0, 0, 3));
  meshes.push_back({"cube and a point sphere", with_sphere});
  for (auto& [name, mesh] : meshes) {
    const auto& name_ = name;  // clang 14 cannot capture a structured binding
    const auto& mesh_ = mesh;  // clang 14 cannot capture a structured binding
    CAPTURE(name_);
    const Mesh original = mesh;
    const std::uint32_t stride = mesh.num_corners() > 100 ? 3 : 1;
    int agreed = 0;
    for (CornerId c1 : original.corners()) {
      for (CornerId c2 : original.corners()) {
        if ((c1.index() + c2.index()) % stride != 0 || original.vertex(c1) == original.vertex(c2)) continue;
        const FaceId f1 = original.face(c1), f2 = original.face(c2);
        if (f1 != f2 && original.is_hole(f1) != original.is_hole(f2)) continue;
        CAPTURE(c1);
        CAPTURE(c2);
        const bool splice_refused = refused([&] { check_splice_corners(original, c1, c2); });
        Transaction tx(mesh);  // reverted at the end of the iteration
        const EdgeId e = tx.insert_edge(c1, c2).edge;
        CHECK(splice_refused == refused([&] { check_collapse_edge(mesh_, e); }));
        ++agreed;
      }
    }
    CHECK(agreed > 0);
    CHECK(mesh == original);
  }
}

TEST_CASE("splice_corners: refusals, each naming the corner, the mesh unchanged") {
  const Mesh cube = mesh_of(test::cube_soup());
  SUBCASE("two corners at one vertex") {
    const Refusal r = refusal(cube, "splice_corners",
                              {{"corner1", corner_of(cube, 0, 0)}, {"corner2", corner_of(cube, 0, 2)}});
    CHECK(r.parameter == "corner2");
    CHECK(r.message == "splice_corners: parameter corner2: " + to_string(corner_of(cube, 0, 2)) +
                           " is at v0, as corner1 is; splicing needs two vertices");
  }
  SUBCASE("vertices already joined: the collapse would make the old edge a self-loop") {
    const Refusal r = refusal(cube, "splice_corners", {{"corner1", CornerId(0)}, {"corner2", CornerId(1)}});
    CHECK(r.parameter == "corner2");
    CHECK(r.message == "splice_corners: parameter corner2: v0 and v2 are already joined by " +
                           to_string(edge_between(cube, 0, 2)) + "; the splice would make it a self-loop");
  }
  SUBCASE("the link condition: common neighbours with no triangle beside the new edge") {
    // Corners of 0 in (0 1 5 4) and of 3 in (2 6 7 3): 1 and 2 are common neighbours, the merged face is no
    // triangle.
    const Refusal r = refusal(cube, "splice_corners",
                              {{"corner1", corner_of(cube, 0, 2)}, {"corner2", corner_of(cube, 3, 3)}});
    CHECK(r.parameter == "corner2");
    CHECK(r.message ==
          "splice_corners: parameter corner2: the result would not be a manifold (the two vertices share 2 "
          "neighbours, the link condition allows 0; the edges to v1 would double up)");
  }
  SUBCASE("a face that would visit both vertices: the hexagonal prism's top, spliced through the sides") {
    const Mesh prism = mesh_of(test::prism_soup(6));
    const Refusal r = refusal(prism, "splice_corners",
                              {{"corner1", corner_of(prism, 6, 2)}, {"corner2", corner_of(prism, 9, 5)}});
    CHECK(r.parameter == "corner2");
    CHECK(r.message.find("f1 would visit both v6 and v9 away from the new edge") != std::string::npos);
  }
  SUBCASE("two boundaries meeting: a cell's diagonal from the outer boundary to the inner hole") {
    const Mesh m = grid_with_inner_hole();
    const Refusal r =
        refusal(m, "splice_corners", {{"corner1", corner_of(m, 1, 1)}, {"corner2", corner_of(m, 6, 1)}});
    CHECK(r.parameter == "corner2");
    CHECK(r.message.find("on the boundary in 2 separate places") != std::string::npos);
  }
  SUBCASE("a hole face and a surface face") {
    const Mesh grid = mesh_of(test::grid_soup(3, 2));
    const Refusal r = refusal(grid, "splice_corners",
                              {{"corner1", corner_of(grid, 0, 0)}, {"corner2", corner_of(grid, 11, 6)}});
    CHECK(r.parameter == "corner2");
    CHECK(r.message ==
          "splice_corners: parameter corner2: " + to_string(corner_of(grid, 11, 6)) +
              " is in hole face f6 and corner1 in surface face f0; the merged face would be both");
  }
  SUBCASE("removed corners and a non-finite position") {
    CHECK(refusal(cube, "splice_corners", {{"corner1", CornerId(99)}, {"corner2", CornerId(2)}}).parameter ==
          "corner1");
    Mesh m = cube;
    CHECK(library_refusal(m, [](Transaction& tx) {
            splice_corners(tx, CornerId(0), CornerId(99));
          }).message == "splice_corners: parameter corner2: c99 does not exist (removed or never created)");
    SpliceCornersOptions inf;
    inf.position = glm::dvec3(0, HUGE_VAL, 0);
    CHECK(library_refusal(m, [&](Transaction& tx) {
            splice_corners(tx, CornerId(0), CornerId(2), inf);
          }).parameter == "position");
  }
}

// ---- divide_edge ----------------------------------------------------------------------------------------

TEST_CASE("divide_edge: counts, equal spacing and the chain of edges on every modeling mesh") {
  CHECK(find_operation("divide_edge").params.at(1).name == "segments");
  CHECK(find_operation("divide_edge").params.at(1).default_value == Value(2));
  test::for_each_modeling_mesh([&](const Mesh& mesh) {
    const Counts before = counts(mesh);
    for (EdgeId e : {EdgeId(0), EdgeId(mesh.num_edges() / 2)}) {
      const glm::dvec3 a = mesh.position(mesh.from(e)), b = mesh.position(mesh.to(e));
      for (int s = 1; s <= 4; ++s) {
        CAPTURE(s);
        Mesh m = mesh;
        const Params out = apply_exactly(m, "divide_edge", {{"edge", e}, {"segments", s}});
        CHECK(counts(m) == plus(before, s - 1, s - 1, 0));
        CHECK(m.size(m.face(e, 0)) == mesh.size(mesh.face(e, 0)) + (s - 1));
        const auto vertices = out.handles<VertexId>("vertices");
        const auto chain = out.handles<EdgeId>("edges");
        REQUIRE(vertices.size() == std::size_t(s - 1));
        REQUIRE(chain.size() == std::size_t(s));
        CHECK(chain.front() == e);
        // Vertex i sits at a + (b - a) i / s, edge i joins vertex i - 1 to vertex i (from(e) and to(e) at the
        // ends).
        std::vector<VertexId> along{mesh.from(e)};
        along.insert(along.end(), vertices.begin(), vertices.end());
        along.push_back(mesh.to(e));
        for (int i = 0; i <= s; ++i)
          CHECK(glm::distance(m.position(along[i]), a + (b - a) * (double(i) / s)) < 1e-12);
        for (int i = 0; i < s; ++i) {
          CHECK(m.from(chain[i]) == along[i]);
          CHECK(m.to(chain[i]) == along[i + 1]);
        }
        if (s == 1) CHECK(m == mesh);
        if (closed(mesh)) CHECK(std::abs(signed_volume(m) - signed_volume(mesh)) < 1e-9);  // straight cuts
      }
    }
  });
}

TEST_CASE("divide_edge: refusals") {
  Mesh cube = mesh_of(test::cube_soup());
  for (long s : {0L, -3L, max_edge_segments + 1}) {
    CAPTURE(s);
    CHECK(refusal(cube, "divide_edge", {{"edge", EdgeId(0)}, {"segments", s}}).parameter == "segments");
  }
  CHECK(library_refusal(cube, [](Transaction& tx) { divide_edge(tx, EdgeId(0), 0); }).message ==
        "divide_edge: parameter segments: 0 is outside [1, 1000000]");
  CHECK(refusal(cube, "divide_edge", {{"edge", EdgeId(12)}}).parameter == "edge");
  CHECK(library_refusal(cube, [](Transaction& tx) { divide_edge(tx, EdgeId(12)); }).message ==
        "divide_edge: parameter edge: e12 does not exist (removed or never created)");
}

// ---- flip_edge ------------------------------------------------------------------------------------------

TEST_CASE("flip_edge: two triangles a-b-x and b-a-y: ab becomes xy, and flipping again gives ab back") {
  // The octahedron's edge 0 2 has the triangles (0 2 4) and (2 0 5): it becomes 4 5 (the poles).
  const Mesh octahedron = mesh_of(test::octahedron_soup());
  Mesh m = octahedron;
  const Params out = apply_exactly(m, "flip_edge", {{"edge", edge_between(octahedron, 0, 2)}});
  const EdgeId flipped = out.handle<EdgeId>("edge");
  CHECK(((m.from(flipped) == V(4) && m.to(flipped) == V(5)) ||
         (m.from(flipped) == V(5) && m.to(flipped) == V(4))));
  CHECK_FALSE(joined(m, V(0), V(2)));
  CHECK(counts(m) == counts(octahedron));
  CHECK(signed_volume(m) > 0);
  const Params again = apply_exactly(m, "flip_edge", {{"edge", flipped}});
  const EdgeId back = again.handle<EdgeId>("edge");
  CHECK(((m.from(back) == V(0) && m.to(back) == V(2)) || (m.from(back) == V(2) && m.to(back) == V(0))));
  CHECK_FALSE(joined(m, V(4), V(5)));

  // Every edge of an icosahedron: flipped twice, it joins its two vertices again.
  const Mesh icosahedron = mesh_of(test::icosahedron_soup());
  for (EdgeId e : icosahedron.edges()) {
    CAPTURE(e);
    Params first;
    Mesh once = applied(icosahedron, "flip_edge", {{"edge", e}}, &first);
    const EdgeId f = first.handle<EdgeId>("edge");
    CHECK_FALSE(joined(once, icosahedron.from(e), icosahedron.to(e)));
    Params second;
    const Mesh twice = applied(once, "flip_edge", {{"edge", f}}, &second);
    const EdgeId g = second.handle<EdgeId>("edge");
    const VertexId a = icosahedron.from(e), b = icosahedron.to(e);
    CHECK(((twice.from(g) == a && twice.to(g) == b) || (twice.from(g) == b && twice.to(g) == a)));
    test::require_valid(twice);
  }
}

TEST_CASE(
    "flip_edge: on two quads each flip turns the edge one step around their hexagon: three flips bring it "
    "back") {
  const Mesh cube = mesh_of(test::cube_soup());
  const EdgeId e = edge_between(cube, 0, 1);
  const VertexId a = cube.from(e), b = cube.to(e);
  Mesh m = cube;
  EdgeId current = e;
  for (int flip = 1; flip <= 3; ++flip) {
    CAPTURE(flip);
    current = apply_exactly(m, "flip_edge", {{"edge", current}}).handle<EdgeId>("edge");
    const bool home =
        (m.from(current) == a && m.to(current) == b) || (m.from(current) == b && m.to(current) == a);
    CHECK(home == (flip == 3));
    CHECK(counts(m) == counts(cube));
    CHECK(m.size(m.face(current, 0)) == 4);
    CHECK(m.size(m.face(current, 1)) == 4);
  }
}

TEST_CASE("flip_edge: a backward flip undoes a forward one on faces of any sizes") {
  // Two quads (cube), a quad and a pentagon (pentagonal prism), two triangles (octahedron): forward then
  // backward must give an edge between the same two vertices, with the two faces' vertex cycles as before.
  for (const auto& [name, soup] :
       {std::pair{"cube", test::cube_soup()}, std::pair{"prism", test::prism_soup(5)},
        std::pair{"octahedron", test::octahedron_soup()}}) {
    const auto& name_ = name;  // clang 14 cannot capture a structured binding
    CAPTURE(name_);
    const Mesh start = mesh_of(soup);
    for (EdgeId e : start.edges()) {
      Mesh m = start;
      const VertexId a = m.from(e), b = m.to(e);
      const std::size_t size0 = m.size(m.face(e, 0)), size1 = m.size(m.face(e, 1));
      const EdgeId forward = apply_exactly(m, "flip_edge", {{"edge", e}}).handle<EdgeId>("edge");
      const EdgeId back = apply_exactly(m, "flip_edge", {{"edge", forward}, {"direction", "backward"}})
                              .handle<EdgeId>("edge");
      CHECK(((m.from(back) == a && m.to(back) == b) || (m.from(back) == b && m.to(back) == a)));
      CHECK(counts(m) == counts(start));
      const std::size_t s0 = m.size(m.face(back, 0)), s1 = m.size(m.face(back, 1));
      CHECK(((s0 == size0 && s1 == size1) || (s0 == size1 && s1 == size0)));
    }
  }
}

TEST_CASE("flip_edge: counts on every modeling mesh, where it applies") {
  // Refused by hand: the tetrahedron's edges (x and y are always joined already) and the grid's boundary
  // edges. Everywhere else the two new ends are neither joined nor on the other face, and every vertex has at
  // least 3 edges.
  test::for_each_modeling_mesh([&](const std::string& name, const Mesh& mesh) {
    for (EdgeId e : mesh.edges()) {
      CAPTURE(e);
      const bool in_tetrahedron =
          name == "tetrahedron" || (name == "cube and tetrahedron" && mesh.from(e).index() >= 8);
      if (in_tetrahedron || is_boundary(mesh, e)) {
        const Refusal r = refusal(mesh, "flip_edge", {{"edge", e}});
        CHECK(r.parameter == "edge");
        CHECK(r.message.find(in_tetrahedron ? "already joined" : "on the boundary") != std::string::npos);
        continue;
      }
      const Mesh m = applied(mesh, "flip_edge", {{"edge", e}});
      test::require_valid(m);
      CHECK(counts(m) == counts(mesh));
      CHECK(m.num_hole_faces() == mesh.num_hole_faces());
      if (closed(mesh)) CHECK(signed_volume(m) > 0);
    }
  });
}

TEST_CASE("flip_edge: refusals, each naming the edge, the mesh unchanged") {
  SUBCASE("the same face on both sides") {
    EdgeId handle;
    const Mesh m = cube_with_handle(&handle);
    const Refusal r = refusal(m, "flip_edge", {{"edge", handle}});
    CHECK(r.parameter == "edge");
    CHECK(r.message == "flip_edge: parameter edge: " + to_string(handle) + " has " +
                           to_string(m.face(handle, 0)) + " on both sides; a flip needs two faces");
  }
  SUBCASE("a boundary edge") {
    const Mesh grid = mesh_of(test::grid_soup(3, 2));
    const Refusal r = refusal(grid, "flip_edge", {{"edge", edge_between(grid, 0, 1)}});
    CHECK(r.message == "flip_edge: parameter edge: " + to_string(edge_between(grid, 0, 1)) +
                           " is on the boundary (hole face f6); a flip would move the boundary");
  }
  SUBCASE("a 2-gon beside the edge") {
    Mesh m = mesh_of(test::cube_soup());
    const EdgeId parallel = m.insert_edge(CornerId(0), CornerId(3)).edge;
    const Refusal r = refusal(m, "flip_edge", {{"edge", parallel}});
    CHECK(r.parameter == "edge");
    CHECK(r.message.find("has 2 sides; a flip needs faces of at least 3") != std::string::npos);
  }
  SUBCASE("a self-loop: the pillow's third vertex is both new ends") {
    const Mesh m = mesh_of(pillow_soup());
    const Refusal r = refusal(m, "flip_edge", {{"edge", edge_between(m, 0, 1)}});
    CHECK(r.message == "flip_edge: parameter edge: the flipped edge would be a self-loop at v2");
  }
  SUBCASE("an end with two edges would hang on one") {
    // Cutting the cube's edge 0 1 leaves its middle vertex v8 with two edges.
    Mesh m = mesh_of(test::cube_soup());
    const EdgeId e = edge_between(m, 0, 1);
    const VertexId middle = m.subdivide_edge(e, glm::dvec3(0, -1, -1));
    const Refusal r = refusal(m, "flip_edge", {{"edge", e}});
    CHECK(r.message == "flip_edge: parameter edge: " + to_string(middle) +
                           " has 2 edges; the flip would leave it hanging on one");
  }
  SUBCASE("new ends already joined: any tetrahedron edge") {
    const Mesh m = mesh_of(test::tetrahedron_soup());
    const Refusal r = refusal(m, "flip_edge", {{"edge", edge_between(m, 0, 1)}});
    // Edge 0 1 has the triangles (0 1 2) and (0 3 1): the new ends 2 and 3 are joined already.
    CHECK(r.message == "flip_edge: parameter edge: v2 and v3 are already joined by " +
                           to_string(edge_between(m, 2, 3)) + "; the flipped edge would double it");
  }
  SUBCASE("a new end already on the other face") {
    // Edge 0 1: side 0 in the hexagon (0 1 2 3 4 5) gives x = 2, side 1 in (1 0 4) gives y = 4, which the
    // hexagon visits already.
    const Mesh m = mesh_of(hexagon_with_chord_soup());
    const Refusal r = refusal(m, "flip_edge", {{"edge", edge_between(m, 0, 1)}});
    CHECK(r.message ==
          "flip_edge: parameter edge: v4 is on f0 already; the face would pass through it twice");
  }
  SUBCASE("a removed edge") {
    Mesh m = mesh_of(test::cube_soup());
    CHECK(refusal(m, "flip_edge", {{"edge", EdgeId(12)}}).parameter == "edge");
    CHECK(library_refusal(m, [](Transaction& tx) { flip_edge(tx, EdgeId(12)); }).message ==
          "flip_edge: parameter edge: e12 does not exist (removed or never created)");
  }
}

// ---- make_hole and fill_hole ----------------------------------------------------------------------------

TEST_CASE("make_hole and fill_hole: every surface face of every modeling mesh, and back") {
  test::for_each_modeling_mesh([&](const Mesh& mesh) {
    for (FaceId f : mesh.faces()) {
      if (mesh.is_hole(f)) continue;
      CAPTURE(f);
      Mesh m = mesh;
      apply_exactly(m, "make_hole", {{"face", f}});
      CHECK(counts(m) == counts(mesh));
      CHECK(m.num_hole_faces() == mesh.num_hole_faces() + 1);
      CHECK(m.is_hole(f));
      apply_exactly(m, "fill_hole", {{"face", f}});
      CHECK(m == mesh);
    }
  });
  // The grid's boundary loop filled: a closed disk of 7 faces, every one a surface face.
  Mesh grid = mesh_of(test::grid_soup(3, 2));
  apply_exactly(grid, "fill_hole", {{"face", FaceId(6)}});
  CHECK(grid.num_hole_faces() == 0);
  CHECK(counts(grid) == Counts{12, 17, 7});
}

TEST_CASE("make_hole and fill_hole: refusals, each naming the face, the mesh unchanged") {
  Mesh grid = mesh_of(test::grid_soup(3, 2));
  CHECK(refusal(grid, "make_hole", {{"face", FaceId(6)}}).message ==
        "make_hole: parameter face: f6 is a hole already");
  CHECK(refusal(grid, "fill_hole", {{"face", FaceId(0)}}).message ==
        "fill_hole: parameter face: f0 is not a hole");
  const VertexId sphere = grid.create_vertex(glm::dvec3(0, 0, 5));
  const FaceId sphere_face = grid.face(grid.corner(sphere));
  CHECK(refusal(grid, "make_hole", {{"face", sphere_face}}).message ==
        "make_hole: parameter face: " + to_string(sphere_face) + " is the face of the point sphere " +
            to_string(sphere) + ", not a surface face");
  CHECK(refusal(grid, "make_hole", {{"face", FaceId(40)}}).parameter == "face");
  CHECK(library_refusal(grid, [](Transaction& tx) { make_hole(tx, FaceId(40)); }).message ==
        "make_hole: parameter face: f40 does not exist (removed or never created)");
  CHECK(library_refusal(grid, [](Transaction& tx) { fill_hole(tx, FaceId(1)); }).parameter == "face");
}

// ---- all together ---------------------------------------------------------------------------------------

TEST_CASE("local editing: random sequences of the six operations on every modeling mesh") {
  // Handles drawn among the live ones: each operation either is refused with a ParameterError and changes
  // nothing, or leaves a valid mesh; the checks must leave the kernel nothing to refuse (a TopologyError
  // would escape here). Undoing everything gives the mesh back.
  std::mt19937 random(2024);
  const auto pick = [&](std::uint32_t n) {
    return std::uniform_int_distribution<std::uint32_t>(0, n - 1)(random);
  };
  test::for_each_modeling_mesh([&](const Mesh& mesh) {
    Editor ed;
    ed.set_mesh(mesh);
    int accepted = 0;
    for (int step = 0; step < 300; ++step) {
      const Mesh& m = ed.mesh();
      const auto live = [&]<class H>(H) {
        for (int tries = 0; tries < 100; ++tries) {
          const H h(pick(m.capacity(element_kind_v<H>)));
          if (m.is_alive(h)) return h;
        }
        return H(0);
      };
      Params p;
      std::string op;
      switch (pick(6)) {
        case 0:
          op = "collapse_edge";
          p = {{"edge", live(EdgeId())}, {"cleanup", pick(2) == 1}};
          break;
        case 1:
          op = "splice_corners";
          p = {{"corner1", live(CornerId())}, {"corner2", live(CornerId())}};
          break;
        case 2:
          op = "divide_edge";
          p = {{"edge", live(EdgeId())}, {"segments", 1 + pick(3)}};
          break;
        case 3:
          op = "flip_edge";
          p = {{"edge", live(EdgeId())}};
          break;
        case 4:
          op = "make_hole";
          p = {{"face", live(FaceId())}};
          break;
        default:
          op = "fill_hole";
          p = {{"face", live(FaceId())}};
          break;
      }
      CAPTURE(step);
      CAPTURE(op);
      const Mesh before = m;
      try {
        ed.apply(op, p);
        ++accepted;
      } catch (const ParameterError&) {
        CHECK(ed.mesh() == before);
        continue;
      }
      test::require_valid(ed.mesh());
    }
    CHECK(accepted > 30);
    while (ed.can_undo() && ed.undo_history().size() > 1) ed.undo();
    CHECK(ed.mesh() == mesh);
  });
}
