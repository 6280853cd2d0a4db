// multi_connect (docs/modeling.md, "Hulls"): on the modeling meshes (the convex ones with every selection of
// 3 faces and with all their faces, the torus, the genus-2 and genus-3 slabs, the cube beside a
// tetrahedron, a crust's inner shell, a pillow beside a cube), the counts in closed form from the hub's size
// (V_h the distinct vertices of the faces, F_h the faces of their convex hull by the brute force of
// brute_force_hull.h), the genus rule (k faces on one component add k - 1 handles; faces of c components
// join them with k - c handles), validity, the tubes' quads, the hub's orientation (a cavity when the faces
// face away from it), exact undo, redo and log replay; and every refusal, the mesh unchanged.

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <glm/geometric.hpp>
#include <limits>
#include <set>
#include <string>
#include <vector>

#include <dlfl/build_mesh.h>
#include <dlfl/create_face_manifold.h>
#include <dlfl/errors.h>
#include <dlfl/geometry.h>
#include <dlfl/navigation.h>
#include <dlfl/operations/crust.h>
#include <dlfl/operations/multi_connect.h>
#include <dlfl/operations/operation.h>
#include <dlfl/validate.h>

#include "brute_force_hull.h"
#include "modeling_checks.h"
#include "modeling_meshes.h"
#include "test_helpers.h"
#include "test_meshes.h"

using namespace dlfl;

