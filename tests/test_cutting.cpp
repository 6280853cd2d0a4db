// truncate_vertex, chamfer_edge, cut_face and plane_cut (docs/modeling.md, "Cutting"): closed-form counts
// on the modeling meshes (from the valences: a cut point on every edge leaving the cut element, a section
// edge per face around it, the element removed), the Archimedean truncations, lists with neighbouring
// elements, closed-form volumes and positions; plane cuts through vertices, edges and faces exactly, touching
// planes, non-convex faces, random planes (no edge crosses, the number of section loops, the areas on the two
// sides add up); the validator, orientation, exact undo, redo and log replay; and every refusal, naming its
// parameter, with the mesh unchanged.

#include <doctest/doctest.h>

#include <cmath>
#include <glm/geometric.hpp>
#include <limits>
#include <map>
#include <random>
#include <string>
#include <vector>

#include <dlfl/build_mesh.h>
#include <dlfl/errors.h>
#include <dlfl/geometry.h>
#include <dlfl/history/editor.h>
#include <dlfl/history/oplog.h>
#include <dlfl/mesh_hash.h>
#include <dlfl/navigation.h>
#include <dlfl/operations/cutting.h>
#include <dlfl/operations/operation.h>
#include <dlfl/operations/plane_cut.h>

#include "modeling_checks.h"
#include "modeling_meshes.h"
#include "test_helpers.h"

using namespace dlfl;

namespace {

using test::apply_and_check;
using test::Delta;
using test::euler_characteristic;
using test::refused_parameter;
using test::signed_volume;

double surface_area(const Mesh& m) {
  double area = 0;
  for (FaceId f : surface_faces(m)) area += face_area(m, f);
  return area;
}

Mesh applied(const Mesh& start, const std::string& op, const Params& params) {
  Mesh m = start;
  apply_operation(m, op, params);
  return m;
}

bool touches_hole(const Mesh& m, VertexId v) {
  for (FaceId f : faces(m, v)) {
    if (m.is_hole(f)) return true;
  }
  return false;
}

std::map<std::uint32_t, long> face_sizes(const Mesh& m) {
  std::map<std::uint32_t, long> sizes;
  for (FaceId f : surface_faces(m)) ++sizes[m.size(f)];
  return sizes;
}

// Edge lengths: smallest and largest.
std::pair<double, double> edge_length_range(const Mesh& m) {
  double lo = std::numeric_limits<double>::infinity(), hi = 0;
  for (EdgeId e : m.edges()) {
    const double l = glm::length(m.position(m.from(e)) - m.position(m.to(e)));
    lo = std::min(lo, l);
    hi = std::max(hi, l);
  }
  return {lo, hi};
}

VertexId vertex_at(const Mesh& m, const glm::dvec3& p) {
  for (VertexId v : m.vertices()) {
    if (glm::length(m.position(v) - p) < 1e-12) return v;
  }
  FAIL("no vertex there");
  return VertexId();
}

// A U (two prongs at x in [0, 1] and [2, 3], the notch between, 2 high) as a pillow of two faces.
Mesh u_pillow() {
  PolygonSoup u;
  for (auto [x, y] :
       std::vector<std::pair<double, double>>{{0, 0}, {3, 0}, {3, 2}, {2, 2}, {2, 1}, {1, 1}, {1, 2}, {0, 2}})
    u.positions.push_back({x, y, 0});
  u.add_face({0, 1, 2, 3, 4, 5, 6, 7});
  u.add_face({7, 6, 5, 4, 3, 2, 1, 0});
  return build_mesh(u);
}

}  // namespace

TEST_CASE("truncate_vertex: V+k-1, E+k, F+1 on every modeling mesh, the new face a k-gon") {
  test::for_each_modeling_mesh([&](const Mesh& mesh) {
    int tried = 0;
    for (VertexId v : mesh.vertices()) {
      if (tried++ == 3) break;
      const long k = mesh.valence(v);
      const long holes = touches_hole(mesh, v) ? 1 : 0;
      const Params out = apply_and_check(mesh, "truncate_vertex", {{"vertex", v}}, {k - 1, k, 1, holes}).out;
      const Mesh after = applied(mesh, "truncate_vertex", {{"vertex", v}});
      const FaceId f = out.handle<FaceId>("face");
      CHECK(after.size(f) == std::uint32_t(k));
      CHECK(after.is_hole(f) == (holes == 1));
      CHECK(!after.is_alive(v));
      // The corners of the new face are a quarter of the way along the old edges from v.
      for (VertexId w : vertices(after, f)) {
        bool on_an_edge = false;
        for (VertexId u : neighbours(mesh, v)) {
          on_an_edge = on_an_edge || glm::length(after.position(w) -
                                                 (0.75 * mesh.position(v) + 0.25 * mesh.position(u))) < 1e-12;
        }
        CHECK(on_an_edge);
      }
    }
  });
}

