// Kobbelt's sqrt(3): counts, valences, topology, the documented output order (which is the edge flip),
// positions derived by hand on the tetrahedron and the octahedron and re-derived from the published rules on
// an irregular mesh, two steps as a 1-to-9 refinement, affine invariance and the errors (holes included:
// there is no boundary rule). (Agreement with CGAL's implementation is in tests/oracle.)

#include <doctest/doctest.h>

#include <cmath>
#include <numbers>
#include <set>

#include <dlfl/errors.h>
#include <dlfl/schemes/sqrt3.h>
#include "triangle_meshes.h"

using namespace dlfl;
using namespace dlfl::test;

namespace {

// F new vertices (the face points), E' = 3E (every old edge flipped, three spokes per triangle: E + 3F = 3E
// as 3F = 2E), F' = 3F triangles; old vertices keep their valence, face points have 6 (three corners, three
// flipped edges).
void check_counts(const Mesh& in, bool solid = true) {
  const std::size_t E = in.num_edges(), F = in.num_faces();
  check_triangle_step(
      in, [](const Mesh& m, Origins* o) { return sqrt3(m, o); }, {F, 3 * E, 3 * F}, solid);
}

}  // namespace

TEST_CASE("sqrt3: the tetrahedron and the octahedron by hand") {
  {
    // Regular tetrahedron centred at the origin; the three other vertices of v sum to -v. a_3 =
    // (4 - 2 cos(2 pi / 3)) / 9 = 5/9, so v moves to (4/9) v + (5/27)(-v) = 7/27 v. The face opposite w has
    // centroid (-w) / 3.
    const Mesh in = test::tetrahedron();
    const Mesh out = sqrt3(in);
    for (VertexId v : in.vertices()) CHECK(close(out.position(v), 7.0 / 27.0 * in.position(v), 1e-15));
    for (FaceId f : in.faces()) {
      glm::dvec3 opposite(0.0);  // the vertex not on f
      for (VertexId v : in.vertices()) {
        bool on_f = false;
        for (VertexId x : face_vertices(in, f)) on_f = on_f || x == v;
        if (!on_f) opposite = in.position(v);
      }
      CHECK(close(out.position(VertexId(4 + f.index())), -opposite / 3.0, 1e-15));
    }
  }
  {
    // Octahedron: a_4 = 4/9; the four neighbours of an axis point sum to 0, so it moves to 5/9 of itself. The
    // face points are the centroids (+-1, +-1, +-1) / 3.
    const Mesh in = build_mesh(octahedron_soup());
    const Mesh out = sqrt3(in);
    for (VertexId v : in.vertices()) CHECK(close(out.position(v), 5.0 / 9.0 * in.position(v), 1e-15));
    for (FaceId f : in.faces()) {
      const glm::dvec3 p = out.position(VertexId(6 + f.index()));
      CHECK(close(glm::abs(p), glm::dvec3(1.0 / 3.0), 1e-15));
    }
  }
}

TEST_CASE("sqrt3: the published rules, the edge flip and the documented output order on an irregular mesh") {
  const Mesh in = irregular_torus();
  const Mesh out = sqrt3(in);
  const std::uint32_t V = in.num_vertices();
  for (VertexId v : in.vertices()) {
    const double n = in.valence(v), a = kobbelt_a(n);
    CHECK(close(out.position(v), (1.0 - a) * in.position(v) + a / n * neighbour_sum(in, v)));
  }
  for (FaceId f : in.faces()) CHECK(close(out.position(VertexId(V + f.index())), centroid(in, f)));
  // Triangle k is (vertex(k), face point across edge(k), face point of face(k)).
  for (CornerId c : in.corners()) {
    CHECK(face_vertices(out, FaceId(c.index())) ==
          std::vector<VertexId>{in.vertex(c), VertexId(V + in.face(in.opposite(c)).index()),
                                VertexId(V + in.face(c).index())});
  }
  // The flip: no two old vertices are joined any more; every old edge is replaced by the edge between the
  // face points on its two sides, and each face point is joined to its triangle's three corners.
  std::set<std::pair<std::uint32_t, std::uint32_t>> edges;
  for (EdgeId e : out.edges()) {
    const auto a = out.from(e).index(), b = out.to(e).index();
    edges.insert({std::min(a, b), std::max(a, b)});
    CHECK(std::max(a, b) >= V);
  }
  std::set<std::pair<std::uint32_t, std::uint32_t>> expected;
  for (EdgeId e : in.edges()) {
    const auto a = V + in.face(e, 0).index(), b = V + in.face(e, 1).index();
    expected.insert({std::min(a, b), std::max(a, b)});
  }
  for (CornerId c : in.corners()) expected.insert({in.vertex(c).index(), V + in.face(c).index()});
  CHECK(edges == expected);
}

