// extrude_face and inset_face (docs/modeling.md, "Extrusions"): the counts of every style on faces of 3 to 8
// sides, derived by hand from what each style builds (docs/modeling.md); the shapes of the new faces; the
// Euler characteristic, the validator, hole flags and orientation (the signed volume); closed-form volumes
// and positions; the regular solids the shape styles build on regular faces; exact undo, redo and log
// replay through the editor; and every refusal, naming its parameter, with the mesh unchanged.

#include <doctest/doctest.h>

#include <cmath>
#include <glm/geometric.hpp>
#include <limits>
#include <map>
#include <numbers>
#include <string>
#include <vector>

#include <dlfl/errors.h>
#include <dlfl/geometry.h>
#include <dlfl/history/editor.h>
#include <dlfl/history/oplog.h>
#include <dlfl/mesh_hash.h>
#include <dlfl/navigation.h>
#include <dlfl/operations/extrude_face.h>
#include <dlfl/operations/inset_face.h>
#include <dlfl/operations/operation.h>

#include "modeling_checks.h"
#include "modeling_meshes.h"
#include "test_helpers.h"

using namespace dlfl;

namespace {

constexpr double phi = std::numbers::phi;

const std::vector<std::string> all_styles = {"cubical",         "doo-sabin",    "octahedral",  "stellate",
                                             "double-stellate", "dodecahedral", "icosahedral", "dome"};
// The styles that end in a moved face, which segments repeat.
const std::vector<std::string> segment_styles = {"cubical", "doo-sabin", "octahedral", "dodecahedral",
                                                 "icosahedral"};

using test::apply_and_check;
using test::Delta;
using test::euler_characteristic;
using test::refused_parameter;
using test::signed_volume;

// The change of V, E and F that a style makes on a face of n sides with s segments, from what it builds:
// cubical and doo-sabin a ring of n new vertices, n rungs and n ring edges per segment, the face split into
// n quads and the moved face; octahedral n vertices over the edges, each joined to two old corners and the
// next new one, 2n triangles; stellate an apex with n edges, the face cut into n triangles; double-stellate
// that, then a stellation of each triangle (+1 vertex, +3 edges, +2 faces each); dodecahedral a cubical
// ring, an octahedral ring and a cubical ring, with the two middle rings' edges deleted (-n edges and -n
// faces each); icosahedral an octahedral ring, a cubical ring with the ring between deleted, then n
// stellated pentagons (+1, +5, +4 each); dome five cubical rings and a stellation.
Delta expected_delta(const std::string& style, long n, long s) {
  if (style == "cubical" || style == "doo-sabin") return {n * s, 2 * n * s, n * s};
  if (style == "octahedral") return {n * s, 3 * n * s, 2 * n * s};
  if (style == "stellate") return {1, n, n - 1};
  if (style == "double-stellate") return {1 + n, n + 3 * n, (n - 1) + 2 * n};
  if (style == "dodecahedral")
    return {3 * n * s, (2 * n + 3 * n - n + 2 * n - n) * s, (n + 2 * n - n + n - n) * s};
  if (style == "icosahedral")
    return {3 * n * s, (3 * n + 2 * n - n + 5 * n) * s, (2 * n + n - n + 4 * n) * s};
  REQUIRE(style == "dome");
  return {5 * n + 1, 5 * 2 * n + n, 5 * n + n - 1};
}

// The faces the style leaves where the face was, by number of sides (the faces touching a new vertex).
std::map<std::uint32_t, long> expected_shapes(const std::string& style, std::uint32_t n, long s) {
  std::map<std::uint32_t, long> shapes;
  if (style == "cubical" || style == "doo-sabin") {
    shapes[4] += n * s;
    shapes[n] += 1;
  } else if (style == "octahedral") {
    shapes[3] += 2 * n * s;
    shapes[n] += 1;
  } else if (style == "stellate") {
    shapes[3] += n;
  } else if (style == "double-stellate") {
    shapes[3] += 3 * n;
  } else if (style == "dodecahedral") {
    shapes[5] += 2 * n * s;
    shapes[n] += 1;
  } else if (style == "icosahedral") {
    shapes[3] += 6 * n * s;
    shapes[n] += 1;
  } else {
    shapes[4] += 5 * n;
    shapes[3] += n;
  }
  return shapes;
}

std::map<std::uint32_t, long> shapes_around_new_vertices(const Mesh& m, std::uint32_t first_new_vertex) {
  std::map<std::uint32_t, long> shapes;
  for (FaceId f : m.faces()) {
    bool touches = false;
    for (VertexId v : vertices(m, f)) touches = touches || v.index() >= first_new_vertex;
    if (touches) ++shapes[m.size(f)];
  }
  return shapes;
}

// The meshes of modeling_meshes() and a heptagonal prism, so that every size from 3 to 8 is there.
std::vector<test::ModelingMesh> meshes() {
  auto out = test::modeling_meshes();
  out.push_back({"heptagonal prism", build_mesh(test::prism_soup(7))});
  return out;
}

// The first surface face of each size.
std::vector<FaceId> one_face_per_size(const Mesh& m) {
  std::map<std::uint32_t, FaceId> by_size;
  for (FaceId f : surface_faces(m)) by_size.emplace(m.size(f), f);
  std::vector<FaceId> out;
  for (const auto& [size, f] : by_size) out.push_back(f);
  return out;
}

// The new vertex joined by an edge to `old` (the rung of a cubical ring).
VertexId new_neighbour(const Mesh& m, VertexId old, std::uint32_t first_new_vertex) {
  for (VertexId w : neighbours(m, old)) {
    if (w.index() >= first_new_vertex) return w;
  }
  return VertexId();
}

void check_near(const glm::dvec3& a, const glm::dvec3& b) {
  CAPTURE(a.x);
  CAPTURE(a.y);
  CAPTURE(a.z);
  CHECK(glm::length(a - b) < 1e-12);
}

// The cube's face at z = +1 (corners (+-1, +-1, 1), normal +z, area 4) and its vertex at (x, y, 1).
FaceId cube_top(const Mesh& m) {
  for (FaceId f : surface_faces(m)) {
    if (face_centroid(m, f) == glm::dvec3(0, 0, 1)) return f;
  }
  FAIL("no top face");
  return FaceId();
}
VertexId cube_vertex(const Mesh& m, double x, double y, double z) {
  for (VertexId v : m.vertices()) {
    if (m.position(v) == glm::dvec3(x, y, z)) return v;
  }
  FAIL("no such vertex");
  return VertexId();
}

// An editor on an open nx x ny grid with the faces the refusals need: the grid's hole face, a point sphere's
// face and the faces of three points on a line (no normal).
struct RefusalScene {
  Editor ed;
  FaceId hole, sphere_face;
  FaceManifold flat;