TEST_CASE("truncate_vertex: the cube's corner, hand counted, and its volume") {
  const Mesh cube = test::cube();
  const VertexId v = vertex_at(cube, {1, 1, 1});
  // 8 - 1 + 3 vertices, 12 + 3 edges, 6 + 1 faces; the corner cut off is a tetrahedron with legs 2 * 0.25.
  apply_and_check(cube, "truncate_vertex", {{"vertex", v}}, {2, 3, 1});
  const Mesh after = applied(cube, "truncate_vertex", {{"vertex", v}});
  CHECK(after.num_vertices() == 10);
  CHECK(after.num_edges() == 15);
  CHECK(after.num_faces() == 7);
  CHECK(signed_volume(after) == doctest::Approx(8.0 - 0.5 * 0.5 * 0.5 / 6.0).epsilon(1e-12));
  CHECK(face_sizes(after) == std::map<std::uint32_t, long>{{3, 1}, {4, 3}, {5, 3}});
}

TEST_CASE("truncate_vertex: every vertex gives the Archimedean truncations, regular at their offsets") {
  SUBCASE("tetrahedron at 1/3: the truncated tetrahedron, 12 vertices, 18 edges, 4 triangles, 4 hexagons") {
    const Mesh t = build_mesh(test::tetrahedron_soup());
    std::vector<VertexId> all(t.vertices().begin(), t.vertices().end());
    apply_and_check(t, "truncate_vertex", {{"vertices", all}, {"offset", 1.0 / 3.0}}, {8, 12, 4});
    const Mesh after = applied(t, "truncate_vertex", {{"vertices", all}, {"offset", 1.0 / 3.0}});
    CHECK(face_sizes(after) == std::map<std::uint32_t, long>{{3, 4}, {6, 4}});
    const auto [lo, hi] = edge_length_range(after);
    CHECK(hi - lo < 1e-12 * hi);
  }
  SUBCASE("cube at 1/(2 + sqrt 2): the truncated cube, 24 vertices, 36 edges, 8 triangles, 6 octagons") {
    const Mesh cube = test::cube();
    std::vector<VertexId> all(cube.vertices().begin(), cube.vertices().end());
    const double offset = 1.0 / (2.0 + std::sqrt(2.0));
    apply_and_check(cube, "truncate_vertex", {{"vertices", all}, {"offset", offset}}, {16, 24, 8});
    const Mesh after = applied(cube, "truncate_vertex", {{"vertices", all}, {"offset", offset}});
    CHECK(after.num_vertices() == 24);
    CHECK(after.num_edges() == 36);
    CHECK(face_sizes(after) == std::map<std::uint32_t, long>{{3, 8}, {8, 6}});
    const auto [lo, hi] = edge_length_range(after);
    CHECK(hi - lo < 1e-12 * hi);
  }
}

TEST_CASE("truncate_vertex: two neighbours share an edge, which keeps a middle piece; the counts add up") {
  const Mesh t = build_mesh(test::tetrahedron_soup());
  const VertexId a(0), b(1);
  REQUIRE(find_edge(t, a, b).valid());
  const Params out =
      apply_and_check(t, "truncate_vertex", {{"vertices", std::vector<VertexId>{a, b}}}, {2 + 2, 3 + 3, 2})
          .out;
  const Mesh after = applied(t, "truncate_vertex", {{"vertices", std::vector<VertexId>{a, b}}});
  CHECK(out.handles<FaceId>("faces").size() == 2);
  // The edge a-b keeps its middle half, from a quarter to three quarters.
  const glm::dvec3 pa = t.position(a), pb = t.position(b);
  const EdgeId middle =
      find_edge(after, vertex_at(after, 0.75 * pa + 0.25 * pb), vertex_at(after, 0.25 * pa + 0.75 * pb));
  CHECK(middle.valid());
}

TEST_CASE("truncate_vertex: a vertex of valence 2 becomes a 2-gon; the open grid's corner widens the hole") {
  const Mesh grid = build_mesh(test::grid_soup(3, 2));
  const VertexId corner = vertex_at(grid, {0, 0, 0});
  REQUIRE(grid.valence(corner) == 2);
  const Params out = apply_and_check(grid, "truncate_vertex", {{"vertex", corner}}, {1, 2, 1, 1}).out;
  const Mesh after = applied(grid, "truncate_vertex", {{"vertex", corner}});
  CHECK(after.size(out.handle<FaceId>("face")) == 2);
  CHECK(after.is_hole(out.handle<FaceId>("face")));
  // The corner quad lost its corner: a pentagon, its area 1 - 0.25 * 0.25 / 2.
  std::map<std::uint32_t, long> sizes = face_sizes(after);
  CHECK(sizes[5] == 1);
  CHECK(surface_area(after) == doctest::Approx(6.0 - 0.03125).epsilon(1e-12));
}

