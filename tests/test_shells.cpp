// crust, rind and wireframe (docs/modeling.md, "Shells and frames"): the counts on every modeling mesh, in
// closed form from what each builds (crust doubles V, E and F; a tube from an n-gon to its twin adds n edges
// and n - 2 faces; an inset ring adds n vertices, 2n edges and n faces); the Euler characteristic and genus
// rules (2chi - 2k for rind, genus E - V + 1 for wireframe); the components; the copy's faces as the
// originals reversed; the inner positions at the documented offset; orientation (the inner copy's signed
// volume is negative); rind applied twice; exact undo, redo and log replay through the editor; and every
// refusal with its parameter, the mesh unchanged.

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <limits>
#include <numeric>
#include <optional>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include <dlfl/errors.h>
#include <dlfl/geometry.h>
#include <dlfl/history/editor.h>
#include <dlfl/history/oplog.h>
#include <dlfl/mesh_hash.h>
#include <dlfl/navigation.h>
#include <dlfl/operations/columns.h>
#include <dlfl/operations/crust.h>
#include <dlfl/operations/operation.h>
#include <dlfl/operations/rind.h>
#include <dlfl/operations/wireframe.h>

#include "modeling_checks.h"
#include "modeling_meshes.h"
#include "test_helpers.h"
#include "test_meshes.h"

using namespace dlfl;

namespace {

// The signed volume enclosed by the surface faces whose vertices all pass `keep`, each face cut into a fan
// from its first corner: positive for a closed surface whose faces turn counter-clockwise seen from outside.
template <class Keep>
double signed_volume(const Mesh& m, Keep keep) {
  double volume = 0;
  for (FaceId f : surface_faces(m)) {
    bool kept = true;
    for (VertexId v : vertices(m, f)) kept = kept && keep(v);
    if (!kept || m.size(f) < 3) continue;
    const CornerId first = m.first_corner(f);
    const glm::dvec3 p0 = m.position(m.vertex(first));
    for (CornerId c = m.next(first); m.next(c) != first; c = m.next(c)) {
      volume += glm::dot(p0, glm::cross(m.position(m.vertex(c)), m.position(m.vertex(m.next(c))))) / 6.0;
    }
  }
  return volume;
}
using test::euler_characteristic;
using test::signed_volume;

// Connected components, by a search along the edges.
long components(const Mesh& m) {
  std::vector<char> seen(m.vertex_capacity(), 0);
  long count = 0;
  for (VertexId root : m.vertices()) {
    if (seen[root.index()]) continue;
    ++count;
    std::vector<VertexId> stack{root};
    seen[root.index()] = 1;
    while (!stack.empty()) {
      const VertexId v = stack.back();
      stack.pop_back();
      for (VertexId w : neighbours(m, v)) {
        if (!seen[w.index()]) {
          seen[w.index()] = 1;
          stack.push_back(w);
        }
      }
    }
  }
  return count;
}

using test::Counts;
using test::refused_parameter;

// Applies `op` through the shared editor round trip, then checks the counts. Returns the mesh after.
Mesh apply_and_check(const Mesh& start, const std::string& op, const Params& params, Counts expected,
                     Params* outputs = nullptr) {
  const Mesh after = test::check_editor_round_trip(start, op, params, outputs);
  CHECK(long(after.num_vertices()) == expected.v);
  CHECK(long(after.num_edges()) == expected.e);
  CHECK(long(after.num_faces()) == expected.f);
  return after;
}

// The faces of m as vertex cycles starting at their smallest vertex index.
std::vector<std::uint32_t> canonical(std::vector<std::uint32_t> cycle) {
  std::rotate(cycle.begin(), std::min_element(cycle.begin(), cycle.end()), cycle.end());
  return cycle;
}
std::multiset<std::vector<std::uint32_t>> face_cycles(const Mesh& m) {
  std::multiset<std::vector<std::uint32_t>> out;
  for (FaceId f : m.faces()) {
    std::vector<std::uint32_t> cycle;
    for (VertexId v : vertices(m, f)) cycle.push_back(v.index());
    out.insert(canonical(cycle));
  }
  return out;
}

// The surface faces with edges, and the sum of their sides and of the hole faces' sides.
struct FaceSides {
  long surface = 0, surface_sides = 0, holes = 0, hole_sides = 0;
};
FaceSides face_sides(const Mesh& m) {
  FaceSides s;
  for (FaceId f : m.faces()) {
    if (m.is_hole(f)) {
      ++s.holes;
      s.hole_sides += m.size(f);
    } else {
      ++s.surface;
      s.surface_sides += m.size(f);
    }
  }
  return s;
}

// The first k surface faces, in handle order, and the sum of their sides.
std::vector<FaceId> first_surface_faces(const Mesh& m, std::size_t k, long& sides) {
  std::vector<FaceId> out;
  sides = 0;
  for (FaceId f : surface_faces(m)) {
    if (out.size() == k) break;
    out.push_back(f);
    sides += m.size(f);
  }
  return out;
}

}  // namespace