  RefusalScene(int nx, int ny) {
    ed.set_mesh(build_mesh(test::grid_soup(nx, ny)));
    for (FaceId f : ed.mesh().faces()) {
      if (ed.mesh().is_hole(f)) hole = f;
    }
    sphere_face = ed.mesh().face(ed.mesh().corner(ed.create_vertex({9, 9, 9})));
    flat = ed.create_face_manifold(std::vector<glm::dvec3>{{0, 0, 5}, {1, 0, 5}, {2, 0, 5}});
  }
};

}  // namespace

TEST_CASE("extrude_face: every style's counts and new faces on faces of 3 to 8 sides") {
  test::for_each_mesh(meshes(), [&](const Mesh& mesh) {
    for (FaceId f : one_face_per_size(mesh)) {
      const auto n = mesh.size(f);
      for (const std::string& style : all_styles) {
        CAPTURE(n);
        CAPTURE(style);
        const Params out = apply_and_check(mesh, "extrude_face", {{"face", f}, {"style", style}},
                                           expected_delta(style, n, 1))
                               .out;
        Mesh after = mesh;
        apply_operation(after, "extrude_face", {{"face", f}, {"style", style}});
        CHECK(shapes_around_new_vertices(after, mesh.vertex_capacity()) == expected_shapes(style, n, 1));
        for (FaceId g : after.faces()) {
          if (g.index() >= mesh.face_capacity()) CHECK_FALSE(after.is_hole(g));
        }
        const bool cone = style == "stellate" || style == "double-stellate" || style == "dome";
        CHECK(out.has("face") == !cone);
        CHECK(out.has("vertex") == cone);
        // The moved face's centroid, or the apex, ends on the axis, 1 (the default distance) along the
        // normal; the moved face is parallel to the face (the faces are planar) and turns the same way.
        const glm::dvec3 c = face_centroid(mesh, f), normal = face_normal(mesh, f);
        if (cone) {
          check_near(after.position(out.get("vertex").as_handle<VertexId>()), c + normal);
        } else {
          const FaceId end = out.get("face").as_handle<FaceId>();
          CHECK(after.size(end) == n);
          check_near(face_centroid(after, end), c + normal);
          CHECK(glm::dot(face_normal(after, end), normal) == doctest::Approx(1.0));
        }
      }
    }
  });
}

