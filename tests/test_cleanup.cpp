// The cleanup and shape operations (docs/modeling.md, "Cleanup and shape"): dissolve_coplanar,
// remove_2gons, remove_valence2, planarize, smooth and spheralize. Counts on the modeling meshes and on
// meshes built for the case, derived by hand in the comments; positions computed by hand; the validator, the
// Euler characteristic, hole faces and orientation (signed volume); exact undo, redo and log replay through
// the editor; every refusal, naming its parameter, with the mesh unchanged.

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <limits>
#include <random>
#include <set>
#include <string>
#include <tuple>
#include <vector>

#include <dlfl/build_mesh.h>
#include <dlfl/create_face_manifold.h>
#include <dlfl/errors.h>
#include <dlfl/geometry.h>
#include <dlfl/history/editor.h>
#include <dlfl/history/oplog.h>
#include <dlfl/mesh_hash.h>
#include <dlfl/navigation.h>
#include <dlfl/operations/collapse_edge.h>
#include <dlfl/operations/dissolve_coplanar.h>
#include <dlfl/operations/divide_edge.h>
#include <dlfl/operations/operation.h>
#include <dlfl/operations/planarize.h>
#include <dlfl/operations/remove_2gons.h>
#include <dlfl/operations/remove_valence2.h>
#include <dlfl/operations/smooth.h>
#include <dlfl/operations/spheralize.h>
#include <dlfl/schemes/scheme_registry.h>

#include "modeling_checks.h"
#include "modeling_meshes.h"
#include "test_helpers.h"

using namespace dlfl;

namespace {

using test::Applied;
using test::apply_and_check;
using test::Delta;
using test::euler_characteristic;
using test::refused_parameter;
using test::signed_volume;

bool is_grid(const std::string& name) { return name == "open grid 3x2"; }
bool is_slab(const std::string& name) { return name == "genus 2" || name == "genus 3"; }

// A face visiting no vertex twice.
bool simple(const Mesh& m, FaceId f) {
  std::set<std::uint32_t> seen;
  for (VertexId v : vertices(m, f)) {
    if (!seen.insert(v.index()).second) return false;
  }
  return true;
}

// Two n-gons on the same n vertices (a regular polygon in the plane z = 0), one each way round: every
// vertex has valence 2. V = n, E = n, F = 2.
Mesh pillow(int n) {
  PolygonSoup s;
  std::vector<std::uint32_t> up, down;
  for (int i = 0; i < n; ++i) {
    const double a = 2 * std::numbers::pi * i / n;
    s.positions.push_back({std::cos(a), std::sin(a), 0.0});
    up.push_back(std::uint32_t(i));
    down.push_back(std::uint32_t(n - 1 - i));
  }
  s.add_face(up);
  s.add_face(down);
  return build_mesh(s);
}

// The two 2-gons on two points (CREATEFACEMANIFOLD of two positions): V 2, E 2, F 2.
Mesh two_gon_pillow() {
  Mesh m;
  const std::vector<glm::dvec3> points = {{0, 0, 0}, {1, 0, 0}};
  create_face_manifold(m, points);
  return m;
}

// The cube at +-1 cut into 24 quads: Catmull-Clark once, every vertex then pushed radially back onto the
// cube (corners to the corners, edge points to the edge midpoints, face points stay at the face centres).
// V 26, E 48, F 24, every face in a plane of the cube.
Mesh subdivided_cube() {
  Mesh m = apply_scheme(build_mesh(test::cube_soup()), "catmull-clark");
  for (VertexId v : m.vertices()) {
    const glm::dvec3 p = m.position(v);
    m.set_position(v, p / std::max({std::abs(p.x), std::abs(p.y), std::abs(p.z)}));
  }
  return m;
}

VertexId vertex_at(const Mesh& m, const glm::dvec3& p) {
  for (VertexId v : m.vertices()) {
    if (m.position(v) == p) return v;
  }
  FAIL("no vertex at the point");
  return VertexId();
}

void check_near(const glm::dvec3& a, const glm::dvec3& b, double tolerance = 1e-12) {
  CAPTURE(a.x);
  CAPTURE(a.y);
  CAPTURE(a.z);
  CAPTURE(b.x);
  CAPTURE(b.y);
  CAPTURE(b.z);
  CHECK(glm::length(a - b) < tolerance);
}

// Positions of every vertex, by handle.
std::vector<glm::dvec3> positions(const Mesh& m) {
  std::vector<glm::dvec3> out;
  for (VertexId v : m.vertices()) out.push_back(m.position(v));
  return out;
}

}  // namespace

