// The local face operations of docs/modeling.md: stellate_face, subdivide_face, triangulate,
// reverse_orientation and transform. Expected counts are the closed forms in n (the face's sides) or worked
// out by hand for the mesh at hand; geometry (volumes, areas, positions) in closed form.

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/vec2.hpp>
#include <numbers>
#include <string>
#include <utility>
#include <vector>

#include <dlfl/errors.h>
#include <dlfl/geometry.h>
#include <dlfl/history/editor.h>
#include <dlfl/history/oplog.h>
#include <dlfl/mesh_hash.h>
#include <dlfl/navigation.h>
#include <dlfl/operations/operation.h>
#include <dlfl/operations/reverse_orientation.h>
#include <dlfl/operations/stellate_face.h>
#include <dlfl/operations/subdivide_face.h>
#include <dlfl/operations/transform.h>
#include <dlfl/operations/triangulate.h>

#include "modeling_checks.h"
#include "modeling_meshes.h"
#include "test_helpers.h"
#include "test_meshes.h"

using namespace dlfl;

namespace {

using test::check_editor_round_trip;
using test::Counts;
using test::counts;
using test::signed_volume;

bool closed(const Mesh& m) { return m.num_hole_faces() == 0; }

// Each face as its vertex cycle started at its least rotation, with its hole flag, all sorted: equal for two
// meshes with the same faces whatever their handles.
using FaceCycle = std::pair<std::vector<std::uint32_t>, bool>;

std::vector<std::uint32_t> least_rotation(std::vector<std::uint32_t> cycle) {
  std::vector<std::uint32_t> best = cycle;
  for (std::size_t i = 1; i < cycle.size(); ++i) {
    std::rotate(cycle.begin(), cycle.begin() + 1, cycle.end());
    best = std::min(best, cycle);
  }
  return best;
}

std::vector<FaceCycle> face_cycles(const Mesh& m, bool reversed = false) {
  std::vector<FaceCycle> out;
  for (FaceId f : m.faces()) {
    std::vector<std::uint32_t> cycle;
    for (VertexId v : vertices(m, f)) cycle.push_back(v.index());
    if (reversed) std::reverse(cycle.begin(), cycle.end());
    out.emplace_back(least_rotation(cycle), m.is_hole(f));
  }
  std::sort(out.begin(), out.end());
  return out;
}

std::vector<FaceId> surface_face_list(const Mesh& m) {
  std::vector<FaceId> out;
  for (FaceId f : surface_faces(m)) out.push_back(f);
  return out;
}

FaceId first_hole(const Mesh& m) {
  for (FaceId f : m.faces())
    if (m.is_hole(f)) return f;
  return FaceId();
}

// The cube with a dangling edge inside its face f: a new vertex at the face's centre joined to its first
// corner. f then has 6 corners and the new edge on both sides. V = 9, E = 13, F = 6.
Mesh cube_with_spoke(FaceId f) {
  Mesh m = test::cube();
  const glm::dvec3 centre = face_centroid(m, f);
  const VertexId v = m.create_vertex(centre);
  m.insert_edge(m.first_corner(f), m.corner(v));
  return m;
}

// Two vertices joined by two edges: two 2-gons, front and back. V = 2, E = 2, F = 2.
Mesh two_gons() {
  Mesh m;
  const glm::dvec3 points[] = {{0, 0, 0}, {1, 0, 0}};
  create_face_manifold(m, points);
  return m;
}

// Applies the face operation `op` to a copy of each modeling mesh, once for each surface face f of n sides,
// and checks what stellate_face and subdivide_face both keep: a valid result, the counts changed by delta(n),
// a closed mesh's volume and the hole faces; `check(mesh, f, n, m, out)` checks the rest on the result m.
template <class Delta, class Check>
void check_every_surface_face(const std::string& op, Delta delta, Check check) {
  test::for_each_modeling_mesh([&](const Mesh& mesh) {
    for (FaceId f : surface_face_list(mesh)) {
      CAPTURE(f);
      Mesh m = mesh;
      const long n = mesh.size(f);
      const Params out = apply_operation(m, op, {{"face", f}});
      test::require_valid(m);
      const Counts c = counts(mesh), d = delta(n);
      CHECK(counts(m) == Counts{c.v + d.v, c.e + d.e, c.f + d.f});
      check(mesh, f, n, m, out);
      if (closed(mesh)) CHECK(signed_volume(m) == doctest::Approx(signed_volume(mesh)));
      CHECK(m.num_hole_faces() == mesh.num_hole_faces());
    }
  });
}

}  // namespace

// ---- stellate_face
// ------------------------------------------------------------------------------------------