TEST_CASE("extrude_face: segments 1 to 8 repeat the unit of the styles that end in a moved face") {
  const std::vector<test::ModelingMesh> some = {{"cube", build_mesh(test::cube_soup())},
                                                {"pentagonal prism", build_mesh(test::prism_soup(5))},
                                                {"open grid", build_mesh(test::grid_soup(3, 2))}};
  test::for_each_mesh(some, [&](const Mesh& mesh) {
    const FaceId f = one_face_per_size(mesh).back();
    const auto n = mesh.size(f);
    for (const std::string& style : segment_styles) {
      for (long s = 1; s <= 8; ++s) {
        CAPTURE(style);
        CAPTURE(s);
        apply_and_check(
            mesh, "extrude_face",
            {{"face", f}, {"style", style}, {"segments", s}, {"distance", 0.5}, {"rotate_degrees", 30.0}},
            expected_delta(style, n, s));
        Mesh after = mesh;
        apply_operation(after, "extrude_face", {{"face", f}, {"style", style}, {"segments", s}});
        CHECK(shapes_around_new_vertices(after, mesh.vertex_capacity()) == expected_shapes(style, n, s));
      }
    }
  });
}

TEST_CASE("extrude_face: a cubical extrusion along the normal adds distance times area to the volume") {
  test::for_each_mesh(meshes(), [&](const Mesh& mesh) {
    if (mesh.num_hole_faces() != 0) return;
    for (FaceId f : one_face_per_size(mesh)) {
      for (double d : {0.5, 1.5, -0.125}) {
        for (long s : {1, 3}) {
          CAPTURE(d);
          CAPTURE(s);
          Mesh m = mesh;
          apply_operation(m, "extrude_face", {{"face", f}, {"distance", d}, {"segments", s}});
          CHECK(signed_volume(m) ==
                doctest::Approx(signed_volume(mesh) + d * face_area(mesh, f)).epsilon(1e-12));
        }
      }
    }
  });
  // The cube of side 2: 8 + 4d.
  Mesh cube = build_mesh(test::cube_soup());
  apply_operation(cube, "extrude_face", {{"face", cube_top(cube)}, {"distance", 0.75}});
  CHECK(signed_volume(cube) == doctest::Approx(8 + 4 * 0.75));
}

TEST_CASE("extrude_face: stellate and double-stellate add pyramids of volume d A / 3 and 2 d A / 9") {
  // On a convex planar face of area A with centroid c: stellate is the pyramid of height d over it. The
  // second apexes of double-stellate, the centroids of (c, p_i, p_i+1), lie in the face and cut a third of
  // each of those triangles away, so the apex stands over a star of area 2A/3.
  for (const char* name : {"tetrahedron", "cube", "octahedron", "pentagonal prism", "octagonal prism"}) {
    test::for_each_mesh(meshes(), [&](const std::string& mesh_name, const Mesh& mesh) {
      if (mesh_name != name) return;
      for (FaceId f : one_face_per_size(mesh)) {
        CAPTURE(mesh.size(f));
        const double area = face_area(mesh, f), volume = signed_volume(mesh);
        Mesh once = mesh, twice = mesh;
        apply_operation(once, "extrude_face", {{"face", f}, {"style", "stellate"}, {"distance", 0.8}});
        apply_operation(twice, "extrude_face",
                        {{"face", f}, {"style", "double-stellate"}, {"distance", 0.8}});
        CHECK(signed_volume(once) == doctest::Approx(volume + 0.8 * area / 3));
        CHECK(signed_volume(twice) == doctest::Approx(volume + 2 * 0.8 * area / 9));
      }
    });
  }
}