TEST_CASE("chamfer_edge: V+a+b-4, E+a+b-3, F+1 on every modeling mesh") {
  test::for_each_modeling_mesh([&](const Mesh& mesh) {
    int tried = 0;
    for (EdgeId e : mesh.edges()) {
      if (tried++ == 3) break;
      const long a = mesh.valence(mesh.from(e)), b = mesh.valence(mesh.to(e));
      const long holes = touches_hole(mesh, mesh.from(e)) || touches_hole(mesh, mesh.to(e)) ? 1 : 0;
      const Params out =
          apply_and_check(mesh, "chamfer_edge", {{"edge", e}}, {a + b - 4, a + b - 3, 1, holes}).out;
      const Mesh after = applied(mesh, "chamfer_edge", {{"edge", e}});
      CHECK(after.size(out.handle<FaceId>("face")) == std::uint32_t(a + b - 2));
      CHECK(!after.is_alive(e));
    }
  });
}

TEST_CASE("chamfer_edge: a cube's edge becomes a quad, the faces at its ends pentagons") {
  const Mesh cube = test::cube();
  const EdgeId e = find_edge(cube, vertex_at(cube, {1, 1, 1}), vertex_at(cube, {1, 1, -1}));
  apply_and_check(cube, "chamfer_edge", {{"edge", e}}, {2, 3, 1});
  const Mesh after = applied(cube, "chamfer_edge", {{"edge", e}});
  CHECK(face_sizes(after) == std::map<std::uint32_t, long>{{4, 5}, {5, 2}});
  // The prism cut off has the right triangle with legs 0.5 as its section and length 2.
  CHECK(signed_volume(after) == doctest::Approx(8.0 - 0.5 * 0.5 * 0.5 * 2.0).epsilon(1e-12));
}

TEST_CASE("chamfer_edge: two opposite edges of a face, joined by edges that get two cuts each") {
  const Mesh cube = test::cube();
  const EdgeId e1 = find_edge(cube, vertex_at(cube, {1, 1, 1}), vertex_at(cube, {1, -1, 1}));
  const EdgeId e2 = find_edge(cube, vertex_at(cube, {-1, 1, 1}), vertex_at(cube, {-1, -1, 1}));
  apply_and_check(cube, "chamfer_edge", {{"edges", std::vector<EdgeId>{e1, e2}}}, {4, 6, 2});
  const Mesh after = applied(cube, "chamfer_edge", {{"edges", std::vector<EdgeId>{e1, e2}}});
  // The top face keeps a strip between the two cuts: corners at x = +-0.5.
  CHECK(signed_volume(after) == doctest::Approx(8.0 - 2 * (0.5 * 0.5 * 0.5 * 2.0)).epsilon(1e-12));
}

TEST_CASE("cut_face: V+m-n, E+m-n, F+0 with m = sum (valence - 2), on every modeling mesh") {
  test::for_each_modeling_mesh([&](const Mesh& mesh) {
    int tried = 0;
    for (FaceId f : surface_faces(mesh)) {
      if (tried++ == 3) break;
      long m = 0, holes = 0;
      for (VertexId v : vertices(mesh, f)) {
        m += long(mesh.valence(v)) - 2;
        holes = holes || touches_hole(mesh, v);
      }
      const long n = mesh.size(f);
      const Params out = apply_and_check(mesh, "cut_face", {{"face", f}}, {m - n, m - n, 0, holes}).out;
      const Mesh after = applied(mesh, "cut_face", {{"face", f}});
      CHECK(after.size(out.handle<FaceId>("face")) == std::uint32_t(m));
    }
  });
}