TEST_CASE("stellate_face: every surface face of every modeling mesh: V+1, E+n, F+n-1, triangles around") {
  check_every_surface_face(
      "stellate_face",
      [](long n) {
        return Counts{1, n, n - 1};
      },
      [](const Mesh& mesh, FaceId f, long n, const Mesh& m, const Params& out) {
        const auto v = out.handle<VertexId>("vertex");
        CHECK(m.valence(v) == std::uint32_t(n));
        CHECK(m.position(v) == face_centroid(mesh, f));
        const auto triangles = out.handles<FaceId>("faces");
        REQUIRE(triangles.size() == std::size_t(n));
        for (FaceId t : triangles) {
          CHECK(m.size(t) == 3);
          CHECK(corner_in_face(m, v, t).valid());
          CHECK_FALSE(m.is_hole(t));
          // Fanned out of a convex planar face: each triangle faces the way the face did.
          CHECK(glm::dot(face_normal(m, t), face_normal(mesh, f)) > 0.0);
        }
      });
}

TEST_CASE("stellate_face: the height raises a pyramid of volume area * height / 3") {
  const Mesh cube = test::cube();  // edge 2, volume 8
  Mesh m = cube;
  const FaceId top(1);  // z = +1, normal +z
  const Params out = apply_operation(m, "stellate_face", {{"face", top}, {"height", 1.5}});
  test::require_valid(m);
  CHECK(counts(m) == Counts{9, 16, 9});  // by hand: 8+1, 12+4, 6+4-1
  CHECK(m.position(out.handle<VertexId>("vertex")) == glm::dvec3(0, 0, 2.5));
  CHECK(signed_volume(m) == doctest::Approx(8.0 + 4.0 * 1.5 / 3.0));
  // A negative height digs the pyramid in.
  Mesh dug = cube;
  apply_operation(dug, "stellate_face", {{"face", top}, {"height", -1.5}});
  CHECK(signed_volume(dug) == doctest::Approx(8.0 - 4.0 * 1.5 / 3.0));
}

TEST_CASE(
    "stellate_face: a list of faces, each on its own; all faces of the cube give the tetrakis hexahedron") {
  const Mesh cube = test::cube();
  Mesh m = cube;
  const Params out =
      apply_operation(m, "stellate_face", {{"faces", surface_face_list(cube)}, {"height", 0.5}});
  test::require_valid(m);
  CHECK(counts(m) == Counts{14, 36, 24});  // 8+6, 12+6*4, 6*4
  CHECK(out.handles<VertexId>("vertices").size() == 6);
  CHECK(out.handles<FaceId>("faces").size() == 24);
  for (FaceId f : m.faces()) CHECK(m.size(f) == 3);
  CHECK(signed_volume(m) == doctest::Approx(8.0 + 6 * 4.0 * 0.5 / 3.0));
  // Two faces of the open grid (quads): V+2, E+8, F+6; the hole is left as it was.
  const Mesh grid = build_mesh(test::grid_soup(3, 2));  // V 12, E 17, F 7 (6 quads and the hole)
  Mesh g = grid;
  apply_operation(g, "stellate_face", {{"faces", std::vector<FaceId>{FaceId(0), FaceId(4)}}});
  test::require_valid(g);
  CHECK(counts(g) == Counts{14, 25, 13});
  CHECK(g.size(first_hole(g)) == 10);
}

TEST_CASE("stellate_face: faces with a dangling edge and 2-gons") {
  // The cube's face with a spoke has 6 corners: V+1, E+6, F+5.
  const Mesh spoke = cube_with_spoke(FaceId(1));
  Mesh m = spoke;
  apply_operation(m, "stellate_face", {{"face", FaceId(1)}});
  test::require_valid(m);
  CHECK(counts(m) == Counts{10, 19, 11});
  const Mesh gons = two_gons();
  Mesh g = gons;
  apply_operation(g, "stellate_face", {{"face", FaceId(0)}});
  test::require_valid(g);
  CHECK(counts(g) == Counts{3, 4, 3});
}

TEST_CASE("stellate_face: undo, redo and the log, on every modeling mesh") {
  test::for_each_modeling_mesh([&](const Mesh& mesh) {
    const FaceId f = surface_face_list(mesh).back();
    check_editor_round_trip(mesh, "stellate_face", {{"face", f}, {"height", 0.25}});
    check_editor_round_trip(mesh, "stellate_face", {{"faces", surface_face_list(mesh)}});
  });
}

