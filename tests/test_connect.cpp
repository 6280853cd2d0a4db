// connect_edges and connect_faces: counts in closed form on the modeling meshes, genus from V - E + F per
// component, orientation (the signed volume of a closed mesh keeps its sign), exact undo and redo through the
// editor, log replay, every refusal, and the tube's geometry (rings along the curves, pinch, bubble, twist).

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <map>
#include <set>
#include <string>
#include <vector>

#include <dlfl/create_face_manifold.h>
#include <dlfl/errors.h>
#include <dlfl/geometry.h>
#include <dlfl/history/editor.h>
#include <dlfl/history/oplog.h>
#include <dlfl/mesh_hash.h>
#include <dlfl/navigation.h>
#include <dlfl/operations/connect_edges.h>
#include <dlfl/operations/connect_faces.h>
#include <dlfl/operations/operation.h>
#include <dlfl/validate.h>

#include "modeling_checks.h"
#include "modeling_meshes.h"
#include "test_helpers.h"

using namespace dlfl;

namespace {

// ---- helpers
// -----------------------------------------------------------------------------------------------

using test::signed_volume;

/// The genus of each component (from V - E + F, the validator's count), in the validator's order.
std::vector<long> genera(const Mesh& m) {
  const ValidationReport r = validate(m);
  REQUIRE(r.valid());
  std::vector<long> out;
  for (const ComponentInfo& c : r.components) {
    CHECK(c.euler_characteristic == 2 - 2 * c.genus);
    out.push_back(c.genus);
  }
  return out;
}

struct Delta {
  long v = 0, e = 0, f = 0;
};

struct Run {
  Mesh mesh;
  Params out;
};

/// Applies `op` to `start` through the shared editor round trip, then checks the counts and the sign of the
/// volume of a closed mesh.
Run checked(const Mesh& start, const std::string& op, const Params& params, Delta d, bool volume = true) {
  Params out;
  const Mesh after = test::check_editor_round_trip(start, op, params, &out);
  CHECK(long(after.num_vertices()) == long(start.num_vertices()) + d.v);
  CHECK(long(after.num_edges()) == long(start.num_edges()) + d.e);
  CHECK(long(after.num_faces()) == long(start.num_faces()) + d.f);
  if (volume && start.num_hole_faces() == 0 && after.num_hole_faces() == 0) {
    const double v0 = signed_volume(start), v1 = signed_volume(after);
    CHECK(v0 > 0);
    CHECK(v1 > 0);  // the sign kept: no face of the result turned inside out
  }
  return {after, out};
}

using test::check_refusal;

CornerId corner_of(const Mesh& m, std::uint32_t v, std::uint32_t f) {
  const CornerId c = corner_in_face(m, VertexId(v), FaceId(f));
  REQUIRE(c.valid());
  return c;
}

/// Checks connect_faces refuses the corners at vertex 4 of faces f1 and f2, which share it: the long edge
/// would join vertex 4 to itself.
void check_shared_corners_refused(const Mesh& m, std::uint32_t f1, std::uint32_t f2) {
  check_refusal(m, "connect_faces",
                {{"face1", FaceId(f1)},
                 {"face2", FaceId(f2)},
                 {"corner1", corner_of(m, 4, f1)},
                 {"corner2", corner_of(m, 4, f2)}},
                "corner2", "would join vertex v4");
}

std::vector<std::uint32_t> face_vertices(const Mesh& m, FaceId f) {
  std::vector<std::uint32_t> out;
  for (VertexId v : vertices(m, f)) out.push_back(v.index());
  return out;
}

/// The surface face of `m` whose centroid is farthest from that of `from` (the first on ties).
FaceId farthest_face(const Mesh& m, FaceId from) {
  const glm::dvec3 c = face_centroid(m, from);
  FaceId best;
  double best_d = -1;
  for (FaceId f : surface_faces(m)) {
    const double d = glm::distance(c, face_centroid(m, f));
    if (d > best_d) {
      best = f;
      best_d = d;
    }
  }
  return best;
}

/// Pairs of vertices joined by more than one edge.
std::size_t doubled_vertex_pairs(const Mesh& m) {
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> count;
  for (EdgeId e : m.edges()) {
    const auto a = m.from(e).index(), b = m.to(e).index();
    ++count[{std::min(a, b), std::max(a, b)}];
  }
  return std::size_t(std::count_if(count.begin(), count.end(), [](const auto& kv) { return kv.second > 1; }));
}

/// The closed-form change of a tube of m long edges and s segments.
Delta tube_delta(long m, long s) { return {m * (s - 1), m * s + m * (s - 1), -2 + m * s}; }

std::vector<FaceId> tube_faces(const Params& out) { return out.get("faces").as_handles<FaceId>(); }
std::vector<VertexId> tube_vertices(const Params& out) { return out.get("vertices").as_handles<VertexId>(); }

/// Checks the tube faces an operation reported: m x s live surface faces of at most four sides, of which
/// `triangles` are triangles.
void check_tube_faces(const Mesh& m, const Params& out, std::size_t count, std::size_t triangles) {
  const std::vector<FaceId> faces = tube_faces(out);
  CHECK(faces.size() == count);
  CHECK(std::set<FaceId>(faces.begin(), faces.end()).size() == count);
  std::size_t seen_triangles = 0;
  for (FaceId f : faces) {
    REQUIRE(m.is_alive(f));
    CHECK_FALSE(m.is_hole(f));
    CHECK(m.size(f) >= 3);
    CHECK(m.size(f) <= 4);
    seen_triangles += m.size(f) == 3;
  }
  CHECK(seen_triangles == triangles);
}

Mesh two_cubes() { return build_mesh(test::disjoint_union(test::cube_soup(), test::cube_soup())); }

// In two_cubes(): cube A's face x = +1 (vertices 1 3 7 5) and cube B's face x = -1 (8 12 14 10, at x = 4),
// facing each other across the gap; and the two top faces (z = 1), side by side.
constexpr std::uint32_t a_right = 5, b_left = 10, a_top = 1, b_top = 7;

// ---- connect_edges
// -----------------------------------------------------------------------------------------

TEST_CASE(
    "connect_edges: a bridge on every modeling mesh: E+2, the genus grows by one or two components join") {
  test::for_each_modeling_mesh([&](const std::string& name, const Mesh& m) {
    const std::vector<long> g = genera(m);
    FaceId f1(0), f2 = farthest_face(m, f1);
    if (name == "cube and tetrahedron") f2 = FaceId(6);  // the tetrahedron's first face: across components
    REQUIRE(f1 != f2);
    // The first corner of face2 whose edge makes a bridge with face1's first (faces may share vertices).
    const CornerId c1 = m.first_corner(f1);
    CornerId c2;
    for (CornerId c : m.corners(f2)) {
      if (!c2.valid() && test::error_message<ParameterError>([&] { check_connect_edges(m, c1, c); }).empty())
        c2 = c;
    }
    REQUIRE(c2.valid());
    const Run r = checked(m, "connect_edges", {{"corner1", c1}, {"corner2", c2}}, {0, 2, 0});
    const FaceId quad = r.out.get("face").as_handle<FaceId>();
    CHECK(r.mesh.size(quad) == 4);
    CHECK_FALSE(r.mesh.is_hole(quad));
    // The quad is c, d, a, b: corner2's edge, a new edge, corner1's edge, a new edge.
    const std::vector<std::uint32_t> expected = {m.vertex(c2).index(), m.vertex(m.next(c2)).index(),
                                                 m.vertex(c1).index(), m.vertex(m.next(c1)).index()};
    std::vector<std::uint32_t> quad_vertices = face_vertices(r.mesh, quad);
    std::rotate(quad_vertices.begin(), std::find(quad_vertices.begin(), quad_vertices.end(), expected[0]),
                quad_vertices.end());
    CHECK(quad_vertices == expected);
    if (g.size() == 1) {
      CHECK(genera(r.mesh) == std::vector<long>{g[0] + 1});
    } else {
      CHECK(genera(r.mesh) == std::vector<long>{g[0] + g[1]});  // chi 2 + 2 - 2: one sphere
    }
  });
}

TEST_CASE("connect_edges: between two boundary loops of an open tube, and refused from a hole to a face") {
  // A hexagonal prism without its caps: two boundary loops, each closed by a hole face.
  PolygonSoup soup = test::prism_soup(6);
  PolygonSoup open;
  open.positions = soup.positions;
  for (std::size_t f = 2; f < soup.num_faces(); ++f) open.add_face(soup.face(f));
  const Mesh m = build_mesh(open);
  REQUIRE(m.num_hole_faces() == 2);
  std::vector<FaceId> holes;
  for (FaceId f : m.faces())
    if (m.is_hole(f)) holes.push_back(f);
  const Run r =
      checked(m, "connect_edges",
              {{"corner1", m.first_corner(holes[0])}, {"corner2", m.first_corner(holes[1])}}, {0, 2, 0});
  CHECK(r.mesh.num_hole_faces() == 1);  // the two loops are one now
  CHECK_FALSE(r.mesh.is_hole(r.out.get("face").as_handle<FaceId>()));
  CHECK(genera(r.mesh) == std::vector<long>{1});  // an annulus with a band across: a torus with one hole

  // A side edge of a side quad: between two surface faces.
  CornerId side;
  for (CornerId c : m.corners(*surface_faces(m).begin()))
    if (!m.is_hole(m.face(m.opposite(c)))) side = c;
  check_refusal(m, "connect_edges", {{"corner1", m.first_corner(holes[0])}, {"corner2", side}}, "corner2",
                "half boundary, half surface");
}

TEST_CASE("connect_edges: refusals name the corner and leave the mesh as it was") {
  Mesh m = test::cube();
  const VertexId sphere = m.create_vertex({5, 5, 5});
  const CornerId top4 = corner_of(m, 4, 1);  // top face 4 5 7 6: its edge runs 4 -> 5
  check_refusal(m, "connect_edges", {{"corner1", top4}, {"corner2", top4}}, "corner2", "is corner1's edge");
  check_refusal(m, "connect_edges", {{"corner1", top4}, {"corner2", m.opposite(top4)}}, "corner2",
                "is corner1's edge");
  check_refusal(m, "connect_edges", {{"corner1", top4}, {"corner2", corner_of(m, 7, 1)}}, "corner2",
                "with corner1");
  check_refusal(m, "connect_edges", {{"corner1", m.corner(sphere)}, {"corner2", top4}}, "corner1",
                "point sphere");
  // Face x = -1 runs 0 4 6 2: its corner at 0 has the edge 0 -> 4, which ends where corner1's edge starts.
  check_refusal(m, "connect_edges", {{"corner1", top4}, {"corner2", corner_of(m, 0, 4)}}, "corner2",
                "join vertex v4 to itself");
  // Removed corners: the registry refuses them; the library function too, when called directly.
  Mesh copy = m;
  Transaction tx(copy);
  const std::string message =
      test::error_message<ParameterError>([&] { connect_edges(tx, CornerId(100000), top4); });
  CHECK(message.rfind("connect_edges: parameter corner1", 0) == 0);
  CHECK(copy == m);
}

TEST_CASE("connect_edges: two edges leaving one vertex make a quad that visits it twice") {
  const Mesh m = test::cube();
  // Top 4 5 7 6: the edge 4 -> 5; face x = -1 (0 4 6 2): the edge 4 -> 6. The quad c d a b is 4 6 4 5.
  const Run r = checked(m, "connect_edges",
                        {{"corner1", corner_of(m, 4, 1)}, {"corner2", corner_of(m, 4, 4)}}, {0, 2, 0}, false);
  const FaceId quad = r.out.get("face").as_handle<FaceId>();
  const std::vector<std::uint32_t> around = face_vertices(r.mesh, quad);
  CHECK(around.size() == 4);
  CHECK(std::count(around.begin(), around.end(), 4u) == 2);
  CHECK(genera(r.mesh) == std::vector<long>{1});
}

// ---- connect_faces: counts
// ---------------------------------------------------------------------------------

TEST_CASE("connect_faces: a tube between far faces of every modeling mesh, and across the two components") {
  // By hand, m = max(n1, n2) of the faces chosen (face 0 and the farthest from it; for the two components the
  // cube's face x = +1 and the tetrahedron's face turned most towards it).
  const std::map<std::string, long> expected_m = {{"tetrahedron", 3},
                                                  {"cube", 4},
                                                  {"octahedron", 3},
                                                  {"pentagonal prism", 5},
                                                  {"hexagonal prism", 6},
                                                  {"octagonal prism", 8},
                                                  {"torus 4x3", 4},
                                                  {"genus 2", 4},
                                                  {"genus 3", 4},
                                                  {"open grid 3x2", 4},
                                                  {"cube and tetrahedron", 4}};
  test::for_each_modeling_mesh([&](const std::string& name, const Mesh& m) {
    const std::vector<long> g = genera(m);
    FaceId f1(0), f2 = farthest_face(m, f1);
    if (name == "cube and tetrahedron") {
      f1 = FaceId(a_right);
      f2 = FaceId(6);
      for (std::uint32_t f = 7; f < 10; ++f)
        if (face_normal(m, FaceId(f)).x < face_normal(m, f2).x) f2 = FaceId(f);
    }
    const long n1 = m.size(f1), n2 = m.size(f2), n = std::max(n1, n2);
    CHECK(n == expected_m.at(name));
    // The line through a non-convex body leaves it, and the sign of a self-crossing surface's volume means
    // nothing: the volume is checked on the convex meshes and across the gap between the two components.
    const bool convex = name != "torus 4x3" && name != "genus 2" && name != "genus 3";
    for (long s : {1L, 3L}) {
      CAPTURE(s);
      // A full-size line tube between two faces of a convex body is the whole body (volume 0): pinched.
      const Run r =
          checked(m, "connect_faces", {{"face1", f1}, {"face2", f2}, {"segments", s}, {"pinch", 0.5}},
                  tube_delta(n, s), convex && s > 1);
      check_tube_faces(r.mesh, r.out, std::size_t(n * s), std::size_t(std::abs(n1 - n2)));
      CHECK(tube_vertices(r.out).size() == std::size_t(n * (s - 1)));
      if (g.size() == 1) {
        CHECK(genera(r.mesh) == std::vector<long>{g[0] + 1});
      } else {
        CHECK(genera(r.mesh) == std::vector<long>{0});  // chi 2 + 2 - 2 = 2 on one component
      }
    }
  });
}

TEST_CASE("connect_faces: every segment count from 1 to 64 between facing faces of two cubes") {
  const Mesh m = two_cubes();
  for (long s = 1; s <= 64; ++s) {
    CAPTURE(s);
    const Run r =
        checked(m, "connect_faces", {{"face1", FaceId(a_right)}, {"face2", FaceId(b_left)}, {"segments", s}},
                tube_delta(4, s));
    check_tube_faces(r.mesh, r.out, std::size_t(4 * s), 0);
    CHECK(genera(r.mesh) == std::vector<long>{0});
    // The volume grows by the tube's: a 2 x 2 square swept 3 units.
    CHECK(signed_volume(r.mesh) == doctest::Approx(16.0 + 12.0));
  }
}

TEST_CASE(
    "connect_faces: prisms of 3 to 12 sides, cap to cap: quads and triangles, never more than 4 sides") {
  for (int a = 3; a <= 12; ++a) {
    for (int b = 3; b <= 12; ++b) {
      CAPTURE(a);
      CAPTURE(b);
      // Both top caps face up, side by side: a Hermite arch over the gap.
      const Mesh m = build_mesh(test::disjoint_union(test::prism_soup(a), test::prism_soup(b)));
      const FaceId top_a(1), top_b(std::uint32_t(a + 2 + 1));
      REQUIRE(m.size(top_a) == std::uint32_t(a));
      REQUIRE(m.size(top_b) == std::uint32_t(b));
      const long n = std::max(a, b);
      for (long s : {1L, 2L}) {
        const Run r = checked(m, "connect_faces",
                              {{"face1", top_a}, {"face2", top_b}, {"segments", s}, {"curve", "hermite"}},
                              tube_delta(n, s));
        // Each triangle column is s - 1 quads and one triangle at the smaller cap.
        check_tube_faces(r.mesh, r.out, std::size_t(n * s), std::size_t(std::abs(a - b)));
        CHECK(genera(r.mesh) == std::vector<long>{0});
      }
    }
    // The two caps of one prism: a torus.
    const Mesh p = build_mesh(test::prism_soup(a));
    const Run r = checked(p, "connect_faces",
                          {{"face1", FaceId(0)}, {"face2", FaceId(1)}, {"segments", 3}, {"pinch", 0.5}},
                          tube_delta(a, 3));
    check_tube_faces(r.mesh, r.out, std::size_t(3 * a), 0);
    CHECK(genera(r.mesh) == std::vector<long>{1});
  }
}

// ---- connect_faces: neighbouring faces
// ---------------------------------------------------------------------

TEST_CASE("connect_faces: faces sharing an edge get a pairing with no self-loop and no doubled edge") {
  const Mesh m = test::cube();
  // Top 4 5 7 6 and side y = -1 (0 1 5 4) share the edge 4-5. The long edge k joins top position s1 + k and
  // side position s2 - k: a self-loop when s1 + s2 = 3 (mod 4) (4 at 0 and 3, 5 at 1 and 2); a long edge
  // beside a cube edge when s1 + s2 = 0 or 2 (4-0, 5-4, 7-5 or 4-5, 5-1, 6-4). Only s1 + s2 = 1 is clean,
  // all its pairs 2 sqrt 2 apart: the first is (0, 1), the corners at 4 and 1.
  REQUIRE(face_vertices(m, FaceId(1)) == std::vector<std::uint32_t>{4, 5, 7, 6});
  REQUIRE(face_vertices(m, FaceId(2)) == std::vector<std::uint32_t>{0, 1, 5, 4});
  const TubeEnds ends = check_connect_faces(m, FaceId(1), FaceId(2));
  CHECK(ends.corner1 == corner_of(m, 4, 1));
  CHECK(ends.corner2 == corner_of(m, 1, 2));
  for (long s : {1L, 3L}) {
    const Run r = checked(m, "connect_faces", {{"face1", FaceId(1)}, {"face2", FaceId(2)}, {"segments", s}},
                          tube_delta(4, s), false);
    check_tube_faces(r.mesh, r.out, std::size_t(4 * s), 0);
    CHECK(genera(r.mesh) == std::vector<long>{1});
    CHECK(doubled_vertex_pairs(r.mesh) == 0);
  }
  // The corners at the shared vertices, given: the long edge from 4 to 4 is refused.
  check_shared_corners_refused(m, 1, 2);
  // Given corner1 only: its partner is chosen the same way.
  const TubeEnds from5 = check_connect_faces(m, FaceId(1), FaceId(2), {.corner1 = corner_of(m, 5, 1)});
  CHECK(from5.corner2 == corner_of(m, 0, 2));  // s1 = 1 needs s2 = 0
}

TEST_CASE("connect_faces: faces sharing only a vertex (the octahedron's opposite triangles at a vertex)") {
  const Mesh m = build_mesh(test::octahedron_soup());
  // Faces 0 (0 2 4) and 2 (1 3 4) share vertex 4 only. Long edge k joins positions s1 + k and s2 - k: a
  // self-loop at 4 when s1 + s2 = 1 (mod 3). Every other vertex pair but the antipodal 0-1 and 2-3 is an
  // edge, so both usable classes, s1 + s2 = 0 and 2, have two long edges beside an edge. Closest first:
  // (0, 0) is 2 apart, (0, 2) (vertices 0 and 4) sqrt 2: the corners at 0 and 4.
  REQUIRE(face_vertices(m, FaceId(0)) == std::vector<std::uint32_t>{0, 2, 4});
  REQUIRE(face_vertices(m, FaceId(2)) == std::vector<std::uint32_t>{1, 3, 4});
  const TubeEnds ends = check_connect_faces(m, FaceId(0), FaceId(2));
  CHECK(ends.corner1 == corner_of(m, 0, 0));
  CHECK(ends.corner2 == corner_of(m, 4, 2));
  const Run one =
      checked(m, "connect_faces", {{"face1", FaceId(0)}, {"face2", FaceId(2)}}, tube_delta(3, 1), false);
  check_tube_faces(one.mesh, one.out, 3, 0);
  CHECK(genera(one.mesh) == std::vector<long>{1});
  // Class 2: long edges 0-4, 2-3 and 4-1; 0-4 and 4-1 run beside octahedron edges.
  CHECK(doubled_vertex_pairs(one.mesh) == 2);
  const Run three = checked(m, "connect_faces", {{"face1", FaceId(0)}, {"face2", FaceId(2)}, {"segments", 3}},
                            tube_delta(3, 3), false);
  CHECK(genera(three.mesh) == std::vector<long>{1});
  CHECK(doubled_vertex_pairs(three.mesh) == 0);  // subdivided long edges
  check_shared_corners_refused(m, 0, 2);
}

// ---- connect_faces: holes
// ----------------------------------------------------------------------------------

TEST_CASE("connect_faces: the two boundary loops of an open tube make a closed torus") {
  for (int n : {3, 6}) {
    PolygonSoup soup = test::prism_soup(n);
    PolygonSoup open;
    open.positions = soup.positions;
    for (std::size_t f = 2; f < soup.num_faces(); ++f) open.add_face(soup.face(f));
    const Mesh m = build_mesh(open);
    std::vector<FaceId> holes;
    for (FaceId f : m.faces())
      if (m.is_hole(f)) holes.push_back(f);
    REQUIRE(holes.size() == 2);
    for (long s : {1L, 3L}) {
      const Run r = checked(m, "connect_faces",
                            {{"face1", holes[0]}, {"face2", holes[1]}, {"segments", s}, {"pinch", 0.5}},
                            tube_delta(n, s));
      CHECK(r.mesh.num_hole_faces() == 0);
      check_tube_faces(r.mesh, r.out, std::size_t(n * s), 0);
      CHECK(genera(r.mesh) == std::vector<long>{1});
      // The inner wall, pinched, lies inside the outer one: a solid torus of positive volume.
      if (s == 3) CHECK(signed_volume(r.mesh) > 0);
    }
  }
}

TEST_CASE("connect_faces: from a boundary loop to a surface face of the same open mesh") {
  const Mesh m = build_mesh(test::grid_soup(3, 2));
  FaceId hole;
  for (FaceId f : m.faces())
    if (m.is_hole(f)) hole = f;
  REQUIRE(m.size(hole) == 10);
  // The quad (1, 0) touches the boundary: the faces share vertices.
  const Run r = checked(m, "connect_faces", {{"face1", hole}, {"face2", FaceId(1)}, {"segments", 2}},
                        tube_delta(10, 2));
  CHECK(r.mesh.num_hole_faces() == 0);
  check_tube_faces(r.mesh, r.out, 20, 6);
  CHECK(genera(r.mesh) == std::vector<long>{1});
}

// ---- connect_faces: geometry
// -------------------------------------------------------------------------------

/// The long edges' ends of a tube from the corners it started at: face1 forward from corner1, face2 backward
/// from the partner (equal sizes).
std::pair<std::vector<glm::dvec3>, std::vector<glm::dvec3>> ends_of(const Mesh& m, CornerId c1, CornerId c2) {
  std::vector<glm::dvec3> p, q;
  CornerId a = c1, b = c2;
  do {
    p.push_back(m.position(m.vertex(a)));
    q.push_back(m.position(m.vertex(b)));
    a = m.next(a);
    b = m.prev(b);
  } while (a != c1);
  return {p, q};
}

void check_near(const glm::dvec3& a, const glm::dvec3& b) {
  CHECK(a.x == doctest::Approx(b.x).epsilon(1e-9));
  CHECK(a.y == doctest::Approx(b.y).epsilon(1e-9));
  CHECK(a.z == doctest::Approx(b.z).epsilon(1e-9));
}

TEST_CASE("connect_faces: a line puts ring k at k/s between corresponding corners and the centroids") {
  const Mesh m = two_cubes();
  // The closest pair: cube A's corner 1 (1, -1, -1) and cube B's 8 (4, -1, -1), 3 apart, first along both
  // faces. Forward from 1 along A's face: 1 3 7 5; backward from 8 along B's: 8 10 14 12, each 3 units on in
  // x.
  const TubeEnds ends = check_connect_faces(m, FaceId(a_right), FaceId(b_left));
  CHECK(ends.corner1 == corner_of(m, 1, a_right));
  CHECK(ends.corner2 == corner_of(m, 8, b_left));
  const auto [p, q] = ends_of(m, ends.corner1, ends.corner2);
  for (std::size_t k = 0; k < 4; ++k) check_near(q[k], p[k] + glm::dvec3(3, 0, 0));
  const int s = 4;
  const Run r =
      checked(m, "connect_faces", {{"face1", FaceId(a_right)}, {"face2", FaceId(b_left)}, {"segments", s}},
              tube_delta(4, s));
  const std::vector<VertexId> ring = tube_vertices(r.out);
  for (int j = 1; j < s; ++j) {
    glm::dvec3 centroid(0.0);
    for (std::size_t k = 0; k < 4; ++k) {
      const glm::dvec3 x = r.mesh.position(ring[(j - 1) * 4 + k]);
      check_near(x, p[k] + glm::dvec3(3.0 * j / s, 0, 0));
      centroid += x / 4.0;
    }
    check_near(centroid, glm::dvec3(1 + 3.0 * j / s, 0, 0));
  }
}

TEST_CASE("connect_faces: pinch scales the middle ring, bubble pushes it outward by the mean end radius") {
  const Mesh m = two_cubes();
  const TubeEnds ends = check_connect_faces(m, FaceId(a_right), FaceId(b_left));
  const auto [p, q] = ends_of(m, ends.corner1, ends.corner2);
  const glm::dvec3 c1(1, 0, 0);
  {
    // s = 2, the ring at t = 1/2: centre (2.5, 0, 0), offsets (0, +-1, +-1) scaled by the pinch.
    const Run r =
        checked(m, "connect_faces",
                {{"face1", FaceId(a_right)}, {"face2", FaceId(b_left)}, {"segments", 2}, {"pinch", 0.5}},
                tube_delta(4, 2));
    const std::vector<VertexId> ring = tube_vertices(r.out);
    for (std::size_t k = 0; k < 4; ++k)
      check_near(r.mesh.position(ring[k]), glm::dvec3(2.5, 0, 0) + 0.5 * (p[k] - c1));
  }
  {
    // s = 4, bubble 1: the ring at t pushed out by sqrt 2 (the mean radius) x 2 sqrt(t(1 - t)), and the pinch
    // 1 + (0.5 - 1) 4t(1 - t) on top: at t = 1/4 the radius is sqrt 2 (1 - 3/8) + sqrt 2 sqrt 3 / 2.
    const Run r = checked(m, "connect_faces",
                          {{"face1", FaceId(a_right)},
                           {"face2", FaceId(b_left)},
                           {"segments", 4},
                           {"bubble", 1.0},
                           {"pinch", 0.5}},
                          tube_delta(4, 4));
    const std::vector<VertexId> ring = tube_vertices(r.out);
    for (int j = 1; j < 4; ++j) {
      const double t = j / 4.0;
      const double radius =
          std::sqrt(2.0) * (1 - 0.5 * 4 * t * (1 - t)) + std::sqrt(2.0) * 2 * std::sqrt(t * (1 - t));
      for (std::size_t k = 0; k < 4; ++k) {
        const glm::dvec3 offset = (p[k] - c1) / std::sqrt(2.0);
        check_near(r.mesh.position(ring[(j - 1) * 4 + k]), glm::dvec3(1 + 3 * t, 0, 0) + radius * offset);
      }
    }
  }
}

TEST_CASE(
    "connect_faces: hermite arches between two upward faces, bezier moves each vertex on its own curve") {
  const Mesh m = two_cubes();
  // Tops of A (4 5 7 6, centroid (0, 0, 1)) and B (12 13 15 14, centroid (5, 0, 1)); the chord is 5 long, so
  // the tangents are 5 z at both ends. The closest pair: A's 5 (1, -1, 1) and B's 12 (4, -1, 1); forward from
  // 5: 5 7 6 4, backward from 12: 12 14 15 13.
  const TubeEnds ends = check_connect_faces(m, FaceId(a_top), FaceId(b_top));
  CHECK(ends.corner1 == corner_of(m, 5, a_top));
  CHECK(ends.corner2 == corner_of(m, 12, b_top));
  const auto [p, q] = ends_of(m, ends.corner1, ends.corner2);
  const glm::dvec3 c1(0, 0, 1);
  {
    // Hermite at t = 1/2: (c1 + c2) / 2 + (T1 - T2) / 8 = (2.5, 0, 1 + 10 / 8), heading +x. The ring is the
    // face1 ring turned a quarter about +y (z to x): an offset (x, y, 0) goes to (0, y, -x).
    const Run r =
        checked(m, "connect_faces",
                {{"face1", FaceId(a_top)}, {"face2", FaceId(b_top)}, {"segments", 2}, {"curve", "hermite"}},
                tube_delta(4, 2));
    const std::vector<VertexId> ring = tube_vertices(r.out);
    for (std::size_t k = 0; k < 4; ++k) {
      const glm::dvec3 o = p[k] - c1;
      check_near(r.mesh.position(ring[k]), glm::dvec3(2.5, 0, 2.25) + glm::dvec3(0, o.y, -o.x));
    }
    CHECK(signed_volume(r.mesh) > 16.0);  // the arch adds its own volume
  }
  {
    // Bezier at t = 1/2: each vertex at (P + Q) / 2 + (T1 - T2) / 8 = (P + Q) / 2 + (0, 0, 1.25).
    const Run r =
        checked(m, "connect_faces",
                {{"face1", FaceId(a_top)}, {"face2", FaceId(b_top)}, {"segments", 2}, {"curve", "bezier"}},
                tube_delta(4, 2));
    const std::vector<VertexId> ring = tube_vertices(r.out);
    for (std::size_t k = 0; k < 4; ++k)
      check_near(r.mesh.position(ring[k]), 0.5 * (p[k] + q[k]) + glm::dvec3(0, 0, 1.25));
  }
  {
    // Zero weights: no tangent, both curves a straight line between the centroids.
    const Run r = checked(m, "connect_faces",
                          {{"face1", FaceId(a_top)},
                           {"face2", FaceId(b_top)},
                           {"segments", 2},
                           {"curve", "hermite"},
                           {"weight1", 0.0},
                           {"weight2", 0.0}},
                          tube_delta(4, 2), false);
    glm::dvec3 centroid(0.0);
    for (VertexId v : tube_vertices(r.out)) centroid += r.mesh.position(v) / 4.0;
    check_near(centroid, glm::dvec3(2.5, 0, 1));
  }
}

TEST_CASE("connect_faces: twist turns the correspondence, and the twisted tube's faces do not degenerate") {
  const Mesh m = two_cubes();
  const TubeEnds ends = check_connect_faces(m, FaceId(a_right), FaceId(b_left));
  for (long twist : {0L, 1L, 2L, 3L, -1L, 6L}) {
    CAPTURE(twist);
    // segments 1: the first edge runs from corner1 to the corner `twist` steps after corner2.
    const Run one =
        checked(m, "connect_faces", {{"face1", FaceId(a_right)}, {"face2", FaceId(b_left)}, {"twist", twist}},
                tube_delta(4, 1));
    CornerId partner = ends.corner2;
    for (long i = 0; i < ((twist % 4) + 4) % 4; ++i) partner = m.next(partner);
    const EdgeId first = one.out.get("edge").as_handle<EdgeId>();
    CHECK(one.mesh.from(first) == m.vertex(ends.corner1));
    CHECK(one.mesh.to(first) == m.vertex(partner));
    // segments 8: every ring turned part of the way, every face of the tube of a fair area.
    const Run eight =
        checked(m, "connect_faces",
                {{"face1", FaceId(a_right)}, {"face2", FaceId(b_left)}, {"segments", 8}, {"twist", twist}},
                tube_delta(4, 8));
    for (FaceId f : tube_faces(eight.out)) CHECK(face_area(eight.mesh, f) > 0.2);
    CHECK(signed_volume(eight.mesh) > 16.0);
  }
}

// ---- connect_faces: handles on handles
// ---------------------------------------------------------------------

TEST_CASE("connect_faces: a handle on a handle on a handle, each on faces of the last tube") {
  Editor ed;
  ed.set_mesh(test::cube());
  const Mesh start = ed.mesh();
  // A tunnel through the cube from bottom to top, pinched; then a strut across it between two opposite
  // faces of its middle ring; then a tunnel through that strut the same way.
  std::vector<Mesh> levels = {start};
  Params out = ed.apply("connect_faces",
                        {{"face1", FaceId(0)}, {"face2", FaceId(1)}, {"segments", 4}, {"pinch", 0.5}});
  for (int level = 1; level <= 3; ++level) {
    CAPTURE(level);
    const Mesh& m = ed.mesh();
    const Mesh& before = levels.back();
    CHECK(m.num_vertices() == before.num_vertices() + 4 * 3);
    CHECK(m.num_edges() == before.num_edges() + 4 * 4 + 4 * 3);
    CHECK(m.num_faces() == before.num_faces() - 2 + 4 * 4);
    CHECK(genera(m) == std::vector<long>{level});
    CHECK(signed_volume(m) > 0);
    levels.push_back(m);
    if (level == 3) break;
    const std::vector<FaceId> faces = tube_faces(out);
    REQUIRE(faces.size() == 16);
    // Ring 1 (the second from face1), faces 0 and 2 of it: opposite walls.
    out = ed.apply("connect_faces",
                   {{"face1", faces[4 + 0]}, {"face2", faces[4 + 2]}, {"segments", 4}, {"pinch", 0.5}});
  }
  const std::string final_hash = mesh_hash(ed.mesh());
  for (int level = 3; level >= 1; --level) {
    REQUIRE(ed.undo());
    CHECK(ed.mesh() == levels[std::size_t(level - 1)]);
  }
  CHECK(mesh_hash(ed.mesh()) == mesh_hash(start));
  for (int level = 1; level <= 3; ++level) REQUIRE(ed.redo());
  CHECK(ed.mesh() == levels.back());
  CHECK(mesh_hash(replay_log(log_text(ed)).mesh()) == final_hash);
}

// ---- connect_faces: refusals
// -------------------------------------------------------------------------------

TEST_CASE("connect_faces: refusals name the argument and leave the mesh as it was") {
  Mesh m = test::cube();
  const VertexId sphere = m.create_vertex({5, 5, 5});
  const FaceId sphere_face = m.face(m.corner(sphere));
  check_refusal(m, "connect_faces", {{"face1", FaceId(0)}, {"face2", FaceId(0)}}, "face2", "is face1");
  check_refusal(m, "connect_faces", {{"face1", sphere_face}, {"face2", FaceId(0)}}, "face1", "point sphere");
  check_refusal(m, "connect_faces", {{"face1", FaceId(0)}, {"face2", sphere_face}}, "face2", "point sphere");
  check_refusal(m, "connect_faces",
                {{"face1", FaceId(0)}, {"face2", FaceId(1)}, {"corner1", corner_of(m, 4, 1)}}, "corner1",
                "is not a corner of face1");
  check_refusal(m, "connect_faces",
                {{"face1", FaceId(0)}, {"face2", FaceId(1)}, {"corner2", corner_of(m, 0, 0)}}, "corner2",
                "is not a corner of face2");
  // The registry's own checks: ranges and removed handles.
  check_refusal(m, "connect_faces", {{"face1", FaceId(0)}, {"face2", FaceId(1)}, {"segments", 0}},
                "segments");
  check_refusal(m, "connect_faces", {{"face1", FaceId(0)}, {"face2", FaceId(1)}, {"pinch", -1.0}}, "pinch");
  check_refusal(m, "connect_faces", {{"face1", FaceId(0)}, {"face2", FaceId(1)}, {"curve", "spline"}},
                "curve");
  check_refusal(m, "connect_faces", {{"face1", FaceId(0)}, {"face2", FaceId(99)}}, "face2");

  // The library function checks the same, before it changes anything.
  Mesh copy = m;
  Transaction tx(copy);
  const auto library_refusal = [&](FaceId f1, FaceId f2, const ConnectFacesOptions& o) {
    try {
      connect_faces(tx, f1, f2, o);
    } catch (const ParameterError& e) {
      CHECK(std::string(e.what()).rfind("connect_faces: parameter " + e.parameter(), 0) == 0);
      return e.parameter();
    }
    return std::string("accepted");
  };
  CHECK(library_refusal(FaceId(99), FaceId(1), {}) == "face1");
  CHECK(library_refusal(FaceId(0), FaceId(1), {.segments = 0}) == "segments");
  CHECK(library_refusal(FaceId(0), FaceId(1), {.segments = 2000}) == "segments");
  CHECK(library_refusal(FaceId(0), FaceId(1), {.weight1 = std::nan("")}) == "weight1");
  CHECK(library_refusal(FaceId(0), FaceId(1), {.weight2 = -1}) == "weight2");
  CHECK(library_refusal(FaceId(0), FaceId(1), {.pinch = -0.5}) == "pinch");
  CHECK(library_refusal(FaceId(0), FaceId(1), {.bubble = INFINITY}) == "bubble");
  CHECK(library_refusal(FaceId(0), FaceId(1), {.corner1 = CornerId(100000)}) == "corner1");
  CHECK(copy == m);
}

TEST_CASE("connect_faces: refused when every pairing of the corners joins a vertex to itself") {
  // A 2-gon a x (with its back x a), then a point sphere y joined to a inside the front: the front becomes
  // a y a x, visiting a twice, two positions apart. Against the back (size 2, holding a), long edge k reaches
  // a in the front for k = -s1 and k = 2 - s1 (mod 4), and b(k) = floor(k / 2) differs by one between them:
  // the back's position of a is met at one of them whatever the partner.
  Mesh m;
  const std::vector<glm::dvec3> points = {{0, 0, 0}, {1, 0, 0}};
  std::vector<CornerId> front(2), back(2);
  const FaceManifold fm = create_face_manifold(m, points, {}, front, back);
  const VertexId y = m.create_vertex({0, 1, 0});
  m.insert_edge(front[0], m.corner(y));
  const FaceId f = m.face(front[1]);
  REQUIRE(m.size(f) == 4);
  REQUIRE(m.size(fm.back) == 2);
  check_refusal(m, "connect_faces", {{"face1", f}, {"face2", fm.back}}, "face2", "every pairing");
  check_refusal(m, "connect_faces", {{"face1", f}, {"face2", fm.back}, {"corner1", front[1]}}, "corner1",
                "every tube from it");
  check_refusal(m, "connect_faces", {{"face1", f}, {"face2", fm.back}, {"corner2", back[0]}}, "corner2",
                "every tube from it");
}

TEST_CASE("connect_edges and connect_faces are registered with their parameters and defaults") {
  const OperationSpec& edges = find_operation("connect_edges");
  CHECK(edges.params.size() == 2);
  const OperationSpec& faces = find_operation("connect_faces");
  const std::map<std::string, Value> defaults = {{"segments", 1},  {"curve", "line"}, {"weight1", 1.0},
                                                 {"weight2", 1.0}, {"twist", 0},      {"pinch", 1.0},
                                                 {"bubble", 0.0}};
  std::set<std::string> names;
  for (const ParamSpec& p : faces.params) {
    names.insert(p.name);
    if (defaults.count(p.name)) CHECK_MESSAGE(p.default_value == defaults.at(p.name), p.name);
  }
  CHECK(names == std::set<std::string>{"face1", "face2", "corner1", "corner2", "segments", "curve", "weight1",
                                       "weight2", "twist", "pinch", "bubble"});
}

}  // namespace