TEST_CASE("crust: doubled counts, reversed faces, inner positions and orientation on every modeling mesh") {
  test::for_each_modeling_mesh([&](const Mesh& mesh) {
    const double thickness = 0.1;
    const FaceSides sides = face_sides(mesh);
    // Closed: everything doubles. Each hole face of h sides: a tube of h quads (E+h, F+h-2).
    const Counts expected{2 * long(mesh.num_vertices()), 2 * long(mesh.num_edges()) + sides.hole_sides,
                          2 * long(mesh.num_faces()) + sides.hole_sides - 2 * sides.holes};
    Params out;
    const Mesh after = apply_and_check(mesh, "crust", {{"thickness", thickness}}, expected, &out);
    const std::vector<VertexId> copies = out.handles<VertexId>("vertices");
    REQUIRE(copies.size() == mesh.num_vertices());
    // Handles of a built mesh are dense: copies[i] is the copy of vertex i.
    for (std::uint32_t i = 0; i < copies.size(); ++i) {
      const VertexId v(i);
      const glm::dvec3 expected_position = mesh.position(v) - thickness * vertex_normal(mesh, v);
      CHECK(glm::length(after.position(copies[i]) - expected_position) < 1e-14);
      CHECK(after.position(v) == mesh.position(v));
    }
    if (sides.holes == 0) {
      CHECK(components(after) == 2 * components(mesh));
      CHECK(euler_characteristic(after) == 2 * euler_characteristic(mesh));
      CHECK(after.num_hole_faces() == 0);
      // Every face of the copy is an original face reversed, over the copies of its vertices.
      const auto cycles = face_cycles(after);
      for (FaceId f : mesh.faces()) {
        std::vector<std::uint32_t> reversed;
        for (VertexId v : vertices(mesh, f)) reversed.push_back(copies[v.index()].index());
        std::reverse(reversed.begin(), reversed.end());
        CHECK(cycles.count(canonical(reversed)) == 1);
      }
      const std::uint32_t first_copy = copies.front().index();
      const double outer = signed_volume(after, [&](VertexId v) { return v.index() < first_copy; });
      const double inner = signed_volume(after, [&](VertexId v) { return v.index() >= first_copy; });
      CHECK(outer == doctest::Approx(signed_volume(mesh)));
      CHECK(inner < 0);
      CHECK(-inner < outer);
      CHECK(signed_volume(after) > 0);
    } else {
      // The open grid: one sheet and its copy, joined along the boundary loop, close into one sphere.
      CHECK(components(after) == components(mesh));
      CHECK(euler_characteristic(after) == 2);
      CHECK(after.num_hole_faces() == 0);
      // The flat grid [0, 3] x [0, 2] faces +z; its copy lies 0.1 below, reversed, and the tube walls are
      // vertical: a closed box of volume 3 x 2 x 0.1, oriented outward.
      CHECK(signed_volume(after) == doctest::Approx(0.6));
    }
  });
}

TEST_CASE("crust: the grid by hand, and twice") {
  // grid 3 x 2: V 12, E 17, F 6 quads + 1 hole of 10 sides. Crust: V 24, E 34 + 10, F 14 - 2 + 10.
  const Mesh grid = build_mesh(test::grid_soup(3, 2));
  const Mesh shell = apply_and_check(grid, "crust", {}, {24, 44, 22});
  // Default thickness 0.1 along the normal +z: the copy of (0, 0, 0) is at (0, 0, -0.1).
  bool found = false;
  for (VertexId v : shell.vertices()) found = found || shell.position(v) == glm::dvec3(0, 0, -0.1);
  CHECK(found);
  // Crust of the crust: closed now, so everything doubles again.
  const Mesh twice = apply_and_check(shell, "crust", {{"thickness", 0.01}}, {48, 88, 44});
  CHECK(components(twice) == 2);
}