TEST_CASE("stellate_face: refusals name the argument and change nothing") {
  const Mesh grid = build_mesh(test::grid_soup(3, 2));
  const FaceId hole = first_hole(grid);
  CHECK(test::check_refusal(grid, "stellate_face", {}, "face").find("give face or faces") !=
        std::string::npos);
  CHECK(test::check_refusal(grid, "stellate_face", {{"face", 0}, {"faces", "1,2"}}, "face").find("both") !=
        std::string::npos);
  CHECK(test::check_refusal(grid, "stellate_face", {{"face", hole}}, "face").find("hole") !=
        std::string::npos);
  CHECK(test::check_refusal(grid, "stellate_face", {{"faces", std::vector<FaceId>{FaceId(0), hole}}}, "faces")
            .find("hole") != std::string::npos);
  CHECK(test::check_refusal(grid, "stellate_face", {{"faces", "0,2,0"}}, "faces").find("f0 twice") !=
        std::string::npos);
  CHECK(
      test::check_refusal(grid, "stellate_face", {{"faces", std::vector<FaceId>{}}}, "faces").find("empty") !=
      std::string::npos);
  CHECK(test::check_refusal(grid, "stellate_face", {{"face", 99}}, "face").find("does not exist") !=
        std::string::npos);
  Mesh with_sphere = grid;
  const VertexId p = with_sphere.create_vertex({5, 5, 5});
  const FaceId sphere = with_sphere.face(with_sphere.corner(p));
  CHECK(test::check_refusal(with_sphere, "stellate_face", {{"face", sphere}}, "face").find("point sphere") !=
        std::string::npos);
  // An apex past the largest double: the cube blown up to +-1e308, raised by 1e308 more.
  Mesh huge = test::cube();
  apply_operation(huge, "transform", {{"scale", glm::dvec3(1e308)}});
  CHECK(test::check_refusal(huge, "stellate_face", {{"face", 1}, {"height", 1e308}}, "face")
            .find("non-finite") != std::string::npos);
  CHECK(test::check_refusal(huge, "stellate_face", {{"faces", "0,1"}, {"height", 1e308}}, "faces")
            .find("lists f0, which would get its new vertex at a non-finite position") != std::string::npos);
  // The library function refuses the same way.
  Mesh m = grid;
  Transaction tx(m);
  CHECK(test::error_message<ParameterError>([&] { stellate_face(tx, hole); }).find("hole") !=
        std::string::npos);
  CHECK(test::error_message<ParameterError>([&] {
          stellate_face(tx, FaceId(0), {std::nan("")});
        }).find("height") != std::string::npos);
  CHECK(tx.size() == 0);
}

// ---- subdivide_face
// -----------------------------------------------------------------------------------------

TEST_CASE("subdivide_face: quads on every surface face of every modeling mesh: V+n+1, E+2n, F+n-1") {
  check_every_surface_face(
      "subdivide_face",
      [](long n) {
        return Counts{n + 1, 2 * n, n - 1};
      },
      [](const Mesh& mesh, FaceId f, long n, const Mesh& m, const Params& out) {
        const auto center = out.handle<VertexId>("vertex");
        CHECK(m.position(center) == face_centroid(mesh, f));
        CHECK(m.valence(center) == std::uint32_t(n));
        const auto midpoints = out.handles<VertexId>("vertices");
        CHECK(midpoints.size() == std::size_t(n));
        for (VertexId mid : midpoints) CHECK(m.valence(mid) == 3);
        const auto quads = out.handles<FaceId>("faces");
        REQUIRE(quads.size() == std::size_t(n));
        for (FaceId q : quads) {
          CHECK(m.size(q) == 4);
          CHECK(glm::dot(face_normal(m, q), face_normal(mesh, f)) > 0.0);
        }
        // Each face across an edge of f gained that edge's midpoint: one side more per edge it shares with f.
        std::vector<FaceId> across;
        for (FaceId g : neighbours(mesh, f)) across.push_back(g);
        for (FaceId g : across) {
          CAPTURE(g);
          CHECK(m.size(g) == mesh.size(g) + std::count(across.begin(), across.end(), g));
        }
      });
}

TEST_CASE("subdivide_face: the cube's top face by hand; the neighbours become pentagons") {
  Mesh m = test::cube();
  const Params out = apply_operation(m, "subdivide_face", {{"face", FaceId(1)}});
  test::require_valid(m);
  CHECK(counts(m) == Counts{13, 20, 9});  // 8+5, 12+8, 6+3
  std::vector<std::uint32_t> sizes;
  for (FaceId f : m.faces()) sizes.push_back(m.size(f));
  std::sort(sizes.begin(), sizes.end());
  CHECK(sizes == std::vector<std::uint32_t>{4, 4, 4, 4, 4, 5, 5, 5, 5});  // 4 quads, the bottom, 4 sides
  std::vector<glm::dvec3> mids;
  for (VertexId v : out.handles<VertexId>("vertices")) mids.push_back(m.position(v));
  for (const glm::dvec3& p : mids) {
    CHECK(p.z == 1.0);
    CHECK(std::abs(p.x) + std::abs(p.y) == 1.0);  // the midpoints of the top square's sides
  }
}

TEST_CASE("subdivide_face: triangles is stellate_face with height 0") {
  test::for_each_modeling_mesh([&](const Mesh& mesh) {
    const FaceId f = surface_face_list(mesh).front();
    Mesh a = mesh, b = mesh;
    const Params out = apply_operation(a, "subdivide_face", {{"face", f}, {"style", "triangles"}});
    apply_operation(b, "stellate_face", {{"face", f}});
    CHECK(a == b);
    const long n = mesh.size(f);
    const Counts c = counts(mesh);
    CHECK(counts(a) == Counts{c.v + 1, c.e + n, c.f + n - 1});
    CHECK(out.handles<FaceId>("faces").size() == std::size_t(n));
  });
}