namespace {

// The lengths of the edges of the solid an extrusion stood on face f: every new edge and f's own.
std::vector<double> solid_edge_lengths(const Mesh& before, FaceId f, const Mesh& after) {
  std::vector<double> lengths;
  for (EdgeId e : after.edges()) {
    bool keep = e.index() >= before.edge_capacity();
    for (EdgeId g : edges(before, f)) keep = keep || g == e;
    if (keep) lengths.push_back(glm::length(after.position(after.from(e)) - after.position(after.to(e))));
  }
  return lengths;
}

void check_regular_solid(const Mesh& mesh, FaceId f, const std::string& style, double distance, double edge,
                         std::size_t edges_of_solid, double volume_of_solid) {
  CAPTURE(style);
  Mesh m = mesh;
  apply_operation(m, "extrude_face", {{"face", f}, {"style", style}, {"distance", distance}});
  const auto lengths = solid_edge_lengths(mesh, f, m);
  CHECK(lengths.size() == edges_of_solid);
  for (double l : lengths) CHECK(l == doctest::Approx(edge).epsilon(1e-12));
  CHECK(signed_volume(m) == doctest::Approx(signed_volume(mesh) + volume_of_solid).epsilon(1e-12));
  for (FaceId g : m.faces()) {
    if (g.index() >= mesh.face_capacity() || g == f) CHECK(face_area(m, g) > 0);
  }
}

}  // namespace

TEST_CASE("extrude_face: the shape styles build the regular solid on a regular face at its height") {
  // The tetrahedron's faces are regular triangles of edge a = 2 sqrt 2 (volume 8/3). A regular octahedron
  // of edge a is a sqrt(2/3) high between opposite faces, volume sqrt(2)/3 a^3; an icosahedron phi^2 a /
  // sqrt(3), volume 5 (3 + sqrt 5) / 12 a^3 (12 edges and 30 edges).
  const Mesh tetra = build_mesh(test::tetrahedron_soup());
  const FaceId t = *surface_faces(tetra).begin();
  const double a = 2 * std::sqrt(2.0);
  check_regular_solid(tetra, t, "octahedral", a * std::sqrt(2.0 / 3.0), a, 12,
                      std::sqrt(2.0) / 3 * a * a * a);
  check_regular_solid(tetra, t, "icosahedral", phi * phi * a / std::sqrt(3.0), a, 30,
                      5 * (3 + std::sqrt(5.0)) / 12 * a * a * a);
  // The pentagonal prism's top is a regular pentagon of circumradius 1, edge b = 2 sin(pi/5). A regular
  // dodecahedron of edge b is b sqrt(5/2 + 11 sqrt(5) / 10) high, volume (15 + 7 sqrt 5) / 4 b^3 (30 edges);
  // its faces are planar: each new pentagon's corners lie in one plane.
  const Mesh prism = build_mesh(test::prism_soup(5));
  FaceId top;
  for (FaceId f : surface_faces(prism)) {
    if (prism.size(f) == 5 && face_centroid(prism, f).z > 0.5) top = f;
  }
  const double b = 2 * std::sin(std::numbers::pi / 5);
  const double height = b * std::sqrt(2.5 + 1.1 * std::sqrt(5.0));
  check_regular_solid(prism, top, "dodecahedral", height, b, 30, (15 + 7 * std::sqrt(5.0)) / 4 * b * b * b);
  Mesh m = prism;
  apply_operation(m, "extrude_face", {{"face", top}, {"style", "dodecahedral"}, {"distance", height}});
  for (FaceId g : m.faces()) {
    if (g.index() < prism.face_capacity() && g != top) continue;
    const glm::dvec3 n = face_normal(m, g), c = face_centroid(m, g);
    for (VertexId v : vertices(m, g)) CHECK(std::abs(glm::dot(m.position(v) - c, n)) < 1e-12);
  }
}