TEST_CASE("rind: 2chi - 2k on every closed modeling mesh, k = 1 and 2") {
  test::for_each_modeling_mesh([&](const Mesh& mesh) {
    if (mesh.num_hole_faces() > 0) return;
    for (std::size_t k = 1; k <= 2; ++k) {
      CAPTURE(k);
      long sides = 0;
      const std::vector<FaceId> faces = first_surface_faces(mesh, k, sides);
      const Counts expected{2 * long(mesh.num_vertices()), 2 * long(mesh.num_edges()) + sides,
                            2 * long(mesh.num_faces()) + sides - 2 * long(k)};
      const Mesh after = apply_and_check(mesh, "rind", {{"faces", faces}, {"thickness", 0.05}}, expected);
      CHECK(euler_characteristic(after) == 2 * euler_characteristic(mesh) - 2 * long(k));
      // The punched faces' components join their copies; the others stay doubled. The faces taken first are
      // on the first component (the cube of "cube and tetrahedron").
      CHECK(components(after) == 2 * components(mesh) - 1);
      CHECK(after.num_hole_faces() == 0);
      CHECK(signed_volume(after) > 0);
      CHECK(signed_volume(after) < signed_volume(mesh));
    }
  });
}

TEST_CASE("rind: one face given as face") {
  // The cube's face 0 (a quad): V 16, E 24 + 4, F 12 + 2; chi 2.
  const Mesh cube = test::cube();
  const Mesh after = apply_and_check(cube, "rind", {{"face", FaceId(0)}}, {16, 28, 14});
  CHECK(euler_characteristic(after) == 2);
  CHECK(components(after) == 1);
}

TEST_CASE("rind twice: the same rule on a rind") {
  const Mesh cube = test::cube();
  long sides = 0;
  const std::vector<FaceId> two = first_surface_faces(cube, 2, sides);
  // Cube chi 2, k = 2: chi 0 (a torus): V 16, E 24 + 8, F 12 + 8 - 4.
  const Mesh torus = apply_and_check(cube, "rind", {{"faces", two}}, {16, 32, 16});
  CHECK(euler_characteristic(torus) == 0);
  // Again with two faces of the torus: chi 2 * 0 - 4 = -4 (genus 3), one component.
  const std::vector<FaceId> again = first_surface_faces(torus, 2, sides);
  const Mesh genus3 = apply_and_check(torus, "rind", {{"faces", again}, {"thickness", 0.02}},
                                      {32, 64 + sides, 32 + sides - 4});
  CHECK(euler_characteristic(genus3) == -4);
  CHECK(components(genus3) == 1);
  CHECK(signed_volume(genus3) > 0);
  // And a third time, with one face: 2 * -4 - 2 = -10.
  const std::vector<FaceId> once = first_surface_faces(genus3, 1, sides);
  const Mesh third =
      apply_and_check(genus3, "rind", {{"faces", once}, {"thickness", 0.005}},
                      {64, 2 * long(genus3.num_edges()) + sides, 2 * long(genus3.num_faces()) + sides - 2});
  CHECK(euler_characteristic(third) == -10);
  CHECK(components(third) == 1);
}

TEST_CASE("wireframe: genus E - V + 1 on every modeling mesh") {
  test::for_each_modeling_mesh([&](const Mesh& mesh) {
    const FaceSides s = face_sides(mesh);
    const long v = long(mesh.num_vertices()), e = long(mesh.num_edges()), f = long(mesh.num_faces());
    // Inset rings on the surface faces (n_s sides in all): V+n_s, E+2n_s, F+n_s; the crust doubles that; a
    // tube from every inset face and every hole face (2E sides in all) adds E+2E... per face E+n, F+n-2.
    const long ns = s.surface_sides, nh = s.hole_sides;
    const Counts expected{2 * (v + ns), 2 * (e + 2 * ns) + ns + nh, 2 * (f + ns) + ns + nh - 2 * f};
    const Mesh after = apply_and_check(mesh, "wireframe", {}, expected);
    CHECK(euler_characteristic(after) == 2 * v - 2 * e);
    CHECK(components(after) == components(mesh));
    CHECK(after.num_hole_faces() == 0);
    if (components(mesh) == 1) CHECK(1 - euler_characteristic(after) / 2 == e - v + 1);  // the genus
    if (s.holes == 0) CHECK(signed_volume(after) > 0);
  });
}