TEST_CASE("subdivide_face: an edge with the face on both sides gets one midpoint; 2-gons") {
  // The spoke is one of the face's 6 sides, on both of them: 5 edges, 5 midpoints, the face vertex joined
  // to the spoke's midpoint twice. V+5+1, E+5+6, F+6-1.
  const Mesh spoke = cube_with_spoke(FaceId(1));
  Mesh m = spoke;
  const Params out = apply_operation(m, "subdivide_face", {{"face", FaceId(1)}});
  test::require_valid(m);
  CHECK(counts(m) == Counts{15, 24, 11});
  CHECK(out.handles<VertexId>("vertices").size() == 5);
  CHECK(out.handles<FaceId>("faces").size() == 6);
  // A 2-gon: two midpoints, two quads. V+3, E+4, F+1.
  Mesh g = two_gons();
  apply_operation(g, "subdivide_face", {{"face", FaceId(0)}});
  test::require_valid(g);
  CHECK(counts(g) == Counts{5, 6, 3});
}

TEST_CASE("subdivide_face: the neighbouring hole grows by a side; undo, redo and the log") {
  const Mesh grid = build_mesh(test::grid_soup(3, 2));
  // Face 0 is the corner cell (0,0): two of its sides are on the boundary.
  Mesh m = grid;
  apply_operation(m, "subdivide_face", {{"face", FaceId(0)}});
  CHECK(m.size(first_hole(m)) == 12);  // 10 + 2
  CHECK(m.num_hole_faces() == 1);
  test::for_each_modeling_mesh([&](const Mesh& mesh) {
    check_editor_round_trip(mesh, "subdivide_face", {{"face", surface_face_list(mesh).back()}});
    check_editor_round_trip(mesh, "subdivide_face",
                            {{"face", surface_face_list(mesh).front()}, {"style", "triangles"}});
  });
}

TEST_CASE("subdivide_face: refusals name the argument and change nothing") {
  const Mesh grid = build_mesh(test::grid_soup(3, 2));
  CHECK(test::check_refusal(grid, "subdivide_face", {{"face", first_hole(grid)}}, "face").find("hole") !=
        std::string::npos);
  CHECK(test::check_refusal(grid, "subdivide_face", {{"face", 42}}, "face").find("does not exist") !=
        std::string::npos);
  CHECK(test::check_refusal(grid, "subdivide_face", {{"face", 0}, {"style", "hexagons"}}, "style") != "");
  CHECK(test::check_refusal(grid, "subdivide_face", {}, "face") != "");
  Mesh with_sphere = grid;
  const VertexId p = with_sphere.create_vertex({5, 5, 5});
  CHECK(test::check_refusal(with_sphere, "subdivide_face",
                            {{"face", with_sphere.face(with_sphere.corner(p))}}, "face")
            .find("point sphere") != std::string::npos);
  Mesh m = grid;
  Transaction tx(m);
  CHECK(test::error_message<ParameterError>([&] { subdivide_face(tx, first_hole(grid)); }).find("hole") !=
        std::string::npos);
  CHECK(tx.size() == 0);
}

// ---- triangulate
// --------------------------------------------------------------------------------------------

TEST_CASE("triangulate: every modeling mesh: E+(n-3), F+(n-3) per face of n > 3 sides, holes left alone") {
  test::for_each_modeling_mesh([&](const Mesh& mesh) {
    long diagonals = 0;
    for (FaceId f : surface_faces(mesh)) diagonals += std::max(0L, long(mesh.size(f)) - 3);
    Mesh m = mesh;
    const Params out = apply_operation(m, "triangulate");
    test::require_valid(m);
    const Counts c = counts(mesh);
    CHECK(counts(m) == Counts{c.v, c.e + diagonals, c.f + diagonals});
    for (FaceId f : surface_faces(m)) CHECK(m.size(f) == 3);
    CHECK(m.num_hole_faces() == mesh.num_hole_faces());
    if (mesh.num_hole_faces() > 0) CHECK(m.size(first_hole(m)) == mesh.size(first_hole(mesh)));
    if (closed(mesh)) CHECK(signed_volume(m) == doctest::Approx(signed_volume(mesh)));
    // The output lists the triangles of the faces that were cut.
    long cut_faces = 0;
    for (FaceId f : surface_faces(mesh)) cut_faces += mesh.size(f) > 3 ? long(mesh.size(f)) - 2 : 0;
    CHECK(long(out.handles<FaceId>("faces").size()) == cut_faces);
  });
}