TEST_CASE("extrude_face: rotate_degrees turns and scale shrinks the moved face, spread over the segments") {
  const Mesh cube = build_mesh(test::cube_soup());
  const FaceId top = cube_top(cube);
  // One segment, d = 2, 90 degrees, scale 1/2: the corner over (1, -1, 1) goes to c + (0, 0, 2) + R90 (1/2
  // (1, -1, 0)) = (0.5, 0.5, 3).
  Mesh m = cube;
  const Params out = apply_operation(
      m, "extrude_face", {{"face", top}, {"distance", 2.0}, {"rotate_degrees", 90.0}, {"scale", 0.5}});
  const VertexId corner = cube_vertex(m, 1, -1, 1);
  check_near(m.position(new_neighbour(m, corner, cube.vertex_capacity())), {0.5, 0.5, 3});
  CHECK(face_area(m, out.get("face").as_handle<FaceId>()) == doctest::Approx(1.0));
  // Two segments end in the same place; the ring between is half-way: 45 degrees, scale sqrt(1/2), height
  // 1, so (1, -1, 0) sqrt(1/2) turned by 45 degrees is (1, 0, 0), at (1, 0, 2).
  Mesh two = cube;
  apply_operation(
      two, "extrude_face",
      {{"face", top}, {"distance", 2.0}, {"rotate_degrees", 90.0}, {"scale", 0.5}, {"segments", 2}});
  const VertexId middle = new_neighbour(two, cube_vertex(two, 1, -1, 1), cube.vertex_capacity());
  check_near(two.position(middle), {1, 0, 2});
  check_near(two.position(new_neighbour(two, middle, cube.vertex_capacity() + 4)), {0.5, 0.5, 3});
}

TEST_CASE("extrude_face: a given direction is normalised and the face moves along it") {
  // Along (1, 0, 1) by sqrt 2: every corner moves by (1, 0, 1); the slanted prism over the area 4 is 1 high.
  Mesh m = build_mesh(test::cube_soup());
  const FaceId top = cube_top(m);
  const auto first_new = m.vertex_capacity();
  apply_operation(m, "extrude_face",
                  {{"face", top}, {"distance", std::sqrt(2.0)}, {"direction", glm::dvec3(1, 0, 1)}});
  for (double x : {-1.0, 1.0}) {
    for (double y : {-1.0, 1.0}) {
      check_near(m.position(new_neighbour(m, cube_vertex(m, x, y, 1), first_new)), {x + 1, y, 2});
    }
  }
  CHECK(signed_volume(m) == doctest::Approx(12.0));
  // A degenerate face (collinear corners) has no normal, but extrudes along a given direction.
  Mesh flat;
  const FaceManifold fm =
      create_face_manifold(flat, std::vector<glm::dvec3>{{0, 0, 0}, {1, 0, 0}, {2, 0, 0}});
  apply_and_check(flat, "extrude_face", {{"face", fm.front}, {"direction", glm::dvec3(0, 0, 1)}},
                  expected_delta("cubical", 3, 1));
}

TEST_CASE("extrude_face: a 2-gon and a face that visits a vertex twice extrude as any face of their size") {
  // A 2-gon (a face manifold of two points) has no normal, so it goes along a given direction. A spike (an
  // edge to a new vertex q inside the cube's top face, which then runs ..., p, q, p, ...) makes a 6-gon that
  // visits p twice and lies on both sides of the spike's edge.
  Mesh two_gon;
  const FaceManifold fm = create_face_manifold(two_gon, std::vector<glm::dvec3>{{0, 0, 0}, {1, 0, 0}});
  Mesh spiked = build_mesh(test::cube_soup());
  const FaceId top = cube_top(spiked);
  const VertexId q = spiked.create_vertex({0.2, 0.1, 1});
  spiked.insert_edge(spiked.first_corner(top), spiked.corner(q));
  REQUIRE(spiked.size(top) == 6);
  for (const std::string& style : all_styles) {
    CAPTURE(style);
    const Params along = {{"face", fm.front}, {"style", style}, {"direction", glm::dvec3(0, 0, 1)}};
    apply_and_check(two_gon, "extrude_face", along, expected_delta(style, 2, 1));
    Mesh m = two_gon;
    apply_operation(m, "extrude_face", along);
    CHECK(shapes_around_new_vertices(m, two_gon.vertex_capacity()) == expected_shapes(style, 2, 1));
    apply_and_check(spiked, "extrude_face", {{"face", top}, {"style", style}}, expected_delta(style, 6, 1));
  }
  apply_and_check(spiked, "inset_face", {{"face", top}, {"depth", 0.5}}, {6, 12, 6});
}

