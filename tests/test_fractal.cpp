// sierpinski and menger (docs/modeling.md, "High genus"): the closed-form counts on every modeling mesh, and
// by hand on six of them, at level 1 and level 2 on the cube and the tetrahedron; the genus E - V + 1; the
// face sizes; validity, orientation (signed volume), exact undo, redo and log replay through the editor; the
// geometry against independent constructions (the level-1 Menger sponge of the cube; the volume of the
// Sierpinski pieces and struts of the tetrahedron and the cube, summed by hand); polygon files; point
// spheres, open meshes and attributes; every refusal with its parameter, the mesh unchanged.

#include <doctest/doctest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <glm/geometric.hpp>
#include <limits>
#include <map>
#include <numeric>
#include <string>
#include <vector>

#include <dlfl/build_mesh.h>
#include <dlfl/errors.h>
#include <dlfl/geometry.h>
#include <dlfl/history/editor.h>
#include <dlfl/io/mesh_io.h>
#include <dlfl/navigation.h>
#include <dlfl/operations/menger.h>
#include <dlfl/operations/sierpinski.h>

#include "modeling_checks.h"
#include "modeling_meshes.h"
#include "test_helpers.h"
#include "test_meshes.h"

using namespace dlfl;
using test::Counts;
using test::euler_characteristic;
using test::signed_volume;

namespace {

// The closed forms of docs/modeling.md, for V vertices and E edges.
Counts sierpinski_counts(long v, long e) { return {v + 6 * e, 13 * e, v + 5 * e}; }
Counts menger_counts(long v, long e) { return {2 * v + 4 * e, 12 * e, 6 * e}; }

// Connected components, by union-find over the edges (point spheres are components of their own).
long components(const Mesh& m) {
  std::vector<std::uint32_t> root(m.vertex_capacity());
  std::iota(root.begin(), root.end(), 0u);
  auto find = [&](std::uint32_t x) {
    while (root[x] != x) x = root[x] = root[root[x]];
    return x;
  };
  for (EdgeId e : m.edges()) root[find(m.from(e).index())] = find(m.to(e).index());
  long count = 0;
  for (VertexId v : m.vertices()) count += find(v.index()) == v.index();
  return count;
}

// The genus of a closed connected mesh.
long genus(const Mesh& m) { return 1 - euler_characteristic(m) / 2; }

// Applies `op` through the editor round trip (valid, undo, redo, replay) and checks the counts.
Mesh apply_and_check(const Mesh& start, const std::string& op, const Params& params, Counts expected) {
  const Mesh after = test::check_editor_round_trip(start, op, params);
  CHECK(test::counts(after) == expected);
  return after;
}

// Faces per number of sides.
std::map<std::uint32_t, long> face_sizes(const Mesh& m) {
  std::map<std::uint32_t, long> out;
  for (FaceId f : m.faces()) ++out[m.size(f)];
  return out;
}

long hole_sides(const Mesh& m) {
  long sides = 0;
  for (FaceId f : m.faces()) sides += m.is_hole(f) ? long(m.size(f)) : 0;
  return sides;
}

// The largest distance of a face's corners from the plane through its centroid along its normal.
double nonplanarity(const Mesh& m, FaceId f) {
  const glm::dvec3 n = face_normal(m, f), c = face_centroid(m, f);
  double worst = 0;
  for (VertexId v : vertices(m, f)) worst = std::max(worst, std::abs(glm::dot(m.position(v) - c, n)));
  return worst;
}

double tetrahedron_volume(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c,
                          const glm::dvec3& d) {
  return std::abs(glm::dot(b - a, glm::cross(c - a, d - a))) / 6.0;
}

// The volume of sierpinski's result on a convex polyhedron whose vertices all have valence 3, built from the
// definition: each corner piece is the tetrahedron of the vertex and its three tips (at `scale` along its
// edges); each strut is the prism from the neck triangle (tip, and the neck points at `neck` along the two
// cut edges beside it) at one piece to the one at the other, cut into three tetrahedra. They touch only
// along the neck triangles.
double sierpinski_volume(const PolygonSoup& soup, double scale, double neck) {
  auto at = [&](std::uint32_t i) { return soup.positions[i]; };
  auto tip = [&](std::uint32_t from, std::uint32_t to) { return at(from) + scale * (at(to) - at(from)); };
  // The neck point near tip(u, w) on u's cut edge towards tip(u, x).
  auto neck_point = [&](std::uint32_t u, std::uint32_t w, std::uint32_t x) {
    return tip(u, w) + neck * (tip(u, x) - tip(u, w));
  };
  // Per directed edge (u, w) of a face: its neighbours x before u and y after w in that face.
  std::map<std::pair<std::uint32_t, std::uint32_t>, std::pair<std::uint32_t, std::uint32_t>> beside;
  std::map<std::uint32_t, std::vector<std::uint32_t>> neighbours;
  for (std::size_t f = 0; f < soup.num_faces(); ++f) {
    const auto face = soup.face(f);
    const std::size_t n = face.size();
    for (std::size_t i = 0; i < n; ++i) {
      const std::uint32_t u = face[i], w = face[(i + 1) % n];
      beside[{u, w}] = {face[(i + n - 1) % n], face[(i + 2) % n]};
      neighbours[u].push_back(w);
    }
  }
  double volume = 0;
  for (const auto& entry : neighbours) {
    const std::uint32_t u = entry.first;
    const std::vector<std::uint32_t>& ws = entry.second;
    REQUIRE(ws.size() == 3);
    volume += tetrahedron_volume(at(u), tip(u, ws[0]), tip(u, ws[1]), tip(u, ws[2]));
  }
  for (const auto& [edge, xy] : beside) {
    const auto [u, w] = edge;
    if (u > w) continue;  // each edge once, from the face that runs u -> w
    const auto [x, y] = xy;
    const auto [y2, x2] = beside.at({w, u});  // the other face runs w -> u: y2 before w, x2 after u
    const glm::dvec3 p = tip(u, w), q = tip(w, u);
    const glm::dvec3 a1 = neck_point(u, w, x), b1 = neck_point(w, u, y);
    const glm::dvec3 a2 = neck_point(u, w, x2), b2 = neck_point(w, u, y2);
    volume += tetrahedron_volume(p, a1, a2, q) + tetrahedron_volume(a1, a2, q, b1) +
              tetrahedron_volume(a2, q, b1, b2);
  }
  return volume;
}

}  // namespace