TEST_CASE("triangulate: the cube by hand, and a chosen list") {
  Mesh m = test::cube();
  apply_operation(m, "triangulate");
  CHECK(counts(m) == Counts{8, 18, 12});  // a diagonal per square
  Mesh two = test::cube();
  const Params out = apply_operation(two, "triangulate", {{"faces", "0,5"}});
  CHECK(counts(two) == Counts{8, 14, 8});
  CHECK(out.handles<FaceId>("faces").size() == 4);
  // Triangles and holes listed are left alone.
  const Mesh grid = build_mesh(test::grid_soup(3, 2));
  Mesh g = grid;
  apply_operation(g, "triangulate", {{"faces", std::vector<FaceId>{first_hole(grid), FaceId(0)}}});
  CHECK(counts(g) == Counts{12, 18, 8});
  Mesh t = test::tetrahedron();
  apply_operation(t, "triangulate");
  CHECK(t == test::tetrahedron());
}

namespace {

// One polygon as an open mesh (the polygon and its hole), its points turned out of the xy plane.
Mesh polygon_mesh(const std::vector<glm::dvec2>& points, const glm::dvec3& axis, double radians) {
  PolygonSoup s;
  std::vector<std::uint32_t> face;
  const glm::dvec3 k = glm::normalize(axis);
  for (const glm::dvec2& q : points) {
    const glm::dvec3 p(q, 0.0);
    s.positions.push_back(p * std::cos(radians) + glm::cross(k, p) * std::sin(radians) +
                          k * glm::dot(k, p) * (1 - std::cos(radians)));
    face.push_back(std::uint32_t(face.size()));
  }
  s.add_face(face);
  return build_mesh(s);
}

// A five-pointed star: outer radius 2, inner radius 1, ten corners counter-clockwise. Its area is that of 10
// triangles (centre, outer, inner) with the angle pi/5 between the two: 10 * (1/2) * 2 * 1 * sin(pi/5).
std::vector<glm::dvec2> star() {
  std::vector<glm::dvec2> points;
  for (int i = 0; i < 10; ++i) {
    const double a = std::numbers::pi * i / 5, r = i % 2 == 0 ? 2.0 : 1.0;
    points.emplace_back(r * std::cos(a), r * std::sin(a));
  }
  return points;
}

// Triangulates the one polygon of `m` and checks that no triangle is folded and that the areas add up.
void check_polygon_triangulation(const Mesh& m, double area) {
  const FaceId polygon = surface_face_list(m).front();
  const glm::dvec3 normal = face_normal(m, polygon);
  CHECK(face_area(m, polygon) == doctest::Approx(area));
  const long n = m.size(polygon);
  Mesh t = m;
  const Params out = apply_operation(t, "triangulate");
  test::require_valid(t);
  CHECK(counts(t) ==
        Counts{long(m.num_vertices()), long(m.num_edges()) + n - 3, long(m.num_faces()) + n - 3});
  double sum = 0.0;
  const auto triangles = out.handles<FaceId>("faces");
  CHECK(long(triangles.size()) == n - 2);
  for (FaceId f : triangles) {
    CHECK(t.size(f) == 3);
    CHECK(face_area(t, f) > 0.0);
    CHECK(glm::dot(face_normal(t, f), normal) == doctest::Approx(1.0));  // none turned over
    sum += face_area(t, f);
  }
  CHECK(sum == doctest::Approx(area));
}

}  // namespace

TEST_CASE("triangulate: non-convex planar faces are cut into triangles that all face the same way") {
  // An L of three unit squares, area 3; its re-entrant corner is (1,1).
  const std::vector<glm::dvec2> l_shape = {{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}};
  check_polygon_triangulation(polygon_mesh(l_shape, {0, 0, 1}, 0.0), 3.0);
  check_polygon_triangulation(polygon_mesh(l_shape, {1, 2, 0.5}, 2.0), 3.0);
  // Started at the re-entrant corner.
  const std::vector<glm::dvec2> l_rotated = {{1, 1}, {1, 2}, {0, 2}, {0, 0}, {2, 0}, {2, 1}};
  check_polygon_triangulation(polygon_mesh(l_rotated, {0, 1, 0}, 1.0), 3.0);
  const double star_area = 10 * 0.5 * 2 * 1 * std::sin(std::numbers::pi / 5);
  check_polygon_triangulation(polygon_mesh(star(), {0, 0, 1}, 0.0), star_area);
  check_polygon_triangulation(polygon_mesh(star(), {-1, 0.3, 2}, 0.9), star_area);
  // A comb: teeth of width 1 and gaps between, area 3 * 1 * 2 + 5 * 1 (the spine of height 1, width 5).
  const std::vector<glm::dvec2> comb = {{0, 0}, {5, 0}, {5, 3}, {4, 3}, {4, 1}, {3, 1},
                                        {3, 3}, {2, 3}, {2, 1}, {1, 1}, {1, 3}, {0, 3}};
  check_polygon_triangulation(polygon_mesh(comb, {0, 0, 1}, 0.0), 5 + 3 * 2);
}