// ---- remove_valence2 ------------------------------------------------------------------------------------

TEST_CASE("remove_valence2: the modeling meshes") {
  // Every vertex of the polyhedra, prisms, torus and slabs has 3 or more edges. The open grid's four
  // corners have two (to (1,0) and (0,1), not joined to each other): each goes, its corner quad becomes a
  // triangle and the hole face loses a corner: V-4, E-4, F+0.
  test::for_each_modeling_mesh([&](const std::string& name, const Mesh& mesh) {
    const long k = is_grid(name) ? 4 : 0;
    const Applied r = apply_and_check(mesh, "remove_valence2", {}, {-k, -k, 0});
    CHECK(r.out.integer("vertices_removed") == k);
    if (is_grid(name)) {
      long triangles = 0;
      for (FaceId f : surface_faces(r.mesh)) triangles += r.mesh.size(f) == 3;
      CHECK(triangles == 4);
      for (FaceId f : r.mesh.faces()) {
        if (r.mesh.is_hole(f)) CHECK(r.mesh.size(f) == 10 - 4);
      }
    }
  });
}

TEST_CASE("remove_valence2: divided edges are joined back; pillows stop at two 2-gons") {
  // Three cube edges divided into 4 (V+3 each) give back the cube: V-9, E-9, the corners where they were.
  Mesh cube = build_mesh(test::cube_soup());
  Mesh divided = cube;
  {
    Transaction tx(divided);
    for (std::uint32_t e : {0u, 5u, 9u}) divide_edge(tx, EdgeId(e), 4);
    tx.commit();
  }
  REQUIRE(divided.num_vertices() == 8 + 9);
  const Applied r = apply_and_check(divided, "remove_valence2", {}, {-9, -9, 0});
  for (FaceId f : r.mesh.faces()) CHECK(r.mesh.size(f) == 4);
  std::vector<glm::dvec3> corners = positions(r.mesh), expected = positions(cube);
  CHECK(corners == expected);  // the corners keep their handles, which come first

  // A pillow of two n-gons: joining a vertex gives the pillow of two (n-1)-gons, down to the triangles,
  // where the third side is the edge the join doubles: two 2-gons. Their two vertices have one neighbour
  // twice: left. n = 5: V 5 -> 2, E 5 -> 2, F 2.
  const Applied p = apply_and_check(pillow(5), "remove_valence2", {}, {-3, -3, 0});
  for (FaceId f : p.mesh.faces()) CHECK(p.mesh.size(f) == 2);
  // Two 2-gons already: nothing to join.
  apply_and_check(two_gon_pillow(), "remove_valence2", {}, {0, 0, 0});
}

TEST_CASE("remove_valence2: edges that run the same way at the vertex are turned round first") {
  // A vertex v at the centre of a cube face a, p, b, q, drawn from a (insert_edge from a's corner to v's
  // point sphere) and from b: both edges start at a or b on side 0, so both end at v, which
  // unsubdivide_edge cannot join as they are. v has valence 2 between the quads a, p, b, v and b, q, a, v;
  // joined, it leaves the diagonal a-b: V-1, E-1, F+0, two triangles. The same on a face made a hole
  // first: both parts are holes, and stay holes.
  for (const bool hole : {false, true}) {
    CAPTURE(hole);
    Mesh m = build_mesh(test::cube_soup());
    const FaceId f(0);
    if (hole) m.set_hole(f, true);
    const CornerId a = m.first_corner(f), b = m.next(m.next(a));
    const VertexId v = m.create_vertex(face_centroid(m, f));
    m.insert_edge(a, m.corner(v));
    m.insert_edge(b, m.corner(v));
    REQUIRE(m.valence(v) == 2);
    for (EdgeId e : edges(m, v)) REQUIRE(m.to(e) == v);
    const Applied r = apply_and_check(m, "remove_valence2", {}, {-1, -1, 0});
    CHECK(r.out.integer("vertices_removed") == 1);
    CHECK(r.mesh.num_hole_faces() == (hole ? 2u : 0u));
    long triangles = 0;
    for (FaceId g : r.mesh.faces()) triangles += r.mesh.size(g) == 3;
    CHECK(triangles == 2);
    CHECK(find_edge(r.mesh, m.vertex(a), m.vertex(b)).valid());
  }
}