TEST_CASE("cut_face: a prism's top slides down by offset times the height; both caps add up") {
  for (int n : {5, 6, 8}) {
    CAPTURE(n);
    const Mesh prism = build_mesh(test::prism_soup(n));
    FaceId top;
    for (FaceId f : surface_faces(prism)) {
      if (prism.size(f) == std::uint32_t(n) && face_centroid(prism, f).z > 0.5) top = f;
    }
    REQUIRE(top.valid());
    const double base_area = face_area(prism, top);
    apply_and_check(prism, "cut_face", {{"face", top}, {"offset", 0.3}}, {0, 0, 0});
    const Mesh after = applied(prism, "cut_face", {{"face", top}, {"offset", 0.3}});
    CHECK(signed_volume(after) == doctest::Approx(base_area * 0.7).epsilon(1e-12));
    std::vector<FaceId> caps;
    for (FaceId f : surface_faces(prism)) {
      if (prism.size(f) == std::uint32_t(n)) caps.push_back(f);
    }
    apply_and_check(prism, "cut_face", {{"faces", caps}, {"offset", 0.3}}, {0, 0, 0});
    const Mesh both = applied(prism, "cut_face", {{"faces", caps}, {"offset", 0.3}});
    CHECK(signed_volume(both) == doctest::Approx(base_area * 0.4).epsilon(1e-12));
  }
}

TEST_CASE("cut_face: an octahedron's triangle becomes a hexagon (m = 3 * 2)") {
  const Mesh o = build_mesh(test::octahedron_soup());
  const FaceId f = *surface_faces(o).begin();
  const Params out = apply_and_check(o, "cut_face", {{"face", f}}, {3, 3, 0}).out;
  CHECK(applied(o, "cut_face", {{"face", f}}).size(out.handle<FaceId>("face")) == 6);
}

TEST_CASE("cutting refusals name their parameter and leave the mesh unchanged") {
  const Mesh cube = test::cube();
  const VertexId v = vertex_at(cube, {1, 1, 1});
  const EdgeId e = find_edge(cube, v, vertex_at(cube, {1, 1, -1}));
  const FaceId f = *surface_faces(cube).begin();
  for (const std::string op : {"truncate_vertex", "chamfer_edge", "cut_face"}) {
    CAPTURE(op);
    const Params base = op == "truncate_vertex" ? Params{{"vertex", v}}
                        : op == "chamfer_edge"  ? Params{{"edge", e}}
                                                : Params{{"face", f}};
    for (double offset : {0.0, 0.5, 1.0, -0.25, std::numeric_limits<double>::infinity(),
                          std::numeric_limits<double>::quiet_NaN()}) {
      CAPTURE(offset);
      Params p = base;
      p["offset"] = offset;
      CHECK(refused_parameter(cube, op, p) == "offset");
    }
    CHECK(refused_parameter(cube, op, {}, "exactly one") != "(accepted)");
  }
  // The library functions refuse TopMod's crashing offset themselves.
  for (double offset : {1.0, 0.5, 0.0}) {
    Mesh m = cube;
    Transaction tx(m);
    const std::string message =
        test::error_message<ParameterError>([&] { truncate_vertex(tx, v, {offset}); });
    CHECK(message.find("truncate_vertex: parameter offset") == 0);
    CHECK(message.find("(0, 0.5)") != std::string::npos);
    CHECK(test::error_message<ParameterError>([&] {
            chamfer_edge(tx, e, {offset});
          }).find("chamfer_edge: parameter offset") == 0);
    CHECK(test::error_message<ParameterError>([&] {
            cut_face(tx, f, {offset});
          }).find("cut_face: parameter offset") == 0);
  }
  CHECK(refused_parameter(cube, "truncate_vertex", {{"vertices", std::vector<VertexId>{v, v}}},
                          "listed twice") == "vertices");
  CHECK(refused_parameter(cube, "truncate_vertex", {{"vertices", std::vector<VertexId>{}}}, "empty") ==
        "vertices");
  CHECK(refused_parameter(cube, "truncate_vertex", {{"vertex", VertexId(99)}}) == "vertex");
  CHECK(refused_parameter(cube, "truncate_vertex", {{"vertex", v}, {"vertices", std::vector<VertexId>{v}}},
                          "both") == "vertex");
  // Two chamfered edges with a common end, two cut faces with a common vertex.
  const EdgeId e2 = find_edge(cube, v, vertex_at(cube, {1, -1, 1}));
  CHECK(refused_parameter(cube, "chamfer_edge", {{"edges", std::vector<EdgeId>{e, e2}}}, "share") == "edges");
  std::vector<FaceId> two_faces;
  for (FaceId g : faces(cube, v)) two_faces.push_back(g);
  two_faces.resize(2);
  CHECK(refused_parameter(cube, "cut_face", {{"faces", two_faces}}, "share") == "faces");

  SUBCASE("a hole face and a point sphere's face for cut_face") {
    const Mesh grid = build_mesh(test::grid_soup(3, 2));
    FaceId hole;
    for (FaceId g : grid.faces()) {
      if (grid.is_hole(g)) hole = g;
    }
    CHECK(refused_parameter(grid, "cut_face", {{"face", hole}}, "hole face") == "face");
    Mesh with_point = cube;
    const VertexId p = with_point.create_vertex({5, 5, 5});
    CHECK(refused_parameter(with_point, "cut_face", {{"face", with_point.face(with_point.corner(p))}},
                            "point sphere") == "face");
    CHECK(refused_parameter(with_point, "truncate_vertex", {{"vertex", p}}, "0 edges") == "vertex");
  }
  SUBCASE("a dangling vertex (one edge) and an edge doubled by a 2-gon") {
    Mesh m = cube;
    const VertexId p = m.create_vertex({2, 2, 2});
    m.insert_edge(m.corner(p), m.corner(v));
    CHECK(refused_parameter(m, "truncate_vertex", {{"vertex", p}}, "1 edge") == "vertex");
    Mesh doubled = cube;
    const CornerId c = corner_in_face(doubled, v, doubled.face(doubled.corner(e, 0)));
    const CornerId other = doubled.from(e) == v ? doubled.next(c) : doubled.prev(c);
    doubled.insert_edge(c, other);
    test::require_valid(doubled);
    CHECK(refused_parameter(doubled, "chamfer_edge", {{"edge", e}}, "comes back") == "edge");
  }
}