TEST_CASE("triangulate: a prism on a star keeps its volume") {
  // The star prism: two star caps (non-convex 10-gons) and 10 side quads; volume = cap area * height.
  PolygonSoup s;
  for (int z = 0; z < 2; ++z) {
    for (const glm::dvec2& q : star()) s.positions.push_back({q, double(z)});
  }
  test::add_prism_faces(s, 10);
  const Mesh prism = build_mesh(s);
  const double star_area = 10 * 0.5 * 2 * 1 * std::sin(std::numbers::pi / 5);
  CHECK(signed_volume(prism) == doctest::Approx(star_area));
  Mesh m = prism;
  apply_operation(m, "triangulate");
  test::require_valid(m);
  CHECK(counts(m) == Counts{20, 30 + 2 * 7 + 10, 12 + 2 * 7 + 10});
  CHECK(signed_volume(m) == doctest::Approx(star_area));
  for (FaceId f : m.faces()) CHECK(face_area(m, f) > 0.0);
}

TEST_CASE("triangulate: faces visiting a vertex twice or three times; 2-gons stay") {
  // The spoke's face has 6 corners, the spoke's end between two corners of the same vertex: 3 diagonals.
  Mesh m = cube_with_spoke(FaceId(1));
  apply_operation(m, "triangulate", {{"faces", "1"}});
  test::require_valid(m);
  CHECK(counts(m) == Counts{9, 16, 9});
  // Two spokes from the same corner of the cube's top face: 4 5 7 6 4 x 4 y, vertex 4 three times. V 10,
  // E 14; 8 corners, 5 diagonals, none from 4 to itself.
  Mesh twice = test::cube();
  const CornerId at4 = twice.first_corner(FaceId(1));
  REQUIRE(twice.vertex(at4) == VertexId(4));
  twice.insert_edge(at4, twice.corner(twice.create_vertex({-0.5, -0.8, 1})));
  twice.insert_edge(at4, twice.corner(twice.create_vertex({-0.8, -0.5, 1})));
  REQUIRE(twice.size(FaceId(1)) == 8);
  apply_operation(twice, "triangulate", {{"faces", "1"}});
  test::require_valid(twice);
  CHECK(counts(twice) == Counts{10, 19, 11});
  Mesh g = two_gons();
  apply_operation(g, "triangulate");
  CHECK(g == two_gons());
}

TEST_CASE("triangulate: undo, redo and the log; refusals") {
  test::for_each_modeling_mesh([&](const Mesh& mesh) { check_editor_round_trip(mesh, "triangulate", {}); });
  const Mesh cube = test::cube();
  CHECK(test::check_refusal(cube, "triangulate", {{"faces", "1,2,1"}}, "faces").find("f1 twice") !=
        std::string::npos);
  CHECK(test::check_refusal(cube, "triangulate", {{"faces", "1,17"}}, "faces").find("does not exist") !=
        std::string::npos);
  Mesh m = cube;
  Transaction tx(m);
  const FaceId removed[] = {FaceId(30)};
  CHECK(test::error_message<ParameterError>([&] { triangulate(tx, removed); }).find("does not exist") !=
        std::string::npos);
}

// ---- reverse_orientation
// ------------------------------------------------------------------------------------

TEST_CASE("reverse_orientation: every face reversed on every modeling mesh; twice gives the faces back") {
  test::for_each_modeling_mesh([&](const Mesh& mesh) {
    Mesh m = mesh;
    apply_operation(m, "reverse_orientation");
    test::require_valid(m);
    CHECK(counts(m) == counts(mesh));
    CHECK(m.num_hole_faces() == mesh.num_hole_faces());
    CHECK(face_cycles(m) == face_cycles(mesh, true));
    for (VertexId v : mesh.vertices()) CHECK(m.position(v) == mesh.position(v));
    if (closed(mesh)) {
      CHECK(signed_volume(mesh) > 0.0);
      CHECK(signed_volume(m) == doctest::Approx(-signed_volume(mesh)));
    }
    const std::vector<long> genus_before = [&] {
      std::vector<long> g;
      for (const auto& c : validate(mesh).components) g.push_back(c.genus);
      return g;
    }();
    std::vector<long> genus_after;
    for (const auto& c : validate(m).components) genus_after.push_back(c.genus);
    CHECK(genus_after == genus_before);
    apply_operation(m, "reverse_orientation");
    test::require_valid(m);
    CHECK(face_cycles(m) == face_cycles(mesh));
    if (closed(mesh)) CHECK(signed_volume(m) == doctest::Approx(signed_volume(mesh)));
  });
}

TEST_CASE("reverse_orientation: meshes with point spheres, dangling edges, 2-gons, holes from set_hole") {
  Mesh m = cube_with_spoke(FaceId(1));
  m.create_vertex({4, 4, 4});  // an isolated point sphere stays as it is
  Mesh gons = two_gons();
  for (Mesh* mesh : {&m, &gons}) {
    const Mesh before = *mesh;
    apply_operation(*mesh, "reverse_orientation");
    test::require_valid(*mesh);
    CHECK(counts(*mesh) == counts(before));
    CHECK(face_cycles(*mesh) == face_cycles(before, true));
  }
  // A hole made by hand on a closed mesh keeps its flag on the reversed face.
  Mesh holed = test::cube();
  holed.set_hole(FaceId(3), true);
  const Mesh before = holed;
  apply_operation(holed, "reverse_orientation");
  CHECK(holed.num_hole_faces() == 1);
  CHECK(face_cycles(holed) == face_cycles(before, true));
  Mesh empty;
  apply_operation(empty, "reverse_orientation");
  CHECK(empty == Mesh());
}