TEST_CASE("sierpinski: closed-form counts, face sizes and genus E - V + 1 on every modeling mesh") {
  for (const auto& [name, mesh] : test::modeling_meshes()) {
    const auto& name_ = name;  // clang 14 cannot capture a structured binding
    CAPTURE(name_);
    const long v = long(mesh.num_vertices()), e = long(mesh.num_edges());
    const Mesh after = apply_and_check(mesh, "sierpinski", {}, sierpinski_counts(v, e));
    CHECK(euler_characteristic(after) == 2 * v - 2 * e);
    CHECK(components(after) == components(mesh));
    if (components(mesh) == 1 && mesh.num_hole_faces() == 0) CHECK(genus(after) == e - v + 1);
    // 2E caps of 5 sides, 2E strut sides and E floors (quads), and per vertex of valence k a 2k-gon.
    std::map<std::uint32_t, long> expected{{5, 2 * e}, {4, 3 * e}};
    for (VertexId x : mesh.vertices()) ++expected[2 * mesh.valence(x)];
    CHECK(face_sizes(after) == expected);
    // The old vertices stay where they were; what is cut from a hole face (a cap per corner and a strut
    // side per side) stays a hole.
    for (VertexId x : mesh.vertices()) CHECK(after.position(x) == mesh.position(x));
    CHECK(long(after.num_hole_faces()) == 2 * hole_sides(mesh));
    if (mesh.num_hole_faces() == 0) {
      CHECK(signed_volume(after) > 0);
      CHECK(signed_volume(after) < signed_volume(mesh));
    }
  }
}

TEST_CASE("menger: closed-form counts, all quads and genus E - V + 1 on every modeling mesh") {
  for (const auto& [name, mesh] : test::modeling_meshes()) {
    const auto& name_ = name;  // clang 14 cannot capture a structured binding
    CAPTURE(name_);
    const long v = long(mesh.num_vertices()), e = long(mesh.num_edges());
    Params out;
    const Mesh after = test::check_editor_round_trip(mesh, "menger", {}, &out);
    CHECK(test::counts(after) == menger_counts(v, e));
    CHECK(euler_characteristic(after) == 2 * v - 2 * e);
    CHECK(components(after) == components(mesh));
    if (components(mesh) == 1 && mesh.num_hole_faces() == 0) CHECK(genus(after) == e - v + 1);
    CHECK(face_sizes(after) == std::map<std::uint32_t, long>{{4, 6 * e}});
    for (VertexId x : mesh.vertices()) CHECK(after.position(x) == mesh.position(x));
    // The skeleton: one vertex per old vertex. A hole face's 2n cells and its tunnel of n walls stay holes.
    CHECK(out.handles<VertexId>("vertices").size() == mesh.num_vertices());
    CHECK(long(after.num_hole_faces()) == 3 * hole_sides(mesh));
    if (mesh.num_hole_faces() == 0) {
      CHECK(signed_volume(after) > 0);
      CHECK(signed_volume(after) < signed_volume(mesh));
    }
  }
}