TEST_CASE("remove_valence2: a join that would double an edge with no 2-gon between is left") {
  // The 4 x 3 torus: the vertex (0,0) with its two edges along the big circle deleted has valence 2; its
  // neighbours (0,1) and (0,2) are joined by an edge of the small circle, which is on none of its faces
  // (hexagons now). Joining would make a second edge (0,1)-(0,2) with no face between: left, nothing done.
  Mesh torus = build_mesh(test::torus_soup(4, 3));
  const VertexId v(0);
  for (int round = 0; round < 2; ++round) {
    for (EdgeId e : edges(torus, v)) {
      const VertexId w = torus.from(e) == v ? torus.to(e) : torus.from(e);
      if (w == VertexId(3) || w == VertexId(9)) {  // (1,0) and (3,0)
        torus.delete_edge(e);
        break;
      }
    }
  }
  REQUIRE(torus.valence(v) == 2);
  REQUIRE(find_edge(torus, VertexId(1), VertexId(2)).valid());
  apply_and_check(torus, "remove_valence2", {}, {0, 0, 0});
}

// ---- remove_2gons ---------------------------------------------------------------------------------------

TEST_CASE("remove_2gons: the modeling meshes have none; collapsed triangles lose theirs") {
  test::for_each_modeling_mesh([&](const Mesh& mesh) {
    CHECK(apply_and_check(mesh, "remove_2gons", {}, {}).out.integer("two_gons_removed") == 0);
  });
  // An octahedron edge collapsed without cleanup: its two triangles become 2-gons (V 5, E 11, F 8). Each is
  // merged into the triangle across one of its edges: E-2, F-2, which is what collapse_edge's cleanup
  // gives (V-1, E-1-2, F-2 from the octahedron).
  Mesh octahedron = build_mesh(test::octahedron_soup());
  {
    Transaction tx(octahedron);
    collapse_edge(tx, EdgeId(0));
    tx.commit();
  }
  const Applied r = apply_and_check(octahedron, "remove_2gons", {}, {0, -2, -2});
  CHECK(r.out.integer("two_gons_removed") == 2);
  CHECK(r.mesh.num_vertices() == 5);
  CHECK(r.mesh.num_edges() == 9);
  CHECK(r.mesh.num_faces() == 6);
  for (FaceId f : r.mesh.faces()) CHECK(r.mesh.size(f) == 3);
}

