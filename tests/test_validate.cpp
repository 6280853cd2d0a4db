// The validator: it reports per-component topology, and it catches each kind of corruption.

#include <doctest/doctest.h>

#include <algorithm>

#include <dlfl/validate.h>
#include "test_helpers.h"
#include "test_meshes.h"

namespace dlfl {
// The one door into a mesh's private arrays, used only to corrupt meshes on purpose.
struct MeshTestAccess {
  static auto& corners(Mesh& m) { return m.corners_; }
  static auto& edges(Mesh& m) { return m.edges_; }
  static auto& faces(Mesh& m) { return m.faces_; }
  static auto& vertex_corner(Mesh& m) { return m.vertex_corner_; }
  static std::size_t& live_vertices(Mesh& m) { return m.live_vertices_; }
};
}  // namespace dlfl

using namespace dlfl;
using test::require_valid;
using Access = MeshTestAccess;

namespace {
bool reports(const Mesh& m, ViolationCode code) {
  auto r = validate(m);
  return std::any_of(r.violations.begin(), r.violations.end(),
                     [&](const Violation& v) { return v.code == code; });
}

// A cube that `corrupt` breaks on purpose: the validator reports `code`.
bool reports_on_cube(ViolationCode code, void (*corrupt)(Mesh&)) {
  Mesh m = test::cube();
  corrupt(m);
  return reports(m, code);
}

PolygonSoup join(PolygonSoup a, const PolygonSoup& b, glm::dvec3 shift) {
  const auto base = static_cast<std::uint32_t>(a.positions.size());
  for (auto p : b.positions) a.positions.push_back(p + shift);
  for (std::size_t i = 0; i < b.num_faces(); ++i) {
    std::vector<std::uint32_t> f;
    for (auto k : b.face(i)) f.push_back(k + base);
    a.add_face(f);
  }
  return a;
}
}  // namespace

TEST_CASE("validate: genus per component on a multi-component mesh") {
  PolygonSoup s = join(test::torus_soup(8, 6), test::cube_soup(), {10, 0, 0});
  s = join(s, test::genus_soup(3), {20, 0, 0});
  s = join(s, test::tetrahedron_soup(), {40, 0, 0});
  Mesh m = build_mesh(s);
  auto r = validate(m);
  REQUIRE(r.valid());
  REQUIRE(r.components.size() == 4);
  CHECK(r.components[0].genus == 1);
  CHECK(r.components[0].vertices == 48);
  CHECK(r.components[0].edges == 96);
  CHECK(r.components[0].faces == 48);
  CHECK(r.components[1].genus == 0);
  CHECK(r.components[1].euler_characteristic == 2);
  CHECK(r.components[2].genus == 3);
  CHECK(r.components[2].euler_characteristic == -4);
  // The slab of genus g has 16g + 16 vertices, 36g + 28 edges and 18g + 14 faces (see test_meshes.h).
  CHECK(r.components[2].vertices == 64);
  CHECK(r.components[2].edges == 136);
  CHECK(r.components[2].faces == 68);
  CHECK(r.components[3].genus == 0);
  CHECK(r.components[3].faces == 4);
}

TEST_CASE("validate: an open grid closes with one hole face and counts it") {
  Mesh m = build_mesh(test::grid_soup(3, 2));
  auto r = validate(m);
  REQUIRE(r.valid());
  REQUIRE(r.components.size() == 1);
  CHECK(r.components[0].holes == 1);
  CHECK(r.components[0].faces == 7);  // 6 quads + 1 hole
  CHECK(r.components[0].genus == 0);  // a disc
}

TEST_CASE("validate: broken next/prev links are caught") {
  CHECK(reports_on_cube(ViolationCode::next_prev, [](Mesh& m) {
    auto& c = Access::corners(m);
    std::swap(c[0].next, c[1].next);
  }));
}

TEST_CASE("validate: a corner in the wrong face is caught") {
  CHECK(reports_on_cube(ViolationCode::corner_face, [](Mesh& m) { Access::corners(m)[5].face = FaceId(3); }));
}

TEST_CASE("validate: a wrong face size is caught") {
  CHECK(reports_on_cube(ViolationCode::face_size, [](Mesh& m) { Access::faces(m)[2].size = 5; }));
}

TEST_CASE("validate: an edge whose sides disagree is caught") {
  CHECK(reports_on_cube(ViolationCode::edge_corner, [](Mesh& m) {
    auto& e = Access::edges(m);
    std::swap(e[0].corner, e[1].corner);
  }));
}

TEST_CASE("validate: a reference to a removed element is caught") {
  CHECK(reports_on_cube(ViolationCode::removed_reference,
                        [](Mesh& m) { Access::corners(m)[7].edge = EdgeId(1000); }));
}

TEST_CASE("validate: a bad vertex representative is caught") {
  CHECK(reports_on_cube(ViolationCode::vertex_corner, [](Mesh& m) {
    auto& vc = Access::vertex_corner(m);
    std::swap(vc[0], vc[1]);
  }));
}

TEST_CASE("validate: a pinched vertex is caught") {
  // Two tetrahedra; then the corners of the second one's vertex 4 are moved to vertex 0, which now has two
  // separate fans.
  Mesh m = build_mesh(join(test::tetrahedron_soup(), test::tetrahedron_soup(), {3, 0, 0}));
  require_valid(m);
  auto& c = Access::corners(m);
  for (auto& rec : c) {
    if (rec.vertex == VertexId(4)) rec.vertex = VertexId(0);
  }
  Access::vertex_corner(m)[4] = CornerId();
  Access::live_vertices(m) -= 1;
  CHECK(reports(m, ViolationCode::pinched_vertex));
}

TEST_CASE("validate: a malformed point sphere is caught") {
  Mesh m;
  VertexId v = m.create_vertex({0, 0, 0});
  Access::faces(m)[m.face(m.corner(v)).index()].size = 2;
  CHECK(reports(m, ViolationCode::point_sphere));
}

TEST_CASE("validate: stale counts are caught") {
  CHECK(reports_on_cube(ViolationCode::counts, [](Mesh& m) { Access::live_vertices(m) += 1; }));
}