TEST_CASE("extrude_face: a list of faces extrudes each on its own, as one operation") {
  const Mesh cube = build_mesh(test::cube_soup());
  const std::vector<FaceId> faces = {FaceId(0), FaceId(2), FaceId(1)};  // 0 and 2 share an edge
  for (const std::string& style : all_styles) {
    CAPTURE(style);
    const Delta one = expected_delta(style, 4, 1);
    const Params out = apply_and_check(cube, "extrude_face", {{"faces", faces}, {"style", style}},
                                       {3 * one.v, 3 * one.e, 3 * one.f})
                           .out;
    const bool cone = style == "stellate" || style == "double-stellate" || style == "dome";
    CHECK(out.has(cone ? "vertices" : "faces"));
    CHECK((cone ? out.get("vertices") : out.get("faces")).as_integers().size() == 3);
    CHECK_FALSE(out.has("face"));
  }
  // The same as one face after another.
  Mesh together = cube, apart = cube;
  apply_operation(together, "extrude_face", {{"faces", faces}, {"style", "dodecahedral"}});
  for (FaceId f : faces) apply_operation(apart, "extrude_face", {{"face", f}, {"style", "dodecahedral"}});
  CHECK(together == apart);
}

TEST_CASE("extrude_face: hole flags stay where they were on an open mesh") {
  const Mesh grid = build_mesh(test::grid_soup(3, 2));
  REQUIRE(grid.num_hole_faces() == 1);
  for (const std::string& style : all_styles) {
    CAPTURE(style);
    Mesh m = grid;
    apply_operation(m, "extrude_face", {{"face", *surface_faces(grid).begin()}, {"style", style}});
    std::size_t holes = 0;
    for (FaceId f : m.faces()) holes += m.is_hole(f);
    CHECK(holes == 1);
    for (FaceId f : m.faces()) {
      if (f.index() < grid.face_capacity()) CHECK(m.is_hole(f) == grid.is_hole(f));
    }
  }
}

TEST_CASE("extrude_face: bad arguments are refused, naming the parameter, with the mesh unchanged") {
  RefusalScene scene(3, 2);
  Editor& ed = scene.ed;
  const FaceId f = FaceId(0), g = FaceId(1);
  const std::string op = "extrude_face";
  CHECK(refused_parameter(ed, op, {{"face", f}, {"faces", std::vector<FaceId>{g}}}, "exactly one") == "face");
  CHECK(refused_parameter(ed, op, {{"distance", 1.0}}, "exactly one") == "face");
  CHECK(refused_parameter(ed, op, {{"faces", std::vector<FaceId>{f, g, f}}}, "listed twice") == "faces");
  CHECK(refused_parameter(ed, op, {{"faces", std::vector<std::int64_t>{}}}, "empty") == "faces");
  CHECK(refused_parameter(ed, op, {{"face", scene.hole}}, "hole") == "face");
  CHECK(refused_parameter(ed, op, {{"faces", std::vector<FaceId>{f, scene.hole}}}, "hole") == "faces");
  CHECK(refused_parameter(ed, op, {{"face", scene.sphere_face}}, "point sphere") == "face");
  CHECK(refused_parameter(ed, op, {{"faces", std::vector<FaceId>{scene.sphere_face}}}, "point sphere") ==
        "faces");
  CHECK(refused_parameter(ed, op, {{"face", FaceId(ed.mesh().face_capacity())}}) == "face");
  CHECK(refused_parameter(ed, op, {{"face", scene.flat.front}}, "no normal") == "face");
  CHECK(refused_parameter(ed, op, {{"face", f}, {"direction", glm::dvec3(0, 0, 0)}}, "no direction") ==
        "direction");
  CHECK(refused_parameter(ed, op, {{"face", f}, {"segments", 0}}) == "segments");
  CHECK(refused_parameter(ed, op, {{"face", f}, {"segments", 10001}}) == "segments");
  for (const char* cone : {"stellate", "double-stellate", "dome"}) {
    CHECK(refused_parameter(ed, op, {{"face", f}, {"style", cone}, {"segments", 2}}, "cone") == "segments");
  }
  for (const char* point : {"stellate", "double-stellate"}) {
    CHECK(refused_parameter(ed, op, {{"face", f}, {"style", point}, {"rotate_degrees", 10.0}}, "turn") ==
          "rotate_degrees");
    CHECK(refused_parameter(ed, op, {{"face", f}, {"style", point}, {"scale", 2.0}}, "to scale") == "scale");
  }
  CHECK(refused_parameter(ed, op, {{"face", f}, {"scale", 0.0}}) == "scale");
  CHECK(refused_parameter(ed, op, {{"face", f}, {"scale", -1.0}}) == "scale");
  CHECK(refused_parameter(ed, op, {{"face", f}, {"distance", std::nan("")}}) == "distance");
  CHECK(
      refused_parameter(ed, op, {{"face", f}, {"rotate_degrees", std::numeric_limits<double>::infinity()}}) ==
      "rotate_degrees");
  CHECK(refused_parameter(ed, op, {{"face", f}, {"style", "cubicle"}}) == "style");
  // Positions that would not be finite: a face far out moved further, a face scaled beyond the doubles.
  PolygonSoup far = test::cube_soup();
  for (auto& p : far.positions) p *= glm::dvec3(10, 10, 1e307);
  Editor big;
  big.set_mesh(build_mesh(far));
  FaceId far_top;  // at z = 1e307, its corners 10 from its centre
  for (FaceId h : big.mesh().faces()) {
    bool up = true;
    for (VertexId v : vertices(big.mesh(), h)) up = up && big.mesh().position(v).z > 0;
    if (up) far_top = h;
  }
  CHECK(refused_parameter(big, op,
                          {{"face", far_top}, {"distance", 1.7e308}, {"direction", glm::dvec3(0, 0, 1)}},
                          "not be finite") == "distance");
  CHECK(refused_parameter(big, op, {{"face", far_top}, {"scale", 1e308}, {"direction", glm::dvec3(0, 0, 1)}},
                          "not be finite") == "scale");
  // The library functions refuse as the operation does, before any change.
  Mesh m = build_mesh(test::cube_soup());
  const Mesh before = m;
  {
    Transaction tx(m);
    ExtrudeFaceOptions o;
    o.style = ExtrudeStyle::stellate;
    o.segments = 2;
    const auto err = [&](auto&& f) {
      try {
        f();
      } catch (const ParameterError& e) {
        return e.parameter();
      }
      return std::string("(accepted)");
    };
    CHECK(err([&] { extrude_face(tx, FaceId(0), o); }) == "segments");
    CHECK(err([&] { extrude_face(tx, FaceId(99), {}); }) == "face");
    const std::vector<FaceId> twice = {FaceId(1), FaceId(1)};
    CHECK(err([&] { extrude_faces(tx, twice, {}); }) == "faces");
    CHECK(tx.size() == 0);
  }
  CHECK(m == before);
}