TEST_CASE("wireframe: the cube by hand") {
  // Cube V 8, E 12, F 6: V 64, E 144, F 72, genus 5.
  const Mesh cube = test::cube();
  const double t = 0.1, w = 0.2;
  const Mesh frame = apply_and_check(cube, "wireframe", {{"thickness", t}, {"width", w}}, {64, 144, 72});
  CHECK(1 - euler_characteristic(frame) / 2 == 5);
  auto has = [&](const glm::dvec3& p) {
    for (VertexId v : frame.vertices()) {
      if (glm::length(frame.position(v) - p) < 1e-12) return true;
    }
    return false;
  };
  // The opening in the top face (z = 1, side 2) lies w inside its edges; its inner copy t below.
  for (double x : {-1 + w, 1 - w}) {
    for (double y : {-1 + w, 1 - w}) {
      CHECK(has({x, y, 1}));
      CHECK(has({x, y, 1 - t}));
    }
  }
  // A corner's normal in the inset cube is the diagonal (three equal quads meet there).
  CHECK(has(glm::dvec3(1, 1, 1) - t / std::sqrt(3.0) * glm::dvec3(1, 1, 1)));
  // The frame's volume: the solid between the two sheets, less than the cube's, more than nothing.
  CHECK(signed_volume(frame) > 0);
  CHECK(signed_volume(frame) < 8 - std::pow(2 - 2 * t, 3));
}

TEST_CASE("columns: counts and genus E - V + 1 on every modeling mesh") {
  test::for_each_modeling_mesh([&](const Mesh& mesh) {
    const long v = long(mesh.num_vertices()), e = long(mesh.num_edges());
    for (long n : {4L, 3L, 6L}) {
      CAPTURE(n);
      // A joint of valence k: V kn, E kn + k, F k + 2 (no vertex here has valence 1); a column: E+n, F+n-2;
      // the surface deleted. V' = 2En, E' = 3En + 2E, F' = 2V + En.
      const Counts expected{2 * e * n, 3 * e * n + 2 * e, 2 * v + e * n};
      const Mesh after = apply_and_check(mesh, "columns", {{"sides", n}}, expected);
      CHECK(euler_characteristic(after) == 2 * v - 2 * e);
      CHECK(components(after) == components(mesh));
      CHECK(after.num_hole_faces() == 0);
      if (components(mesh) == 1) CHECK(1 - euler_characteristic(after) / 2 == e - v + 1);
    }
  });
}

TEST_CASE("columns: the cube by hand, positions and the columns' walls") {
  const Mesh cube = test::cube();
  const double t = 0.1;
  for (long n : {4L, 5L}) {
    CAPTURE(n);
    // V 8, E 12: V 24n, E 36n + 24, F 16 + 12n; genus 5.
    const Mesh frame = apply_and_check(cube, "columns", {{"thickness", t}, {"sides", n}},
                                       {24 * n, 36 * n + 24, 16 + 12 * n});
    CHECK(1 - euler_characteristic(frame) / 2 == 5);
    // Every point of the frame is on a ring: at distance t from the line of a cube edge, 2t from one of its
    // ends along it. Returns the edge's ends (a, b), or nothing.
    auto axis_of = [&](const glm::dvec3& p) -> std::optional<std::pair<glm::dvec3, glm::dvec3>> {
      for (EdgeId ce : cube.edges()) {
        const glm::dvec3 a = cube.position(cube.from(ce)), b = cube.position(cube.to(ce));
        const glm::dvec3 d = glm::normalize(b - a);
        const double along = glm::dot(p - a, d);
        const double across = glm::length(p - a - along * d);
        const bool at_end = std::abs(along - 2 * t) < 1e-12 || std::abs(along - (2 - 2 * t)) < 1e-12;
        if (std::abs(across - t) < 1e-12 && at_end) return std::pair{a, b};
      }
      return std::nullopt;
    };
    for (VertexId x : frame.vertices()) CHECK(axis_of(frame.position(x)).has_value());
    // The columns' walls (quads along one edge) face away from its axis.
    long walls = 0;
    for (FaceId f : frame.faces()) {
      if (frame.size(f) != 4) continue;
      const auto axis = axis_of(frame.position(frame.vertex(frame.first_corner(f))));
      bool same = true;
      for (VertexId x : vertices(frame, f)) same = same && axis_of(frame.position(x)) == axis;
      if (!same) continue;
      ++walls;
      const glm::dvec3 c = face_centroid(frame, f), a = axis->first, d = glm::normalize(axis->second - a);
      const glm::dvec3 out = c - a - glm::dot(c - a, d) * d;
      CHECK(glm::dot(face_normal(frame, f), out) > 0);
    }
    CHECK(walls == 12 * n);
  }
}