namespace {

// Signed distances from the plane, and the tolerance the checks use.
double distance(const glm::dvec3& p, const glm::dvec3& point, const glm::dvec3& normal) {
  return glm::dot(p - point, glm::normalize(normal));
}

// No edge has its ends strictly on opposite sides (beyond `tolerance`).
bool no_edge_crosses(const Mesh& m, const glm::dvec3& point, const glm::dvec3& normal, double tolerance) {
  for (EdgeId e : m.edges()) {
    const double a = distance(m.position(m.from(e)), point, normal);
    const double b = distance(m.position(m.to(e)), point, normal);
    if ((a > tolerance && b < -tolerance) || (a < -tolerance && b > tolerance)) return false;
  }
  return true;
}

// The loops of the section: the components of the graph of edges lying on the plane, each of whose
// vertices has two such edges. Returns -1 if some vertex has another number.
int section_loops(const Mesh& m, const glm::dvec3& point, const glm::dvec3& normal, double tolerance) {
  const auto on = [&](VertexId v) { return std::abs(distance(m.position(v), point, normal)) <= tolerance; };
  std::map<std::uint32_t, std::vector<std::uint32_t>> graph;
  for (EdgeId e : m.edges()) {
    if (on(m.from(e)) && on(m.to(e))) {
      graph[m.from(e).index()].push_back(m.to(e).index());
      graph[m.to(e).index()].push_back(m.from(e).index());
    }
  }
  std::map<std::uint32_t, bool> seen;
  int loops = 0;
  for (const auto& [start, next] : graph) {
    if (next.size() != 2) return -1;
    if (seen[start]) continue;
    ++loops;
    std::vector<std::uint32_t> stack{start};
    while (!stack.empty()) {
      const std::uint32_t x = stack.back();
      stack.pop_back();
      if (seen[x]) continue;
      seen[x] = true;
      for (std::uint32_t y : graph[x]) stack.push_back(y);
    }
  }
  return loops;
}

Params plane(const glm::dvec3& point, const glm::dvec3& normal, const std::string& keep = "both") {
  return {{"point", point}, {"normal", normal}, {"keep", keep}};
}

}  // namespace