TEST_CASE("sierpinski and menger: counts and genus by hand on six meshes") {
  // name, V, E, then by hand from V' = V + 6E, E' = 13E, F' = V + 5E (sierpinski) and V' = 2V + 4E,
  // E' = 12E, F' = 6E (menger), and the genus E - V + 1.
  struct Row {
    const char* name;
    Counts sierpinski, menger;
    long genus;
  };
  const std::vector<Row> rows = {
      {"tetrahedron", {40, 78, 34}, {32, 72, 36}, 3},           // V 4, E 6
      {"cube", {80, 156, 68}, {64, 144, 72}, 5},                // V 8, E 12
      {"octahedron", {78, 156, 66}, {60, 144, 72}, 7},          // V 6, E 12
      {"pentagonal prism", {100, 195, 85}, {80, 180, 90}, 6},   // V 10, E 15
      {"hexagonal prism", {120, 234, 102}, {96, 216, 108}, 7},  // V 12, E 18
      {"torus 4x3", {156, 312, 132}, {120, 288, 144}, 13},      // V 12, E 24
  };
  const auto meshes = test::modeling_meshes();
  for (const Row& row : rows) {
    CAPTURE(row.name);
    const auto found =
        std::find_if(meshes.begin(), meshes.end(), [&](const auto& m) { return m.name == row.name; });
    REQUIRE(found != meshes.end());
    const Mesh s = apply_and_check(found->mesh, "sierpinski", {}, row.sierpinski);
    const Mesh g = apply_and_check(found->mesh, "menger", {}, row.menger);
    CHECK(genus(s) == row.genus);
    CHECK(genus(g) == row.genus);
  }
}

TEST_CASE("sierpinski and menger: levels 1 and 2 on the cube and the tetrahedron") {
  // Level 2 applies the operation to level 1; its counts follow from level 1's V and E (docs/modeling.md).
  struct Row {
    const char* op;
    Mesh mesh;
    Counts level1, level2;
    long genus1, genus2;
  };
  const std::vector<Row> rows = {
      // Tetrahedron V 4, E 6 -> V 40, E 78 -> V 40 + 468, E 1014, F 40 + 390.
      {"sierpinski", test::tetrahedron(), {40, 78, 34}, {508, 1014, 430}, 3, 39},
      // Cube V 8, E 12 -> V 80, E 156 -> V 80 + 936, E 2028, F 80 + 780.
      {"sierpinski", test::cube(), {80, 156, 68}, {1016, 2028, 860}, 5, 77},
      // Tetrahedron -> V 32, E 72 -> V 64 + 288, E 864, F 432.
      {"menger", test::tetrahedron(), {32, 72, 36}, {352, 864, 432}, 3, 41},
      // Cube -> V 64, E 144 -> V 128 + 576, E 1728, F 864; genus 81, the Menger sponge's at level 2.
      {"menger", test::cube(), {64, 144, 72}, {704, 1728, 864}, 5, 81},
  };
  for (const Row& row : rows) {
    CAPTURE(row.op);
    CAPTURE(row.level1);
    const Mesh one = apply_and_check(row.mesh, row.op, {}, row.level1);
    CHECK(genus(one) == row.genus1);
    const Mesh two = apply_and_check(one, row.op, {}, row.level2);
    CHECK(genus(two) == row.genus2);
    CHECK(components(two) == 1);
    CHECK(signed_volume(two) > 0);
    CHECK(signed_volume(two) < signed_volume(one));
  }
}