TEST_CASE("shells: refusals name their parameter and change nothing") {
  const Mesh cube = test::cube();
  const Mesh grid = build_mesh(test::grid_soup(3, 2));
  CHECK(refused_parameter(cube, "crust", {{"thickness", 0.0}}) == "thickness");
  CHECK(refused_parameter(cube, "crust", {{"thickness", -1.0}}) == "thickness");
  CHECK(refused_parameter(cube, "crust", {{"thickness", std::numeric_limits<double>::infinity()}}) ==
        "thickness");
  {
    // A quad far below the origin, facing +z: its copy 1.5e308 further down would overflow.
    PolygonSoup low = test::grid_soup(1, 1);
    for (auto& p : low.positions) p.z = -0.8e308;
    CHECK(refused_parameter(build_mesh(low), "crust", {{"thickness", 1.5e308}},
                            "would not have a finite position") == "thickness");
  }
  CHECK(refused_parameter(cube, "rind", {{"faces", std::vector<FaceId>{}}}, "is empty") == "faces");
  CHECK(refused_parameter(cube, "rind", {{"faces", std::vector<FaceId>{FaceId(1), FaceId(1)}}},
                          "is listed twice") == "faces");
  CHECK(refused_parameter(cube, "rind", {{"faces", std::vector<FaceId>{FaceId(1)}}, {"thickness", 0.0}}) ==
        "thickness");
  CHECK(refused_parameter(cube, "rind", {{"faces", std::vector<FaceId>{FaceId(99)}}}) == "faces");
  {
    Editor ed;
    ed.set_mesh(cube);
    CHECK(test::error_message<ParameterError>([&] { ed.apply("rind", {}); }) ==
          "rind: give exactly one of parameters face and faces (neither is given)");
    CHECK(ed.mesh() == cube);
  }
  CHECK(refused_parameter(cube, "rind", {{"face", FaceId(99)}}) == "face");
  FaceId hole;
  for (FaceId f : grid.faces()) {
    if (grid.is_hole(f)) hole = f;
  }
  CHECK(refused_parameter(grid, "rind", {{"faces", std::vector<FaceId>{hole}}}, "is a hole face") == "faces");
  CHECK(refused_parameter(grid, "rind", {{"face", hole}}, "is a hole face") == "face");
  Mesh with_sphere = cube;
  const VertexId lone = with_sphere.create_vertex({5, 5, 5});
  CHECK(refused_parameter(with_sphere, "rind",
                          {{"faces", std::vector<FaceId>{with_sphere.face(with_sphere.corner(lone))}}},
                          "point sphere") == "faces");
  CHECK(refused_parameter(cube, "wireframe", {{"thickness", 0.0}}) == "thickness");
  CHECK(refused_parameter(cube, "wireframe", {{"width", -0.5}}) == "width");
  CHECK(refused_parameter(cube, "wireframe", {{"width", std::numeric_limits<double>::quiet_NaN()}}) ==
        "width");

  // The library functions refuse as the registered operations do, with the operation's wording.
  Mesh m = cube;
  {
    Transaction tx(m);
    CHECK(test::error_message<ParameterError>([&] { crust(tx, {0.0}); }) ==
          "crust: parameter thickness = 0 must be finite and > 0");
    CHECK(test::error_message<ParameterError>([&] { rind(tx, std::vector<FaceId>{}, {}); }) ==
          "rind: parameter faces is empty: it needs at least one face");
    CHECK(test::error_message<ParameterError>([&] {
            wireframe(tx, {0.05, 0.0});
          }) == "wireframe: parameter width = 0 must be finite and > 0");
    CHECK(tx.size() == 0);
  }
  CHECK(m == cube);
}

TEST_CASE("shells: point spheres") {
  // A lone vertex: crust copies it (as a point sphere, in place: it has no normal); wireframe leaves it.
  Mesh m = test::cube();
  const VertexId lone = m.create_vertex({5, 5, 5});
  Params out;
  const Mesh shell = apply_and_check(m, "crust", {}, {18, 24, 14}, &out);
  CHECK(shell.position(out.handles<VertexId>("vertices").back()) == m.position(lone));
  // The cube's frame (V 64, E 144, F 72) and the point sphere (V 1, F 1).
  apply_and_check(m, "wireframe", {}, {65, 144, 73});
  // The cube's columns (V 96, E 168, F 64) and the point sphere.
  const Mesh frame = apply_and_check(m, "columns", {}, {97, 168, 65});
  CHECK(frame.is_alive(lone));
  CHECK(frame.position(lone) == m.position(lone));
}