namespace {

const Mesh& named(const std::vector<test::ModelingMesh>& meshes, const std::string& name) {
  for (const test::ModelingMesh& m : meshes) {
    if (m.name == name) return m.mesh;
  }
  FAIL("no modeling mesh " << name);
  throw;
}

std::vector<FaceId> surface_face_list(const Mesh& m) {
  std::vector<FaceId> out;
  for (FaceId f : surface_faces(m)) out.push_back(f);
  return out;
}

// The face whose centroid is `centroid` (to 1e-9) and whose unit normal is `normal`.
FaceId face_at(const Mesh& m, const glm::dvec3& centroid, const glm::dvec3& normal) {
  for (FaceId f : surface_faces(m)) {
    if (glm::length(face_centroid(m, f) - centroid) < 1e-9 && glm::length(face_normal(m, f) - normal) < 1e-9)
      return f;
  }
  FAIL("no face at the given centroid and normal");
  throw;
}

// The genera of the components, sorted.
std::vector<long> genera(const Mesh& m) {
  std::vector<long> out;
  for (const ComponentInfo& c : validate(m).components) out.push_back(c.genus);
  std::sort(out.begin(), out.end());
  return out;
}

// Which component (by the index validate gives it) each face lies on, found by a search along the edges
// from the vertices of each component in validate's order.
std::vector<std::size_t> component_of_faces(const Mesh& m, const std::vector<FaceId>& faces) {
  std::vector<std::size_t> label(m.vertex_capacity(), std::size_t(-1));
  std::size_t next = 0;
  for (VertexId root : m.vertices()) {
    if (label[root.index()] != std::size_t(-1)) continue;
    std::vector<VertexId> stack{root};
    label[root.index()] = next;
    while (!stack.empty()) {
      const VertexId v = stack.back();
      stack.pop_back();
      for (VertexId w : neighbours(m, v)) {
        if (label[w.index()] == std::size_t(-1)) label[w.index()] = next, stack.push_back(w);
      }
    }
    ++next;
  }
  std::vector<std::size_t> out;
  for (FaceId f : faces) out.push_back(label[m.vertex(m.first_corner(f)).index()]);
  return out;
}

// multi_connect of `faces` on `start` through the editor (valid, undo, redo, replay), checked against the
// closed forms: the hub from the faces' distinct vertices and the brute-force hull of their positions; the
// genus rule; the tubes; the hub's orientation (`away`: the faces face away from the hub, which is then a
// cavity whose faces look toward its centre).
void check_multi_connect_on(const Mesh& start, const std::vector<FaceId>& faces, bool away,
                            double scale = 0.5) {
  CAPTURE(faces.size());
  std::set<test::Key> distinct;
  std::vector<glm::dvec3> hub_points;
  long sides = 0;
  for (FaceId f : faces) {
    sides += long(start.size(f));
    for (VertexId v : vertices(start, f)) {
      if (distinct.insert(test::key(start.position(v))).second) hub_points.push_back(start.position(v));
    }
  }
  const long k = long(faces.size());
  const long hub_vertices = long(hub_points.size());
  const long hub_faces = long(test::brute_force_planes(hub_points, 1e-9).size());
  const long hub_edges = hub_vertices + hub_faces - 2;

  const std::vector<long> genera_before = genera(start);
  const std::vector<std::size_t> comps = component_of_faces(start, faces);
  const std::set<std::size_t> joined(comps.begin(), comps.end());
  long joined_genus = 0;
  std::vector<long> untouched;
  {
    const auto components = validate(start).components;
    for (std::size_t c = 0; c < components.size(); ++c) {
      if (joined.count(c)) {
        joined_genus += components[c].genus;
      } else {
        untouched.push_back(components[c].genus);
      }
    }
  }

  Params params;
  params["faces"] = faces;
  params["scale"] = scale;
  Params out;
  const Mesh after = test::check_editor_round_trip(start, "multi_connect", params, &out);
  const test::Counts before = test::counts(start);
  CHECK(test::counts(after) == test::Counts{before.v + hub_vertices, before.e + hub_edges + sides,
                                            before.f + hub_faces + sides - 2 * k});
  CHECK(test::euler_characteristic(after) == test::euler_characteristic(start) + 2 - 2 * k);
  // The genus rule: the components of the faces and the hub become one, of their genera plus k - c.
  std::vector<long> expected = untouched;
  expected.push_back(joined_genus + k - long(joined.size()));
  std::sort(expected.begin(), expected.end());
  CHECK(genera(after) == expected);
  CHECK(genera_before.size() - joined.size() + 1 == genera(after).size());

  // The tubes: a quad per side of each face.
  const std::vector<FaceId> tube = out.get("faces").as_handles<FaceId>();
  CHECK(long(tube.size()) == sides);
  for (FaceId f : tube) CHECK(after.size(f) == 4);
  // The hub: its vertices at c + scale (p - c), and its faces that no tube took facing its centre (a cavity)
  // or away from it.
  const std::vector<VertexId> hub = out.get("vertices").as_handles<VertexId>();
  CHECK(long(hub.size()) == hub_vertices);
  glm::dvec3 centre(0.0);
  for (const glm::dvec3& p : hub_points) centre += p / double(hub_points.size());
  std::set<test::Key> expected_positions, positions;
  for (const glm::dvec3& p : hub_points) expected_positions.insert(test::key(centre + scale * (p - centre)));
  std::set<std::uint32_t> hub_set;
  glm::dvec3 hub_centre(0.0);
  for (VertexId v : hub) {
    hub_set.insert(v.index());
    hub_centre += after.position(v) / double(hub.size());
    bool found = false;
    for (const test::Key& e : expected_positions) {
      const glm::dvec3 q(std::get<0>(e), std::get<1>(e), std::get<2>(e));
      found = found || glm::length(q - after.position(v)) < 1e-12;
    }
    CHECK(found);
  }
  long hub_faces_left = 0;
  for (FaceId f : surface_faces(after)) {
    bool all = true;
    for (VertexId v : vertices(after, f)) all = all && hub_set.count(v.index()) == 1;
    if (!all) continue;
    ++hub_faces_left;
    const double outward = glm::dot(face_normal(after, f), face_centroid(after, f) - hub_centre);
    CHECK((away ? outward < 0 : outward > 0));
  }
  CHECK(hub_faces_left == hub_faces - k);
}

// Every selection of `k` surface faces of a mesh (in handle order), for the convex meshes.
void for_each_selection(const std::vector<FaceId>& all, std::size_t k, std::vector<FaceId>& chosen,
                        std::size_t from, const std::function<void(const std::vector<FaceId>&)>& visit) {
  if (chosen.size() == k) {
    visit(chosen);
    return;
  }
  for (std::size_t i = from; i < all.size(); ++i) {
    chosen.push_back(all[i]);
    for_each_selection(all, k, chosen, i + 1, visit);
    chosen.pop_back();
  }
}

// A cube and, at x = 3, a pillow (the two sides of one triangle), the front facing +x.
struct CubeAndPillow {
  Mesh mesh;
  FaceManifold pillow;
};

CubeAndPillow cube_and_pillow() {
  CubeAndPillow out{test::cube(), {}};
  const std::vector<glm::dvec3> triangle = {{3, -0.5, -0.5}, {3, 0.5, -0.5}, {3, 0, 0.5}};
  out.pillow = create_face_manifold(out.mesh, triangle);
  return out;
}

}  // namespace