TEST_CASE("remove_2gons: a 2-gon beside a hole merges into the surface face; pillows and hole 2-gons stay") {
  // The tetrahedron with an edge collapsed: two 2-gons, each between two triangles (V 3, E 5, F 4). One
  // triangle across a 2-gon is made a hole: that 2-gon merges across its other edge, the hole stays.
  Mesh tet = build_mesh(test::tetrahedron_soup());
  {
    Transaction tx(tet);
    collapse_edge(tx, EdgeId(0));
    tx.commit();
  }
  FaceId two_gon;
  for (FaceId f : tet.faces()) {
    if (tet.size(f) == 2) two_gon = f;
  }
  REQUIRE(two_gon.valid());
  const FaceId across = tet.face(tet.opposite(tet.first_corner(two_gon)));
  REQUIRE(tet.size(across) == 3);
  tet.set_hole(across, true);
  const Applied r = apply_and_check(tet, "remove_2gons", {}, {0, -2, -2});
  CHECK(r.mesh.num_hole_faces() == 1);
  for (FaceId f : r.mesh.faces()) CHECK(r.mesh.size(f) == 3);

  // Two 2-gons on the same two edges (each the face across both edges of the other): left.
  apply_and_check(two_gon_pillow(), "remove_2gons", {}, {0, 0, 0});
  // A hole 2-gon between two triangles (one 2-gon of the collapsed tetrahedron made a hole) is left: one
  // removed.
  Mesh holed = build_mesh(test::tetrahedron_soup());
  {
    Transaction tx(holed);
    collapse_edge(tx, EdgeId(0));
    tx.commit();
  }
  for (FaceId f : holed.faces()) {
    if (holed.size(f) == 2) {
      holed.set_hole(f, true);
      break;
    }
  }
  CHECK(apply_and_check(holed, "remove_2gons", {}, {0, -1, -1}).out.integer("two_gons_removed") == 1);
  // Both triangles of the collapsed tetrahedron made holes: each 2-gon has a hole across both its edges, a
  // sliver between boundary loops: both stay.
  Mesh slivers = build_mesh(test::tetrahedron_soup());
  {
    Transaction tx(slivers);
    collapse_edge(tx, EdgeId(0));
    tx.commit();
  }
  for (FaceId f : slivers.faces()) {
    if (slivers.size(f) == 3) slivers.set_hole(f, true);
  }
  REQUIRE(slivers.num_hole_faces() == 2);
  CHECK(apply_and_check(slivers, "remove_2gons", {}, {}).out.integer("two_gons_removed") == 0);
}

// ---- dissolve_coplanar ----------------------------------------------------------------------------------

TEST_CASE("dissolve_coplanar: the modeling meshes") {
  // Polyhedra, prisms and the torus: no two faces sharing an edge are coplanar (dihedral angles of at
  // least 45 degrees), nothing changes. The open grid (V 12, E 17, F 6 + 1 hole): its six quads, one
  // plane, merge into one quad (5 merges); the two interior edges left dangling go with the two interior
  // vertices, and the six boundary vertices between corners, left with two edges along the border, are
  // joined away: V 4, E 4, F 2 (the quad and the hole).
  test::for_each_modeling_mesh([&](const std::string& name, const Mesh& mesh) {
    if (is_slab(name)) return;
    const Delta d = is_grid(name) ? Delta{-8, -13, -5} : Delta{};
    const Applied r = apply_and_check(mesh, "dissolve_coplanar", {}, d);
    if (is_grid(name)) {
      CHECK(r.out.integer("edges_merged") == 5);
      CHECK(r.out.integer("edges_peeled") == 2);
      CHECK(r.out.integer("vertices_joined") == 6);
      for (FaceId f : r.mesh.faces()) CHECK(r.mesh.size(f) == 4);
    }
  });
}

TEST_CASE("dissolve_coplanar: the genus slabs keep their walls apart and their tops simple") {
  // A slab of genus g: the top (and the bottom) is a (2g+1) x 3 grid with g cells missing, a flat region
  // with g holes, which no simple face can be. It ends as simple faces, none of which can merge with a
  // neighbour; F simple disks glued along C chains make a disk with g holes when F - C = 1 - g, and every
  // pair of neighbours sharing two chains or more gives F - 1 <= C / 2: so 2 <= F <= g + 1. Each of the
  // four outer walls is a strip of quads in one plane: one face each. The 4g walls of the holes lie in no
  // plane with a neighbour: they stay.
  test::for_each_modeling_mesh([&](const std::string& name, const Mesh& mesh) {
    if (!is_slab(name)) return;
    const long g = name == "genus 2" ? 2 : 3;
    Editor ed;
    ed.set_mesh(mesh);
    ed.apply("dissolve_coplanar");
    const Mesh& after = ed.mesh();
    test::require_valid(after);
    CHECK(euler_characteristic(after) == euler_characteristic(mesh));
    CHECK((signed_volume(after) > 0) == (signed_volume(mesh) > 0));
    long top = 0, bottom = 0, outer_walls = 0, hole_walls = 0;
    const double nx = double(2 * g + 1);
    for (FaceId f : surface_faces(after)) {
      CHECK(simple(after, f));
      const glm::dvec3 n = face_normal(after, f), c = face_centroid(after, f);
      if (n.z > 0.5) {
        ++top;
      } else if (n.z < -0.5) {
        ++bottom;
      } else if (c.x == 0 || c.x == nx || c.y == 0 || c.y == 3) {
        ++outer_walls;
      } else {
        ++hole_walls;
        CHECK(after.size(f) == 4);
      }
    }
    CHECK(top >= 2);
    CHECK(top <= g + 1);
    CHECK(bottom >= 2);
    CHECK(bottom <= g + 1);
    CHECK(outer_walls == 4);
    CHECK(hole_walls == 4 * g);
    REQUIRE(ed.undo());
    CHECK(ed.mesh() == mesh);
    REQUIRE(ed.redo());
    const auto path = test::scratch("dissolve_slab.log.json");
    write_log(ed, path);
    CHECK(mesh_hash(replay_log_file(path).mesh()) == mesh_hash(ed.mesh()));
  });
}