TEST_CASE("plane_cut: the cube through its middle, through two of its edges and through three vertices") {
  const Mesh cube = test::cube();
  SUBCASE("z = 0: 4 edges split, 4 section edges, one loop; below becomes the bottom and 4 half sides") {
    const Params out = apply_and_check(cube, "plane_cut", plane({0, 0, 0}, {0, 0, 1}), {4, 8, 4}).out;
    const Mesh after = applied(cube, "plane_cut", plane({0, 0, 0}, {0, 0, 1}));
    CHECK(section_loops(after, {0, 0, 0}, {0, 0, 1}, 1e-12) == 1);
    CHECK(out.handles<EdgeId>("edges").size() == 4);
    apply_and_check(cube, "plane_cut", plane({0, 0, 0}, {0, 0, 1}, "above"), {4, 8, 4, 5});
    CHECK(surface_area(applied(cube, "plane_cut", plane({0, 0, 0}, {0, 0, 1}, "above"))) ==
          doctest::Approx(12.0));
  }
  SUBCASE("x = y: through two opposite edges, no edge split, the top and bottom cut along a diagonal") {
    apply_and_check(cube, "plane_cut", plane({0, 0, 0}, {1, -1, 0}), {0, 2, 2});
    apply_and_check(cube, "plane_cut", plane({0, 0, 0}, {1, -1, 0}, "above"), {0, 2, 2, 4});
    const Mesh above = applied(cube, "plane_cut", plane({0, 0, 0}, {1, -1, 0}, "above"));
    CHECK(surface_area(above) == doctest::Approx(12.0));
    CHECK(section_loops(applied(cube, "plane_cut", plane({0, 0, 0}, {1, -1, 0})), {0, 0, 0}, {1, -1, 0},
                        1e-12) == 1);
  }
  SUBCASE("x + y + z = 1: through three vertices exactly, three faces cut along diagonals, a triangle") {
    apply_and_check(cube, "plane_cut", plane({1, 0, 0}, {1, 1, 1}), {0, 3, 3});
    const Mesh after = applied(cube, "plane_cut", plane({1, 0, 0}, {1, 1, 1}));
    CHECK(section_loops(after, {1, 0, 0}, {1, 1, 1}, 1e-12) == 1);
    // Above: the corner tetrahedron's three right triangles, each half a face.
    CHECK(surface_area(applied(cube, "plane_cut", plane({1, 0, 0}, {1, 1, 1}, "above"))) ==
          doctest::Approx(6.0));
  }
  SUBCASE("x + y + z = 0: the regular hexagon, 6 edges split") {
    apply_and_check(cube, "plane_cut", plane({0, 0, 0}, {1, 1, 1}), {6, 12, 6});
    CHECK(section_loops(applied(cube, "plane_cut", plane({0, 0, 0}, {1, 1, 1})), {0, 0, 0}, {1, 1, 1},
                        1e-12) == 1);
  }
  SUBCASE("touching planes change nothing: z = 1 (a face in it), x + y + z = 3 (a vertex on it)") {
    apply_and_check(cube, "plane_cut", plane({0, 0, 1}, {0, 0, 1}), {0, 0, 0});
    apply_and_check(cube, "plane_cut", plane({0, 0, 1}, {0, 0, 1}, "above"), {0, 0, 0, 5});
    apply_and_check(cube, "plane_cut", plane({0, 0, 1}, {0, 0, 1}, "below"), {0, 0, 0, 0});
    apply_and_check(cube, "plane_cut", plane({1, 1, 1}, {1, 1, 1}), {0, 0, 0});
    apply_and_check(cube, "plane_cut", plane({0, 0, 5}, {0, 0, 1}, "below"), {0, 0, 0, 0});
  }
}

TEST_CASE("plane_cut: the torus through its equator and through its axis gives two loops") {
  const Mesh torus = build_mesh(test::torus_soup(4, 3));
  SUBCASE("z = 0: the outer equator is on edges already; the inner one crosses the 4 inner rings") {
    apply_and_check(torus, "plane_cut", plane({0, 0, 0}, {0, 0, 1}), {4, 8, 4});
    CHECK(section_loops(applied(torus, "plane_cut", plane({0, 0, 0}, {0, 0, 1})), {0, 0, 0}, {0, 0, 1},
                        1e-12) == 2);
  }
  SUBCASE("a plane through the axis, turned off the vertices: two meridian loops of 3 edges each") {
    const glm::dvec3 n{std::cos(0.3), std::sin(0.3), 0};
    apply_and_check(torus, "plane_cut", plane({0, 0, 0}, n), {6, 12, 6});
    CHECK(section_loops(applied(torus, "plane_cut", plane({0, 0, 0}, n)), {0, 0, 0}, n, 1e-12) == 2);
  }
}

TEST_CASE(
    "plane_cut: the open grid at x = 1.5: the hole's crossed edges split, no section edge in the hole") {
  const Mesh grid = build_mesh(test::grid_soup(3, 2));
  // The 3 edges from x = 1 to x = 2 split; the 2 quads between get a section edge each, the hole none.
  apply_and_check(grid, "plane_cut", plane({1.5, 0, 0}, {1, 0, 0}), {3, 3 + 2, 2});
  // Keeping x > 1.5: the 2 quads of the first column and the 2 left halves become holes; area 1.5 x 2.
  apply_and_check(grid, "plane_cut", plane({1.5, 0, 0}, {1, 0, 0}, "above"), {3, 3 + 2, 2, 4});
  CHECK(surface_area(applied(grid, "plane_cut", plane({1.5, 0, 0}, {1, 0, 0}, "above"))) ==
        doctest::Approx(3.0));
}