TEST_CASE("multi_connect on the convex meshes: every selection of 3 faces, and all the faces") {
  const auto meshes = test::modeling_meshes();
  for (const char* name :
       {"tetrahedron", "cube", "octahedron", "pentagonal prism", "hexagonal prism", "octagonal prism"}) {
    const std::string label = name;
    CAPTURE(label);
    const Mesh& start = named(meshes, label);
    const std::vector<FaceId> all = surface_face_list(start);
    std::vector<FaceId> chosen;
    // A strictly convex polyhedron: every face of it is a face of the hull of any of its vertices that
    // include the face's, so every selection is accepted, and the faces face away from the hub.
    for_each_selection(all, 3, chosen, 0,
                       [&](const std::vector<FaceId>& faces) { check_multi_connect_on(start, faces, true); });
    check_multi_connect_on(start, all, true, 0.3);
  }
  // By hand: the cube's three faces around its corner 0 (z = -1, y = -1, x = -1). Their hub is the hull of
  // the 7 other corners scaled: the 3 squares, the 3 faces around the missing corner cut to triangles, and
  // the triangle that cuts it off (V_h 7, F_h 7, E_h 12); 3 tubes of 4 quads. V 8 + 7, E 12 + 12 + 12,
  // F 6 + 7 + 12 - 6; genus 2.
  Params p;
  p["faces"] = std::vector<FaceId>{FaceId(0), FaceId(2), FaceId(4)};
  const Mesh after = test::check_editor_round_trip(named(meshes, "cube"), "multi_connect", p);
  CHECK(test::counts(after) == test::Counts{15, 36, 19});
  CHECK(genera(after) == std::vector<long>{2});
}