TEST_CASE("reverse_orientation: named values follow their elements") {
  Mesh m = build_mesh(test::grid_soup(3, 2));
  auto weight = m.add_vertex_attribute<double>("weight", 0.0);
  auto crease = m.add_edge_attribute<int>("crease", -1);
  auto colour = m.add_face_attribute<glm::dvec3>("colour", glm::dvec3(0.0));
  auto uv = m.add_corner_attribute<glm::dvec3>("uv", glm::dvec3(-1.0));
  for (VertexId v : m.vertices()) weight[v] = 10.0 + v.index();
  // Each value is a function of what the element is, not of its handle: an edge of its two ends, a face of
  // its vertices and hole flag, a corner of its vertex and its face's vertices.
  auto key = [](const Mesh& mesh, FaceId f) {  // the least vertex and the sum of the squares
    std::uint32_t low = ~0u, squares = 0;
    for (VertexId v : vertices(mesh, f)) {
      low = std::min(low, v.index());
      squares += v.index() * v.index();
    }
    return 1000.0 * low + squares;
  };
  for (EdgeId e : m.edges()) {
    crease[e] = int(std::min(m.from(e).index(), m.to(e).index()) * 100 +
                    std::max(m.from(e).index(), m.to(e).index()));
  }
  for (FaceId f : m.faces()) colour[f] = {key(m, f), m.is_hole(f) ? 1.0 : 0.0, double(m.size(f))};
  for (CornerId c : m.corners()) uv[c] = {double(m.vertex(c).index()), key(m, m.face(c)), 7.0};
  Editor ed;
  ed.set_mesh(m);
  const Mesh before = ed.mesh();
  ed.apply("reverse_orientation");
  const Mesh& r = ed.mesh();
  test::require_valid(r);
  for (VertexId v : r.vertices()) CHECK(r.vertex_attribute<double>("weight")[v] == 10.0 + v.index());
  for (EdgeId e : r.edges()) {
    CHECK(r.edge_attribute<int>("crease")[e] == int(std::min(r.from(e).index(), r.to(e).index()) * 100 +
                                                    std::max(r.from(e).index(), r.to(e).index())));
  }
  for (FaceId f : r.faces()) {
    CHECK(r.face_attribute<glm::dvec3>("colour")[f] ==
          glm::dvec3(key(r, f), r.is_hole(f) ? 1.0 : 0.0, double(r.size(f))));
  }
  for (CornerId c : r.corners()) {
    CHECK(r.corner_attribute<glm::dvec3>("uv")[c] ==
          glm::dvec3(double(r.vertex(c).index()), key(r, r.face(c)), 7.0));
  }
  // Exact undo and redo, and the log.
  const Mesh reversed = r;
  REQUIRE(ed.undo());
  CHECK(ed.mesh() == before);
  CHECK(mesh_hash(ed.mesh()) == mesh_hash(before));
  REQUIRE(ed.redo());
  CHECK(ed.mesh() == reversed);
  CHECK(mesh_hash(replay_log(log_text(ed)).mesh()) == mesh_hash(reversed));
}

TEST_CASE("reverse_orientation: undo, redo and the log on every modeling mesh") {
  test::for_each_modeling_mesh(
      [&](const Mesh& mesh) { check_editor_round_trip(mesh, "reverse_orientation", {}); });
}

// ---- transform
// ----------------------------------------------------------------------------------------------

TEST_CASE("transform: the defaults change nothing, on every modeling mesh") {
  test::for_each_modeling_mesh([&](const Mesh& mesh) {
    Mesh m = mesh;
    apply_operation(m, "transform");
    CHECK(m == mesh);
  });
}