TEST_CASE("plane_cut: a non-convex face crossed four times is cut along the pieces inside it") {
  const Mesh pillow = u_pillow();
  apply_and_check(pillow, "plane_cut", plane({0, 1.5, 0}, {0, 1, 0}), {4, 8, 4});
  const Mesh after = applied(pillow, "plane_cut", plane({0, 1.5, 0}, {0, 1, 0}));
  // Each section edge is inside a prong, none across the notch.
  int inside = 0;
  for (EdgeId e : after.edges()) {
    const glm::dvec3 a = after.position(after.from(e)), b = after.position(after.to(e));
    if (std::abs(a.y - 1.5) > 1e-12 || std::abs(b.y - 1.5) > 1e-12) continue;
    const double mid = 0.5 * (a.x + b.x);
    CHECK((std::abs(mid - 0.5) < 1e-12 || std::abs(mid - 2.5) < 1e-12));
    ++inside;
  }
  CHECK(inside == 4);
  CHECK(surface_area(applied(pillow, "plane_cut", plane({0, 1.5, 0}, {0, 1, 0}, "above"))) ==
        doctest::Approx(2 * 2 * 0.5));
}

TEST_CASE(
    "plane_cut: a line along the notch of a U, touching it from inside, gives a section edge per prong") {
  // The U cut at y = 1 along the bottom of its notch: the notch's corners are reflex, so the line goes on
  // inside the face past them; the section is (0, 1)-(1, 1) and (2, 1)-(3, 1), not one edge over the notch's
  // side.
  const Mesh pillow = u_pillow();
  // Two edges split (x = 0 and x = 3), two section edges in each of the two faces.
  apply_and_check(pillow, "plane_cut", plane({0, 1, 0}, {0, 1, 0}), {2, 2 + 4, 4});
  const Mesh after = applied(pillow, "plane_cut", plane({0, 1, 0}, {0, 1, 0}));
  for (EdgeId e : after.edges()) {
    const glm::dvec3 a = after.position(after.from(e)), b = after.position(after.to(e));
    if (std::abs(a.y - 1) > 1e-12 || std::abs(b.y - 1) > 1e-12) continue;
    CHECK(std::abs(a.x - b.x) == doctest::Approx(1.0));  // the notch's side or a section edge, never 3 long
  }
  CHECK(surface_area(applied(pillow, "plane_cut", plane({0, 1, 0}, {0, 1, 0}, "below"))) ==
        doctest::Approx(2 * 3.0));
}

TEST_CASE("plane_cut: random planes through random meshes: no edge crosses, loops, areas add up") {
  std::mt19937_64 random(20261202);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  const auto direction = [&] {
    glm::dvec3 d;
    do d = {unit(random), unit(random), unit(random)};
    while (glm::length(d) < 0.1);
    return d;
  };
  const std::vector<std::string> convex = {
      "tetrahedron", "cube", "octahedron", "pentagonal prism", "hexagonal prism", "octagonal prism"};
  test::for_each_modeling_mesh([&](const std::string& name, const Mesh& mesh) {
    const bool is_convex = std::find(convex.begin(), convex.end(), name) != convex.end();
    glm::dvec3 centre(0.0);
    for (VertexId v : mesh.vertices()) centre += mesh.position(v);
    centre /= double(mesh.num_vertices());
    for (int trial = 0; trial < 8; ++trial) {
      const glm::dvec3 n = direction();
      // Inside a convex mesh: within 0.2 of the centre (each has its faces farther away than that).
      const glm::dvec3 point = centre + 0.2 * unit(random) * glm::normalize(direction());
      const Mesh both = applied(mesh, "plane_cut", plane(point, n));
      test::require_valid(both);
      CHECK(euler_characteristic(both) == euler_characteristic(mesh));
      CHECK(no_edge_crosses(both, point, n, 1e-9));
      if (is_convex) CHECK(section_loops(both, point, n, 1e-9) == 1);
      const double above = surface_area(applied(mesh, "plane_cut", plane(point, n, "above")));
      const double below = surface_area(applied(mesh, "plane_cut", plane(point, n, "below")));
      CHECK(above + below == doctest::Approx(surface_area(mesh)).epsilon(1e-9));
      CHECK(surface_area(both) == doctest::Approx(surface_area(mesh)).epsilon(1e-9));
    }
    // The counts through an editor: V+c, E+c+s, F+s, with c the edges the test finds crossing.
    const glm::dvec3 n = direction();
    long crossing = 0;
    for (EdgeId e : mesh.edges()) {
      crossing +=
          distance(mesh.position(mesh.from(e)), centre, n) * distance(mesh.position(mesh.to(e)), centre, n) <
          0;
    }
    Editor probe;
    probe.set_mesh(mesh);
    const long s = long(probe.apply("plane_cut", plane(centre, n)).handles<EdgeId>("edges").size());
    CHECK(s >= (crossing > 0 ? 1 : 0));
    apply_and_check(mesh, "plane_cut", plane(centre, n), {crossing, crossing + s, s});
  });
}