TEST_CASE("multi_connect on the torus, the genus slabs and the cube beside the tetrahedron") {
  const auto meshes = test::modeling_meshes();
  SUBCASE("torus 4x3: three outer faces (away from the hub) and three inner faces (toward it)") {
    // Face i * 3 + j runs between rings i and i + 1 around the axis and j and j + 1 around the tube: j = 0
    // the upper outside, j = 1 the inside, facing the axis.
    const Mesh& torus = named(meshes, "torus 4x3");
    check_multi_connect_on(torus, {FaceId(0), FaceId(3), FaceId(6)}, true);
    check_multi_connect_on(torus, {FaceId(1), FaceId(4), FaceId(7), FaceId(10)}, false);
  }
  for (const char* name : {"genus 2", "genus 3"}) {
    const std::string label = name;
    CAPTURE(label);
    const Mesh& slab = named(meshes, label);
    // The four faces of the corner cell [0, 1]^3 that are on the surface: its top, bottom, and the sides at
    // y = 0 and x = 0; their hub is the cell itself.
    const FaceId top = face_at(slab, {0.5, 0.5, 1}, {0, 0, 1});
    const FaceId bottom = face_at(slab, {0.5, 0.5, 0}, {0, 0, -1});
    const FaceId front = face_at(slab, {0.5, 0, 0.5}, {0, -1, 0});
    const FaceId left = face_at(slab, {0, 0.5, 0.5}, {-1, 0, 0});
    check_multi_connect_on(slab, {top, bottom, front}, true);
    check_multi_connect_on(slab, {top, bottom, front, left}, true, 0.8);
    // Sides at three ends of the slab.
    const FaceId right = face_at(slab, {label == "genus 2" ? 5.0 : 7.0, 1.5, 0.5}, {1, 0, 0});
    const FaceId back = face_at(slab, {1.5, 3, 0.5}, {0, 1, 0});
    check_multi_connect_on(slab, {front, right, back}, true);
  }
  SUBCASE("cube and tetrahedron: faces of both components join them") {
    const Mesh& both = named(meshes, "cube and tetrahedron");
    const FaceId cube_left = face_at(both, {-1, 0, 0}, {-1, 0, 0});
    std::vector<FaceId> faces{cube_left};
    for (FaceId f : surface_faces(both)) {
      if (face_centroid(both, f).x > 5.1) faces.push_back(f);  // the tetrahedron's two faces toward +x
    }
    REQUIRE(faces.size() == 3);
    check_multi_connect_on(both, faces, true);
    // Three faces of the cube alone leave the tetrahedron as it is.
    check_multi_connect_on(both, {FaceId(0), FaceId(1), FaceId(2)}, true);
  }
}

TEST_CASE("multi_connect of faces that face toward the hub, and of a pillow beside a cube") {
  SUBCASE("the inner shell of a crust faces its centre: the hub is kept as the hull, not turned inside out") {
    Mesh m = test::cube();
    {
      Transaction tx(m);
      crust(tx, {0.2});
      tx.commit();
    }
    // The inner copy's faces: those whose vertices are all inside the cube.
    std::vector<FaceId> inner;
    for (FaceId f : surface_faces(m)) {
      bool inside = true;
      for (VertexId v : vertices(m, f)) inside = inside && std::abs(m.position(v).x) < 0.999;
      if (inside) inner.push_back(f);
    }
    REQUIRE(inner.size() == 6);
    check_multi_connect_on(m, {inner[0], inner[1], inner[2]}, false);
    check_multi_connect_on(m, inner, false);
  }
  SUBCASE("the pillow's front faces away from the hub of the cube's top and bottom: joined, genus 1") {
    const CubeAndPillow cp = cube_and_pillow();
    const FaceId top = face_at(cp.mesh, {0, 0, 1}, {0, 0, 1});
    const FaceId bottom = face_at(cp.mesh, {0, 0, -1}, {0, 0, -1});
    check_multi_connect_on(cp.mesh, {top, bottom, cp.pillow.front}, true);
  }
}