TEST_CASE("dissolve_coplanar: a subdivided cube dissolves back to the cube") {
  // 24 quads, four in each plane around a face point: 18 merges (3 per face), the fourth spoke of each face
  // peeled with its face point (6), and the 12 edge midpoints left with two edges joined: V 26 -> 8,
  // E 48 -> 12, F 24 -> 6.
  const Mesh start = subdivided_cube();
  REQUIRE(start.num_vertices() == 26);
  const Applied r = apply_and_check(start, "dissolve_coplanar", {}, {-18, -36, -18});
  CHECK(r.out.integer("edges_merged") == 18);
  CHECK(r.out.integer("edges_peeled") == 6);
  CHECK(r.out.integer("vertices_joined") == 12);
  for (FaceId f : r.mesh.faces()) CHECK(r.mesh.size(f) == 4);
  for (VertexId v : r.mesh.vertices()) {
    const glm::dvec3 p = r.mesh.position(v);
    CHECK(std::abs(p.x) == 1);
    CHECK(std::abs(p.y) == 1);
    CHECK(std::abs(p.z) == 1);
  }
  check_near(glm::dvec3(signed_volume(r.mesh)), glm::dvec3(8.0));
}

TEST_CASE("dissolve_coplanar: the angle decides") {
  // A 2 x 1 grid folded 5 degrees along its middle edge (the vertices at x = 2 lifted by tan 5 degrees):
  // V 6, E 7, F 2 + hole. Below 5 degrees nothing changes; above, the two quads merge (one edge), and the
  // middle edge's two ends, left with two edges each, are joined: V 4, E 4, F 2.
  Mesh folded = build_mesh(test::grid_soup(2, 1));
  const double lift = std::tan(5.0 * std::numbers::pi / 180.0);
  for (VertexId v : folded.vertices()) {
    const glm::dvec3 p = folded.position(v);
    if (p.x == 2) folded.set_position(v, {p.x, p.y, lift});
  }
  apply_and_check(folded, "dissolve_coplanar", {{"angle_degrees", 4.9}}, {});
  apply_and_check(folded, "dissolve_coplanar", {}, {});
  const Applied r = apply_and_check(folded, "dissolve_coplanar", {{"angle_degrees", 5.1}}, {-2, -3, -1});
  CHECK(r.out.integer("edges_merged") == 1);
  CHECK(r.out.integer("vertices_joined") == 2);
}

TEST_CASE("dissolve_coplanar: refusals") {
  const Mesh cube = build_mesh(test::cube_soup());
  for (double a : {0.0, -1.0, 180.5, std::numeric_limits<double>::infinity(),
                   std::numeric_limits<double>::quiet_NaN()}) {
    CAPTURE(a);
    CHECK(refused_parameter(cube, "dissolve_coplanar", {{"angle_degrees", a}}) == "angle_degrees");
  }
  // The library function refuses too, before changing anything.
  Mesh m = subdivided_cube();
  const Mesh before = m;
  {
    Transaction tx(m);
    const std::string message = test::error_message<ParameterError>([&] { dissolve_coplanar(tx, {0.0}); });
    CHECK(message.rfind("dissolve_coplanar: parameter angle_degrees", 0) == 0);
  }
  CHECK(m == before);
  // 180 degrees is allowed.
  Editor ed;
  ed.set_mesh(cube);
  CHECK_NOTHROW(ed.apply("dissolve_coplanar", {{"angle_degrees", 180.0}}));
}