TEST_CASE("menger: the cube becomes the level-1 Menger sponge") {
  // The cube [-1, 1]^3 with the defaults (scale 1/3, depth 1/3): 20 of its 27 sub-cubes of side 2/3 stay.
  // Every vertex lies on the grid of thirds, every face is one of the 72 squares of side 2/3 on the
  // sponge's surface, the volume is 8 x 20/27 and the area 72 x 4/9.
  const Mesh sponge = test::check_editor_round_trip(test::cube(), "menger", {});
  const double third = 1.0 / 3.0;
  for (VertexId v : sponge.vertices()) {
    for (int axis = 0; axis < 3; ++axis) {
      const double x = sponge.position(v)[axis];
      CHECK(std::abs(std::round((x + 1) / (2 * third)) * 2 * third - 1 - x) < 1e-14);
    }
  }
  double area = 0;
  for (FaceId f : sponge.faces()) {
    CHECK(nonplanarity(sponge, f) < 1e-14);
    CHECK(face_area(sponge, f) == doctest::Approx(4.0 / 9.0).epsilon(1e-12));
    area += face_area(sponge, f);
  }
  CHECK(area == doctest::Approx(32.0).epsilon(1e-12));
  CHECK(signed_volume(sponge) == doctest::Approx(8.0 * 20.0 / 27.0).epsilon(1e-12));
  // The skeleton is the cube's central sub-cube: its corners at (+-1/3, +-1/3, +-1/3).
  Params out;
  test::check_editor_round_trip(test::cube(), "menger", {}, &out);
  for (VertexId v : out.handles<VertexId>("vertices")) {
    const glm::dvec3 p = sponge.position(v);
    CHECK(glm::length(glm::abs(p) - glm::dvec3(third)) < 1e-14);
  }
}

TEST_CASE("menger: scale and depth place the centre faces and the skeleton") {
  // The cube with scale 1/2 and depth 1/4: each centre face is its face halved about its centroid (corners
  // at +-1/2 in the face's plane), and the skeleton's corner averages the three tunnels' straight ends,
  // (1/2, 1/2, 1) - 1/4 x 2 x (0, 0, 1) and its rotations: (1/2, 1/2, 1/2).
  Params out;
  const Mesh m =
      test::check_editor_round_trip(test::cube(), "menger", {{"scale", 0.5}, {"depth", 0.25}}, &out);
  for (VertexId v : out.handles<VertexId>("vertices")) {
    CHECK(glm::length(glm::abs(m.position(v)) - glm::dvec3(0.5)) < 1e-14);
  }
  long centre_corners = 0;
  for (VertexId v : m.vertices()) {
    const glm::dvec3 a = glm::abs(m.position(v));
    const double big = std::max({a.x, a.y, a.z});
    centre_corners += big == 1.0 && a.x + a.y + a.z == 2.0 && std::min({a.x, a.y, a.z}) == 0.5;
  }
  CHECK(centre_corners == 24);
}

TEST_CASE("sierpinski: the volume of the pieces and struts, by hand, on the tetrahedron and the cube") {
  for (const PolygonSoup& soup : {test::tetrahedron_soup(), test::cube_soup()}) {
    for (const std::array<double, 2> shares :
         {std::array{0.45, 0.1}, std::array{0.3, 0.25}, std::array{0.49, 0.01}}) {
      const double scale = shares[0], neck = shares[1];
      CAPTURE(scale);
      CAPTURE(neck);
      const Mesh m =
          test::check_editor_round_trip(build_mesh(soup), "sierpinski", {{"scale", scale}, {"neck", neck}});
      CHECK(signed_volume(m) == doctest::Approx(sierpinski_volume(soup, scale, neck)).epsilon(1e-12));
      // Every face is planar: the caps lie in the old faces, the struts' sides too, the pieces' inner faces
      // in the planes of their tips, and the floors are trapezoids (their long sides parallel to the edge).
      for (FaceId f : m.faces()) CHECK(nonplanarity(m, f) < 1e-12);
    }
  }
}

TEST_CASE("sierpinski and menger: results are polygon files") {
  // No two edges join the same two vertices and no face visits a vertex twice, so a polygon file holds
  // the result: written as OBJ and read back it has the same counts and validates.
  for (const char* op : {"sierpinski", "menger"}) {
    CAPTURE(op);
    Mesh m = test::cube();
    {
      Transaction tx(m);
      if (std::string(op) == "sierpinski") sierpinski(tx);
      if (std::string(op) == "menger") menger(tx);
      tx.commit();
    }
    const auto path = test::scratch(std::string(op) + ".obj");
    write_mesh(m, path);
    const Mesh back = read_mesh(path);
    test::require_valid(back);
    CHECK(test::counts(back) == test::counts(m));
  }
}