TEST_CASE("multi_connect refuses bad selections and parameters, naming them, the mesh unchanged") {
  const auto meshes = test::modeling_meshes();
  const Mesh& cube = named(meshes, "cube");
  auto refusal = [](const Mesh& m, Params p, const std::string& parameter) {
    if (!p.has("faces")) p["faces"] = std::vector<FaceId>{FaceId(0), FaceId(1), FaceId(2)};
    return test::check_refusal(m, "multi_connect", p, parameter);
  };
  auto faces = [](std::vector<FaceId> f) {
    Params p;
    p["faces"] = f;
    return p;
  };
  CHECK(refusal(cube, faces({FaceId(0), FaceId(1)}), "faces").find("at least 3 faces") != std::string::npos);
  CHECK(refusal(cube, faces({}), "faces").find("empty") != std::string::npos);
  CHECK(refusal(cube, faces({FaceId(0), FaceId(1), FaceId(1)}), "faces").find("twice") != std::string::npos);
  {
    // A removed face: the cube with one edge deleted (its two faces merge, one goes).
    Mesh m = cube;
    const FaceId gone = m.delete_edge(EdgeId(0)).removed_face;
    REQUIRE(gone.valid());
    refusal(m, faces({gone, FaceId(gone.index() == 5 ? 4 : 5), FaceId(gone.index() == 3 ? 2 : 3)}), "faces");
  }
  {
    const Mesh& grid = named(meshes, "open grid 3x2");
    FaceId hole;
    for (FaceId f : grid.faces()) {
      if (grid.is_hole(f)) hole = f;
    }
    CHECK(refusal(grid, faces({FaceId(0), FaceId(1), hole}), "faces").find("hole") != std::string::npos);
    // Three faces in one plane: no hub with an inside.
    CHECK(refusal(grid, faces({FaceId(0), FaceId(1), FaceId(2)}), "faces").find("degenerate") !=
          std::string::npos);
  }
  {
    Mesh m = cube;
    const VertexId lone = m.create_vertex({5, 5, 5});
    const FaceId sphere = m.face(m.corner(lone));
    CHECK(refusal(m, faces({FaceId(0), FaceId(1), sphere}), "faces").find("point sphere") !=
          std::string::npos);
  }
  for (double scale : {0.0, 1.0, 1.5, -0.5}) {
    Params p;
    p["scale"] = scale;
    refusal(cube, p, "scale");
  }
  {
    Params p;
    p["method"] = std::string("sphere");
    refusal(cube, p, "method");
  }
  {
    // The tops of two neighbouring cells of a slab and the bottom of one: the vertices the tops share lie on
    // an edge of the hull of the faces' vertices.
    const Mesh& slab = named(meshes, "genus 2");
    const std::string message =
        refusal(slab,
                faces({face_at(slab, {0.5, 0.5, 1}, {0, 0, 1}), face_at(slab, {1.5, 0.5, 1}, {0, 0, 1}),
                       face_at(slab, {0.5, 0.5, 0}, {0, 0, -1})}),
                "faces");
    CHECK(message.find("would not be a corner of the hub") != std::string::npos);
  }
  {
    // The cube with its corner (1, 1, 1) pulled out: the top face is no longer planar, so the hull of the
    // faces' vertices cuts it in two and the hub has no copy of it.
    PolygonSoup soup = test::cube_soup();
    soup.positions[7] = {1.3, 1.2, 1.1};
    const Mesh bent = build_mesh(soup);
    const FaceId top(1), bottom(0), front(2);  // z = +1, z = -1, y = -1 (cube_soup's order)
    const std::string message = refusal(bent, faces({top, bottom, front}), "faces");
    CHECK(message.find("has no copy among the faces of the hub") != std::string::npos);
  }
  {
    // The pillow's back faces the other way than the cube's top and bottom.
    const CubeAndPillow cp = cube_and_pillow();
    const FaceId top = face_at(cp.mesh, {0, 0, 1}, {0, 0, 1});
    const FaceId bottom = face_at(cp.mesh, {0, 0, -1}, {0, 0, -1});
    const std::string message = refusal(cp.mesh, faces({top, bottom, cp.pillow.back}), "faces");
    CHECK(message.find("toward it") != std::string::npos);
  }
  // The library function refuses what the registry cannot express.
  Mesh m = cube;
  const std::vector<FaceId> three{FaceId(0), FaceId(1), FaceId(2)};
  for (double scale : {std::numeric_limits<double>::quiet_NaN(), std::numeric_limits<double>::infinity()}) {
    const std::string message =
        test::error_message<ParameterError>([&] { check_multi_connect(m, three, {scale}); });
    CHECK(message.rfind("multi_connect: parameter scale: ", 0) == 0);
    Transaction tx(m);
    CHECK_THROWS_AS(multi_connect(tx, three, {scale}), ParameterError);
  }
  CHECK(m == cube);
}