TEST_CASE("plane_cut refusals") {
  const Mesh cube = test::cube();
  CHECK(refused_parameter(cube, "plane_cut", plane({0, 0, 0}, {0, 0, 0}), "zero") == "normal");
  CHECK(refused_parameter(cube, "plane_cut", plane({0, 0, 0}, {0, 0, 0}), "zero") == "normal");
  const double inf = std::numeric_limits<double>::infinity();
  CHECK(refused_parameter(cube, "plane_cut", plane({inf, 0, 0}, {0, 0, 1})) == "point");
  CHECK(refused_parameter(cube, "plane_cut", plane({0, 0, 0}, {0, inf, 1})) == "normal");
  CHECK(refused_parameter(cube, "plane_cut", plane({0, 0, 0}, {0, 0, 1}, "left")) == "keep");
  CHECK(refused_parameter(cube, "plane_cut", {{"normal", glm::dvec3(0, 0, 1)}}) == "point");
  Mesh m = cube;
  Transaction tx(m);
  CHECK(test::error_message<ParameterError>([&] {
          plane_cut(tx, {{1.7e308, 1.7e308, 1.7e308}, {1, 1, 1}});
        }).find("plane_cut: parameter point") == 0);
  CHECK(m == cube);
}

namespace {

// A cube with a dangling edge at one corner and a 2-gon doubling an edge at another: elements the cuts
// either refuse or cut.
Mesh messy_cube() {
  Mesh m = test::cube();
  const VertexId corner = vertex_at(m, {1, 1, 1});
  const VertexId p = m.create_vertex({2, 2, 2});
  m.insert_edge(m.corner(p), m.corner(corner));
  const VertexId far = vertex_at(m, {-1, -1, -1});
  const CornerId c = m.corner(far);
  m.insert_edge(c, m.next(c));
  return m;
}

// The change the cut of one element makes by the closed form of docs/modeling.md, from the valences.
Delta cap_delta(const Mesh& m, const std::string& op, std::uint32_t index) {
  long holes = 0;
  const auto around = [&](VertexId v) { holes = holes || touches_hole(m, v); };
  if (op == "truncate_vertex") {
    const VertexId v(index);
    around(v);
    const long k = m.valence(v);
    return {k - 1, k, 1, holes};
  }
  if (op == "chamfer_edge") {
    const EdgeId e(index);
    around(m.from(e));
    around(m.to(e));
    const long a = m.valence(m.from(e)), b = m.valence(m.to(e));
    return {a + b - 4, a + b - 3, 1, holes};
  }
  const FaceId f(index);
  long sum = 0;
  for (VertexId v : vertices(m, f)) {
    around(v);
    sum += long(m.valence(v)) - 2;
  }
  const long n = m.size(f);
  return {sum - n, sum - n, 0, holes};
}

}  // namespace

TEST_CASE(
    "every vertex, edge and face of every modeling mesh and of a messy cube: cut, or refused unchanged") {
  auto meshes = test::modeling_meshes();
  meshes.push_back({"messy cube", messy_cube()});
  test::for_each_mesh(meshes, [&](const Mesh& mesh) {
    for (const std::string op : {"truncate_vertex", "chamfer_edge", "cut_face"}) {
      CAPTURE(op);
      const std::uint32_t count = op == "truncate_vertex" ? mesh.vertex_capacity()
                                  : op == "chamfer_edge"  ? mesh.edge_capacity()
                                                          : mesh.face_capacity();
      const std::string key = op == "truncate_vertex" ? "vertex" : op == "chamfer_edge" ? "edge" : "face";
      for (std::uint32_t i = 0; i < count; ++i) {
        CAPTURE(i);
        Mesh m = mesh;
        try {
          apply_operation(m, op, {{key, std::int64_t(i)}, {"offset", 0.3}});
        } catch (const ParameterError&) {
          CHECK(m == mesh);
          continue;
        }
        const Delta d = cap_delta(mesh, op, i);
        CHECK(long(m.num_vertices()) == long(mesh.num_vertices()) + d.v);
        CHECK(long(m.num_edges()) == long(mesh.num_edges()) + d.e);
        CHECK(long(m.num_faces()) == long(mesh.num_faces()) + d.f);
        CHECK(long(m.num_hole_faces()) == long(mesh.num_hole_faces()) + d.holes);
        test::require_valid(m);
      }
    }
  });
}