// ---- planarize ------------------------------------------------------------------------------------------

TEST_CASE("planarize: planar meshes do not move") {
  // Every face of the modeling meshes is planar (the torus's quads are isosceles trapezoids): the measure
  // is 0 up to rounding, and no vertex is written.
  test::for_each_modeling_mesh([&](const Mesh& mesh) {
    CHECK(nonplanarity(mesh) <= 1e-12);
    const Applied r = apply_and_check(mesh, "planarize", {}, {});
    CHECK(r.mesh == mesh);
    CHECK(r.out.number("nonplanarity_before") <= 1e-12);
    CHECK(r.out.number("nonplanarity_after") <= 1e-12);
    CHECK(r.out.integer("iterations_run") == 0);
  });
}

TEST_CASE("planarize: a skew quad's measure and its flattening") {
  // A pillow of two quads on (1,0,h), (0,1,-h), (-1,0,h), (0,-1,-h): centroid 0, covariance
  // diag(2, 2, 4h^2), so for small h the least-squares plane is z = 0, each corner h from it; each edge
  // has length sqrt(2 + 4h^2). Non-planarity h / sqrt(2 + 4h^2). Both faces have that plane, so one round
  // puts every vertex on it.
  const double h = 0.1;
  PolygonSoup s;
  s.positions = {{1, 0, h}, {0, 1, -h}, {-1, 0, h}, {0, -1, -h}};
  s.add_face({0, 1, 2, 3});
  s.add_face({3, 2, 1, 0});
  const Mesh skew = build_mesh(s);
  CHECK(nonplanarity(skew) == doctest::Approx(h / std::sqrt(2 + 4 * h * h)).epsilon(1e-12));
  // The pillow encloses no volume (its two fans cancel only when flat): no orientation to compare.
  const Applied r = apply_and_check(skew, "planarize", {{"iterations", 1}}, {}, false);
  CHECK(r.out.number("nonplanarity_before") == doctest::Approx(h / std::sqrt(2 + 4 * h * h)).epsilon(1e-12));
  CHECK(r.out.number("nonplanarity_after") <= 1e-12);
  for (VertexId v : r.mesh.vertices()) CHECK(std::abs(r.mesh.position(v).z) <= 1e-12);
  // 0 rounds measure only.
  const Applied none = apply_and_check(skew, "planarize", {{"iterations", 0}}, {}, false);
  CHECK(none.mesh == skew);
  CHECK(none.out.number("nonplanarity_after") == none.out.number("nonplanarity_before"));
}

TEST_CASE("planarize: a randomly perturbed cube gets flatter") {
  Mesh cube = build_mesh(test::cube_soup());
  std::mt19937 random(7);
  std::uniform_real_distribution<double> offset(-0.1, 0.1);
  for (VertexId v : cube.vertices())
    cube.set_position(v, cube.position(v) + glm::dvec3(offset(random), offset(random), offset(random)));
  const double before = nonplanarity(cube);
  REQUIRE(before > 0.01);
  const Applied r = apply_and_check(cube, "planarize", {}, {});
  CHECK(r.out.number("nonplanarity_before") == before);
  CHECK(r.out.number("nonplanarity_after") < before);
  CHECK(nonplanarity(r.mesh) == r.out.number("nonplanarity_after"));
}

TEST_CASE("planarize: refusals") {
  const Mesh cube = build_mesh(test::cube_soup());
  for (int n : {-1, 10001}) CHECK(refused_parameter(cube, "planarize", {{"iterations", n}}) == "iterations");
  CHECK(refused_parameter(cube, "planarize", {{"iterations", 0.5}}) == "iterations");
}