TEST_CASE("extrude_face: the library function returns the moved face or the apex") {
  Mesh m = build_mesh(test::cube_soup());
  const FaceId top = cube_top(m);
  Transaction tx(m);
  const ExtrudeFaceResult r = extrude_face(tx, top, {});
  CHECK(m.size(r.end_face) == 4);
  CHECK(face_centroid(m, r.end_face) == glm::dvec3(0, 0, 2));
  CHECK(face_normal(m, r.end_face) == glm::dvec3(0, 0, 1));
  CHECK_FALSE(r.apex.valid());
  ExtrudeFaceOptions cone;
  cone.style = ExtrudeStyle::stellate;
  cone.distance = 0.5;
  const ExtrudeFaceResult s = extrude_face(tx, r.end_face, cone);
  CHECK(m.position(s.apex) == glm::dvec3(0, 0, 2.5));
  CHECK(m.valence(s.apex) == 4);
  CHECK_FALSE(s.end_face.valid());
  tx.commit();
  test::require_valid(m);
}

TEST_CASE("extrude_face and inset_face: the parameters and defaults of the contract") {
  std::map<std::string, Value> defaults;
  for (const ParamSpec& p : find_operation("extrude_face").params) defaults[p.name] = p.default_value;
  CHECK(defaults.size() == 8);
  CHECK(defaults.at("face").empty());
  CHECK(defaults.at("faces").empty());
  CHECK(defaults.at("direction").empty());
  CHECK(defaults.at("distance") == Value(1.0));
  CHECK(defaults.at("segments") == Value(1));
  CHECK(defaults.at("rotate_degrees") == Value(0.0));
  CHECK(defaults.at("scale") == Value(1.0));
  CHECK(defaults.at("style") == Value("cubical"));
  std::map<std::string, Value> inset;
  for (const ParamSpec& p : find_operation("inset_face").params) inset[p.name] = p.default_value;
  CHECK(inset.size() == 4);
  CHECK(inset.at("amount") == Value(0.25));
  CHECK(inset.at("depth") == Value(0.0));
}

// ---- inset_face ----------------------------------------------------------------------------------------