TEST_CASE("transform: translate, scale and rotate, in that order about the centre") {
  const Mesh cube = test::cube();  // [-1, 1]^3, vertex i at (i&1 ? 1 : -1, i&2 ? 1 : -1, i&4 ? 1 : -1)
  Mesh moved = cube;
  apply_operation(moved, "transform", {{"translate", glm::dvec3(1, 2, 3)}});
  for (VertexId v : cube.vertices()) CHECK(moved.position(v) == cube.position(v) + glm::dvec3(1, 2, 3));
  CHECK(signed_volume(moved) == doctest::Approx(8.0));
  // Scale (2, 1, 1) then a quarter turn about z: (x, y, z) -> (2x, y, z) -> (-y, 2x, z), about the bbox
  // centre 0; then + (0, 0, 10).
  Mesh m = cube;
  apply_operation(
      m, "transform",
      {{"scale", glm::dvec3(2, 1, 1)}, {"rotate_degrees", 90.0}, {"translate", glm::dvec3(0, 0, 10)}});
  test::require_valid(m);
  for (VertexId v : cube.vertices()) {
    const glm::dvec3 p = cube.position(v);
    const glm::dvec3 q = m.position(v);
    CHECK(q.x == doctest::Approx(-p.y));
    CHECK(q.y == doctest::Approx(2 * p.x));
    CHECK(q.z == doctest::Approx(p.z + 10));
  }
  CHECK(signed_volume(m) == doctest::Approx(16.0));
  // About a given centre: the cube scaled by 3 about its corner (-1,-1,-1) keeps that corner.
  Mesh c = cube;
  apply_operation(c, "transform", {{"scale", glm::dvec3(3, 3, 3)}, {"center", glm::dvec3(-1, -1, -1)}});
  CHECK(c.position(VertexId(0)) == glm::dvec3(-1, -1, -1));
  CHECK(c.position(VertexId(7)) == glm::dvec3(5, 5, 5));
  CHECK(signed_volume(c) == doctest::Approx(8.0 * 27));
  // The default centre is the bounding box's: the open grid [0,3]x[0,2] about (1.5, 1, 0).
  Mesh g = build_mesh(test::grid_soup(3, 2));
  apply_operation(g, "transform", {{"rotate_axis", glm::dvec3(0, 0, 5)}, {"rotate_degrees", 180.0}});
  CHECK(g.position(VertexId(0)).x == doctest::Approx(3.0));
  CHECK(g.position(VertexId(0)).y == doctest::Approx(2.0));
  // A tilted axis: a third of a turn about (1,1,1) takes x to y, y to z, z to x.
  Mesh t = cube;
  apply_operation(t, "transform", {{"rotate_axis", glm::dvec3(1, 1, 1)}, {"rotate_degrees", 120.0}});
  for (VertexId v : cube.vertices()) {
    const glm::dvec3 p = cube.position(v), q = t.position(v);
    CHECK(q.x == doctest::Approx(p.z));
    CHECK(q.y == doctest::Approx(p.x));
    CHECK(q.z == doctest::Approx(p.y));
  }
  // Two negative factors are a half turn: the volume keeps its sign.
  Mesh h = cube;
  apply_operation(h, "transform", {{"scale", glm::dvec3(-1, -2, 1)}});
  CHECK(signed_volume(h) == doctest::Approx(16.0));
}

TEST_CASE("transform: counts and volume sign on every modeling mesh; undo, redo and the log") {
  test::for_each_modeling_mesh([&](const Mesh& mesh) {
    const Params params = {{"scale", glm::dvec3(0.5, -2, -3)},
                           {"rotate_axis", glm::dvec3(1, -2, 0.5)},
                           {"rotate_degrees", 33.0},
                           {"translate", glm::dvec3(-1, 0.25, 7)}};
    const Mesh m = check_editor_round_trip(mesh, "transform", params);
    CHECK(counts(m) == counts(mesh));
    if (closed(mesh)) CHECK(signed_volume(m) == doctest::Approx(signed_volume(mesh) * 0.5 * 2 * 3));
  });
}

TEST_CASE("transform: refusals name the argument and change nothing") {
  const Mesh cube = test::cube();
  CHECK(test::check_refusal(cube, "transform", {{"rotate_axis", glm::dvec3(0.0)}}, "rotate_axis")
            .find("zero") != std::string::npos);
  CHECK(test::check_refusal(cube, "transform", {{"scale", glm::dvec3(1, 0, 1)}}, "scale").find("zero") !=
        std::string::npos);
  CHECK(test::check_refusal(cube, "transform", {{"scale", glm::dvec3(-1, 1, 1)}}, "scale").find("odd") !=
        std::string::npos);
  CHECK(test::check_refusal(cube, "transform", {{"scale", glm::dvec3(-1, -1, -1)}}, "scale").find("odd") !=
        std::string::npos);
  CHECK(test::check_refusal(cube, "transform",
                            {{"scale", glm::dvec3(1e308, 1, 1)}, {"center", glm::dvec3(-1e10, 0, 0)}},
                            "scale")
            .find("finite") != std::string::npos);
  CHECK(test::check_refusal(cube, "transform",
                            {{"scale", glm::dvec3(1e308, 1, 1)}, {"translate", glm::dvec3(1e308, 0, 0)}},
                            "translate")
            .find("finite") != std::string::npos);
  CHECK(test::check_refusal(cube, "transform", {{"rotate_degrees", "x"}}, "rotate_degrees") != "");
  Mesh m = cube;
  Transaction tx(m);
  TransformOptions zero_axis;
  zero_axis.rotate_axis = glm::dvec3(0.0);
  CHECK(test::error_message<ParameterError>([&] { transform(tx, zero_axis); }).find("rotate_axis") !=
        std::string::npos);
  CHECK(tx.size() == 0);
}