// ---- smooth ---------------------------------------------------------------------------------------------

TEST_CASE("smooth: positions by hand") {
  // Tetrahedron at (1,1,1), (1,-1,-1), (-1,1,-1), (-1,-1,1): the mean of a vertex's three neighbours is
  // -p/3, so p + 0.5 (-p/3 - p) = p/3; twice: p/9; with lambda 1: -p/3, a point reflection, which turns
  // the tetrahedron inside out (so its orientation is not checked here).
  const Mesh tet = build_mesh(test::tetrahedron_soup());
  const std::vector<glm::dvec3> start = positions(tet);
  for (const auto& [iterations, lambda, factor] : std::vector<std::tuple<int, double, double>>{
           {1, 0.5, 1.0 / 3}, {2, 0.5, 1.0 / 9}, {1, 1.0, -1.0 / 3}}) {
    const Applied r =
        apply_and_check(tet, "smooth", {{"iterations", iterations}, {"lambda", lambda}}, {}, false);
    const std::vector<glm::dvec3> now = positions(r.mesh);
    for (std::size_t i = 0; i < now.size(); ++i) check_near(now[i], start[i] * factor);
  }
  // Cube at +-1: the neighbours of (1,1,1) average (1/3, 1/3, 1/3): 1 + 0.5 (1/3 - 1) = 2/3.
  const Mesh cube = build_mesh(test::cube_soup());
  const Applied c = apply_and_check(cube, "smooth", {}, {});
  for (VertexId v : c.mesh.vertices()) check_near(c.mesh.position(v), cube.position(v) * (2.0 / 3));
}

TEST_CASE("smooth: the open grid's boundary stays unless asked") {
  // The 3 x 2 grid with (1,1) lifted to z = 1. Jacobi: (1,1) has flat neighbours, mean z 0: z 0.5; (2,1)
  // has (1,1) among four: mean z 1/4, z 0.125. The ten boundary vertices stay. Without keep_boundary,
  // (1,0) goes halfway to the mean of (0,0), (2,0), (1,1,1), (1, 1/3, 1/3): (1, 1/6, 1/6); the corner (0,0)
  // halfway to (0.5, 0.5, 0): (0.25, 0.25, 0).
  Mesh grid = build_mesh(test::grid_soup(3, 2));
  grid.set_position(vertex_at(grid, {1, 1, 0}), {1, 1, 1});
  const Applied kept = apply_and_check(grid, "smooth", {}, {});
  for (VertexId v : grid.vertices()) {
    const glm::dvec3 p = grid.position(v);
    if (is_boundary(grid, v)) CHECK(kept.mesh.position(v) == p);
  }
  check_near(kept.mesh.position(vertex_at(grid, {1, 1, 1})), {1, 1, 0.5});
  check_near(kept.mesh.position(vertex_at(grid, {2, 1, 0})), {2, 1, 0.125});
  const Applied free = apply_and_check(grid, "smooth", {{"keep_boundary", false}}, {});
  check_near(free.mesh.position(vertex_at(grid, {1, 0, 0})), {1, 1.0 / 6, 1.0 / 6});
  check_near(free.mesh.position(vertex_at(grid, {0, 0, 0})), {0.25, 0.25, 0});
}

TEST_CASE("smooth: the modeling meshes keep their counts, validity and orientation") {
  test::for_each_modeling_mesh([&](const Mesh& mesh) {
    apply_and_check(mesh, "smooth", {{"iterations", 3}}, {});
    CHECK(apply_and_check(mesh, "smooth", {{"iterations", 0}}, {}).mesh == mesh);
  });
}

TEST_CASE("smooth: refusals") {
  const Mesh cube = build_mesh(test::cube_soup());
  for (double lambda : {0.0, -0.5, 1.5, std::numeric_limits<double>::infinity()})
    CHECK(refused_parameter(cube, "smooth", {{"lambda", lambda}}) == "lambda");
  for (int n : {-1, 10001}) CHECK(refused_parameter(cube, "smooth", {{"iterations", n}}) == "iterations");
  Mesh m = cube;
  {
    Transaction tx(m);
    SmoothOptions o;
    o.lambda = std::numeric_limits<double>::quiet_NaN();
    CHECK(test::error_message<ParameterError>([&] { smooth(tx, o); }).rfind("smooth: parameter lambda", 0) ==
          0);
  }
  CHECK(m == cube);
}