TEST_CASE("inset_face: a copy inside every face size, joined by n quads: V+n, E+2n, F+n") {
  test::for_each_mesh(meshes(), [&](const Mesh& mesh) {
    for (FaceId f : one_face_per_size(mesh)) {
      const long n = mesh.size(f);
      CAPTURE(n);
      const Params out =
          apply_and_check(mesh, "inset_face", {{"face", f}, {"depth", 0.1}}, {n, 2 * n, n}).out;
      Mesh m = mesh;
      apply_operation(m, "inset_face", {{"face", f}});
      CHECK(shapes_around_new_vertices(m, mesh.vertex_capacity()) == expected_shapes("cubical", n, 1));
      // amount 0.25: each corner of the copy is a quarter of the way to the centroid, in the face's plane.
      const glm::dvec3 c = face_centroid(mesh, f);
      for (VertexId v : vertices(mesh, f)) {
        const VertexId q = new_neighbour(m, v, mesh.vertex_capacity());
        check_near(m.position(q), c + 0.75 * (mesh.position(v) - c));
      }
      CHECK(out.has("face"));
    }
  });
}

TEST_CASE("inset_face: depth raises the copy along the normal, a frustum of volume h/3 (A + kA k + kA)") {
  // The copy is the face scaled by k = 1 - amount about its centroid and raised by h: the solid between is
  // a frustum of a pyramid, of bases A and k^2 A: h/3 (A + k^2 A + k A). With depth 0 the volume stays.
  test::for_each_mesh(meshes(), [&](const Mesh& mesh) {
    if (mesh.num_hole_faces() != 0) return;
    for (FaceId f : one_face_per_size(mesh)) {
      const double area = face_area(mesh, f), volume = signed_volume(mesh);
      for (double amount : {0.25, 0.6}) {
        for (double h : {0.0, 0.4, -0.2}) {
          Mesh m = mesh;
          apply_operation(m, "inset_face", {{"face", f}, {"amount", amount}, {"depth", h}});
          const double k = 1 - amount;
          CHECK(signed_volume(m) == doctest::Approx(volume + h / 3 * (area + k * k * area + k * area)));
        }
      }
    }
  });
}

TEST_CASE("inset_face: a list of faces, and the refusals") {
  const Mesh cube = build_mesh(test::cube_soup());
  apply_and_check(cube, "inset_face", {{"faces", std::vector<FaceId>{FaceId(3), FaceId(0)}}}, {8, 16, 8});
  Mesh together = cube, apart = cube;
  apply_operation(together, "inset_face",
                  {{"faces", std::vector<FaceId>{FaceId(3), FaceId(0)}}, {"amount", 0.5}});
  for (FaceId f : {FaceId(3), FaceId(0)})
    apply_operation(apart, "inset_face", {{"face", f}, {"amount", 0.5}});
  CHECK(together == apart);

  RefusalScene scene(2, 2);
  Editor& ed = scene.ed;
  const std::string op = "inset_face";
  const FaceId f = FaceId(0);
  CHECK(refused_parameter(ed, op, {{"face", f}, {"faces", std::vector<FaceId>{f}}}, "exactly one") == "face");
  CHECK(refused_parameter(ed, op, {}, "exactly one") == "face");
  CHECK(refused_parameter(ed, op, {{"faces", std::vector<FaceId>{f, f}}}, "listed twice") == "faces");
  CHECK(refused_parameter(ed, op, {{"face", scene.hole}}, "hole") == "face");
  CHECK(refused_parameter(ed, op, {{"face", scene.sphere_face}}, "point sphere") == "face");
  CHECK(refused_parameter(ed, op, {{"face", scene.flat.front}, {"depth", 1.0}}, "no normal") == "face");
  CHECK(refused_parameter(ed, op, {{"face", f}, {"amount", 0.0}}) == "amount");
  CHECK(refused_parameter(ed, op, {{"face", f}, {"amount", 1.0}}) == "amount");
  CHECK(refused_parameter(ed, op, {{"face", f}, {"depth", std::numeric_limits<double>::infinity()}}) ==
        "depth");
  // A degenerate face insets at depth 0.
  const Mesh before = ed.mesh();
  ed.apply(op, {{"face", scene.flat.front}});
  CHECK(ed.mesh().num_faces() == before.num_faces() + 3);
  test::require_valid(ed.mesh());
}