TEST_CASE("sqrt3: two steps refine every triangle into nine") {
  for (const PolygonSoup& soup : {icosahedron_soup(), triangulated(torus_soup(5, 4))}) {
    const Mesh in = build_mesh(soup);
    const Mesh twice = sqrt3(sqrt3(in));
    check_valid_same_genus(in, twice);
    CHECK(twice.num_faces() == 9 * in.num_faces());
    CHECK(twice.num_edges() == 9 * in.num_edges());
    // V'' = V' + F' = (V + F) + 3F.
    CHECK(twice.num_vertices() == in.num_vertices() + 4 * in.num_faces());
  }
}

TEST_CASE("sqrt3: counts, valences and genus on triangle meshes of several genera") {
  for (const PolygonSoup& soup : closed_triangle_soups()) check_counts(build_mesh(soup));
}

TEST_CASE("sqrt3: affine invariance") {
  check_affine_invariance(build_mesh(icosahedron_soup()), [](const Mesh& m) { return sqrt3(m); });
  check_affine_invariance(build_mesh(triangulated(genus_soup(2))), [](const Mesh& m) { return sqrt3(m); });
}

TEST_CASE(
    "sqrt3: non-triangles, point spheres and (with boundary=hole) every hole are refused, naming them") {
  // A tombstone face before the offending face: the square pyramid's base split by a diagonal and joined
  // again (one of its triangles is now removed), so the quad base is not at its compacted index.
  Mesh m = build_mesh(triangle_soup({{-1, -1, 0}, {1, -1, 0}, {1, 1, 0}, {-1, 1, 0}, {0, 0, 1}},
                                    {{0, 1, 4}, {1, 2, 4}, {2, 3, 4}, {3, 0, 4}, {0, 3, 2}, {0, 2, 1}}));
  EdgeId diagonal;
  for (CornerId c : m.corners(FaceId(4)))
    if (m.face(m.opposite(c)) == FaceId(5)) diagonal = m.edge(c);
  const DeleteEdgeResult merged = m.delete_edge(diagonal);
  const FaceId quad = merged.removed_face == FaceId(4) ? FaceId(5) : FaceId(4);
  REQUIRE(m.size(quad) == 4);
  CHECK(error_message<TopologyError>([&] { sqrt3(m); }) ==
        "sqrt3: " + to_string(quad) + " has 4 corners; sqrt(3) subdivision needs triangles");

  // With boundary=hole, holes, even triangular ones: that rule has no meaning for sqrt(3)'s flips.
  PolygonSoup open = tetrahedron_soup();
  open.offsets.pop_back();
  open.indices.resize(9);
  CHECK(
      error_message<TopologyError>([&] { sqrt3(build_mesh(open), {BoundaryRule::hole}); }) ==
      "sqrt3: f3 is a hole (a boundary loop) with 3 corners; sqrt(3) subdivision with boundary=hole needs a "
      "closed triangle mesh (boundary=curve takes open meshes)");

  Mesh sphere = test::tetrahedron();
  sphere.create_vertex({3, 3, 3});
  CHECK(error_message<TopologyError>([&] { sqrt3(sphere); }) == "sqrt3: v4 is a point sphere (no edge)");
}

TEST_CASE("sqrt3: through the editor, its undo and the log") {
  const Mesh in = build_mesh(triangulated(torus_soup(4, 3)));
  check_editor_and_log(in, "sqrt3", {}, sqrt3(sqrt3(in)), test::cube());
}

TEST_CASE("sqrt3: the two-triangle pillow flips into three edges between its two face points") {
  // Every old edge of the pillow has the same two triangles on its sides, so all three flipped edges join the
  // same two face points: parallel edges, which the kernel holds.
  const Mesh in = build_mesh(pillow_soup());
  check_counts(in, false);
  const Mesh out = sqrt3(in);
  std::size_t between_face_points = 0;
  for (EdgeId e : out.edges()) between_face_points += out.from(e).index() >= 3 && out.to(e).index() >= 3;
  CHECK(between_face_points == 3);
  // a_2 = (4 + 2) / 9 = 2/3: a vertex moves to S/3 + (1/3)(sum of its two neighbours).
  const glm::dvec3 sum = in.position(VertexId(0)) + in.position(VertexId(1)) + in.position(VertexId(2));
  for (VertexId v : in.vertices()) CHECK(close(out.position(v), sum / 3.0, 1e-15));
  CHECK(sqrt3(Mesh{}).empty());
}