TEST_CASE("sierpinski and menger: point spheres are left, vertex attributes kept") {
  Mesh m = test::cube();
  const VertexId lone = m.create_vertex({5, 5, 5});
  auto weight = m.add_vertex_attribute<double>("weight", 0.0);
  for (VertexId v : m.vertices()) weight[v] = 1.0 + v.index();
  // sierpinski: the cube's 80, 156, 68 and the point sphere (V 1, F 1; in the closed form through V).
  const Mesh s = apply_and_check(m, "sierpinski", {}, {81, 156, 69});
  CHECK(s.is_point_sphere(lone));
  // menger: the cube's 64, 144, 72 and the point sphere, which the skeleton leaves out.
  const Mesh g = apply_and_check(m, "menger", {}, {65, 144, 73});
  CHECK(g.is_point_sphere(lone));
  for (const Mesh* after : {&s, &g}) {
    const auto kept = after->vertex_attribute<double>("weight");
    for (VertexId v : m.vertices()) {
      CHECK(kept[v] == 1.0 + v.index());
      CHECK(after->position(v) == m.position(v));
    }
  }
}

TEST_CASE("sierpinski and menger: refusals name their parameter and change nothing") {
  const Mesh cube = test::cube();
  const double inf = std::numeric_limits<double>::infinity(), nan = std::numeric_limits<double>::quiet_NaN();
  for (double bad : {0.0, 0.5, -0.1, 0.7, inf, nan}) {
    CAPTURE(bad);
    test::check_refusal(cube, "sierpinski", {{"scale", bad}}, "scale");
    test::check_refusal(cube, "sierpinski", {{"neck", bad}}, "neck");
  }
  for (double bad : {0.0, 1.0, -0.5, 2.0, inf, nan}) {
    CAPTURE(bad);
    test::check_refusal(cube, "menger", {{"scale", bad}}, "scale");
  }
  for (double bad : {0.0, -1.0, inf, nan}) {
    CAPTURE(bad);
    test::check_refusal(cube, "menger", {{"depth", bad}}, "depth");
  }
  // A vertex of valence 1: the cube with an edge from a corner to a new vertex.
  Mesh dangling = test::cube();
  const VertexId end = dangling.create_vertex({3, 3, 3});
  dangling.insert_edge(dangling.corner(VertexId(7)), dangling.corner(end));
  for (const char* op : {"sierpinski", "menger"}) {
    CAPTURE(op);
    CHECK(test::check_refusal(dangling, op, {}, "scale").find("has valence 1") != std::string::npos);
  }
  // Coordinates whose differences overflow: the tips and cuts would not be finite.
  PolygonSoup huge = test::tetrahedron_soup();
  for (auto& p : huge.positions) p *= 1.5e308;
  for (const char* op : {"sierpinski", "menger"}) {
    CAPTURE(op);
    CHECK(test::check_refusal(build_mesh(huge), op, {}, "scale").find("finite") != std::string::npos);
  }
  // A tunnel so deep that the skeleton overflows.
  PolygonSoup large = test::tetrahedron_soup();
  for (auto& p : large.positions) p *= 1e300;
  CHECK(test::check_refusal(build_mesh(large), "menger", {{"depth", 1e10}}, "depth").find("skeleton") !=
        std::string::npos);

  // The library functions refuse as the registered operations do, with the operations' wording.
  Mesh m = cube;
  {
    Transaction tx(m);
    CHECK(test::error_message<ParameterError>([&] {
            sierpinski(tx, {0.5, 0.1});
          }).rfind("sierpinski: parameter scale = 0.5 is outside (0, 0.5)", 0) == 0);
    CHECK(test::error_message<ParameterError>([&] {
            sierpinski(tx, {0.45, 0.0});
          }).rfind("sierpinski: parameter neck = 0 is outside (0, 0.5)", 0) == 0);
    CHECK(test::error_message<ParameterError>([&] {
            menger(tx, {1.0, 0.5});
          }).rfind("menger: parameter scale = 1 is outside (0, 1)", 0) == 0);
    CHECK(test::error_message<ParameterError>([&] {
            menger(tx, {0.5, -1.0});
          }) == "menger: parameter depth = -1 must be finite and > 0");
    CHECK(tx.size() == 0);
  }
  CHECK(m == cube);
  CHECK_NOTHROW(check_sierpinski(cube, {}));
  CHECK_NOTHROW(check_menger(cube, {}));
}