// ---- spheralize -----------------------------------------------------------------------------------------

TEST_CASE("spheralize: every vertex at the radius afterwards") {
  test::for_each_modeling_mesh([&](const std::string& name, const Mesh& mesh) {
    // Projecting the second component from a centre outside it folds it: its volume's sign is not kept.
    const bool folds = name == "cube and tetrahedron";
    const Applied r = apply_and_check(mesh, "spheralize", {}, {}, !folds);
    const glm::dvec3 c = r.out.point("center");
    const double radius = r.out.number("radius");
    for (VertexId v : r.mesh.vertices())
      CHECK(glm::length(r.mesh.position(v) - c) == doctest::Approx(radius).epsilon(1e-12));
    CHECK(r.out.integer("vertices_at_center") == 0);
  });
}

TEST_CASE("spheralize: vertices already on the sphere stay; one at the centre is left") {
  // The cube, tetrahedron and octahedron have every vertex at the same distance from their centroid, 0:
  // nothing moves. The cube's radius is sqrt 3.
  for (const Mesh& m : {build_mesh(test::cube_soup()), build_mesh(test::tetrahedron_soup()),
                        build_mesh(test::octahedron_soup())}) {
    CHECK(apply_and_check(m, "spheralize", {}, {}).mesh == m);
  }
  const Applied cube = apply_and_check(build_mesh(test::cube_soup()), "spheralize", {}, {});
  CHECK(cube.out.number("radius") == std::sqrt(3.0));
  CHECK(cube.out.point("center") == glm::dvec3(0.0));
  // A point sphere at the origin keeps the centroid there: it has no ray to move along and stays.
  Mesh with_centre = build_mesh(test::cube_soup());
  with_centre.create_vertex({0, 0, 0});
  const Applied r = apply_and_check(with_centre, "spheralize", {}, {});
  CHECK(r.mesh == with_centre);
  CHECK(r.out.integer("vertices_at_center") == 1);
  // The cube with one corner pulled out to (3,3,3): the other corners move outwards onto its sphere.
  Mesh pulled = build_mesh(test::cube_soup());
  pulled.set_position(vertex_at(pulled, {1, 1, 1}), {3, 3, 3});
  const Applied p = apply_and_check(pulled, "spheralize", {}, {});
  // Centroid (2,2,2)/8 = (0.25, 0.25, 0.25); the farthest vertex is (3,3,3), at 2.75 sqrt 3.
  check_near(p.out.point("center"), glm::dvec3(0.25));
  CHECK(p.out.number("radius") == doctest::Approx(2.75 * std::sqrt(3.0)).epsilon(1e-14));
  // (-1,-1,-1) lies on the ray from the centre along -(1,1,1): it goes to centre - radius (1,1,1)/sqrt 3.
  check_near(p.mesh.position(vertex_at(pulled, {-1, -1, -1})), glm::dvec3(0.25 - 2.75));
}

// ---- every operation of the section is registered --------------------------------------------------------

TEST_CASE("cleanup operations: registered with their parameters and defaults") {
  CHECK(find_operation("dissolve_coplanar").params.at(0).default_value == Value(0.01));
  CHECK(find_operation("planarize").params.at(0).default_value == Value(10));
  const OperationSpec& smooth_op = find_operation("smooth");
  CHECK(smooth_op.params.size() == 3);
  for (const ParamSpec& p : smooth_op.params) {
    if (p.name == "iterations") CHECK(p.default_value == Value(1));
    if (p.name == "lambda") CHECK(p.default_value == Value(0.5));
    if (p.name == "keep_boundary") CHECK(p.default_value == Value(true));
  }
  for (const char* name : {"remove_2gons", "remove_valence2", "spheralize"})
    CHECK(find_operation(name).params.empty());
}
