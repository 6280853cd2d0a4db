// Lateral artifacts (docs/lateral_artifacts.md): the concave-edge measure, the honeycomb's `planarize`
// rule and the `hexagonalize` operation. Expected values come from hand computation (the comments), closed
// form counts and invariants.

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <glm/geometric.hpp>
#include <vector>

#include <dlfl/analysis/concave_edges.h>
#include <dlfl/analysis/convex_polyhedron.h>
#include <dlfl/analysis/mesh_info.h>
#include <dlfl/build_mesh.h>
#include <dlfl/errors.h>
#include <dlfl/geometry.h>
#include <dlfl/mesh_hash.h>
#include <dlfl/operations/hexagonalize.h>
#include <dlfl/render/colors.h>
#include <dlfl/schemes/honeycomb.h>
#include <dlfl/schemes/zhang_wang_honeycomb.h>
#include <dlfl/validate.h>
#include "lateral_meshes.h"
#include "modeling_checks.h"
#include "test_meshes.h"

using namespace dlfl;

namespace {

// The L-shaped prism of height 2 over the hexagon (0,0) (2,0) (2,1) (1,1) (1,2) (0,2): 18 edges, all of them
// right angles; the vertical edge at the reflex corner (1,1) is the only concave one.
PolygonSoup l_prism_soup(double scale = 1.0) {
  const double xy[6][2] = {{0, 0}, {2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}};
  PolygonSoup s;
  for (int z = 0; z < 2; ++z) {
    for (const auto& p : xy) s.positions.push_back(scale * glm::dvec3(p[0], p[1], 2.0 * z));
  }
  test::add_prism_faces(s, 6);
  return s;
}

}  // namespace

TEST_CASE("concave_edges: a convex box has none, every bend 90 degrees") {
  const ConcaveEdges c = concave_edges(build_mesh(test::cube_soup()));
  CHECK(c.measured == 12);
  CHECK(c.concave == 0);
  CHECK(c.worst_concave_degrees == 0.0);
  CHECK(c.mean_dihedral_degrees == doctest::Approx(90.0));
}

TEST_CASE("concave_edges: the L prism's reflex edge is the one concave edge, whatever the scale") {
  for (double scale : {1.0, 1e-6, 1e6}) {
    CAPTURE(scale);
    const ConcaveEdges c = concave_edges(build_mesh(l_prism_soup(scale)));
    CHECK(c.measured == 18);
    CHECK(c.concave == 1);
    CHECK(c.worst_concave_degrees == doctest::Approx(90.0));
    CHECK(c.mean_dihedral_degrees == doctest::Approx(90.0));
  }
}

TEST_CASE("concave_edges: coplanar faces are not concave") {
  // The sides of the 6-gonal prism split into 3 rows: the 12 edges between rows join coplanar quads.
  const ConcaveEdges c = concave_edges(build_mesh(test::prism_rows_soup(6, 3)));
  CHECK(c.measured == 6 * 7);
  CHECK(c.concave == 0);
  // Mean bend: 12 edges between rows bend by 0, 18 vertical edges (6 per row) by 60, 12 at the caps by 90.
  CHECK(c.mean_dihedral_degrees == doctest::Approx((18 * 60.0 + 12 * 90.0) / 42.0));
}

TEST_CASE("concave_edges: edges beside a hole are not measured; a bad tolerance is refused") {
  const Mesh grid = build_mesh(test::grid_soup(3, 2));  // flat: 7 interior edges between coplanar quads
  const ConcaveEdges c = concave_edges(grid);
  CHECK(c.measured == 7);
  CHECK(c.concave == 0);
  CHECK(c.mean_dihedral_degrees == 0.0);
  CHECK_THROWS_AS(concave_edges(grid, -1.0), InvalidArgument);
  CHECK_THROWS_AS(concave_edges(grid, std::nan("")), InvalidArgument);
}

namespace {

// The honeycomb's closed-form counts and invariants between a step's input and output: V' = 2E, E' = 3E,
// F' = F + V, every vertex 3-valent, valid, the same genus per component.
void check_honeycomb_structure(const Mesh& in, const Mesh& out) {
  CHECK(out.num_vertices() == 2 * in.num_edges());
  CHECK(out.num_edges() == 3 * in.num_edges());
  CHECK(out.num_faces() == in.num_faces() + in.num_vertices());
  for (VertexId v : out.vertices()) CHECK(out.valence(v) == 3);
  const ValidationReport a = validate(in), b = validate(out);
  REQUIRE(b.valid());
  REQUIRE(a.components.size() == b.components.size());
  for (std::size_t i = 0; i < a.components.size(); ++i) CHECK(a.components[i].genus == b.components[i].genus);
}

HoneycombParams planarizing() {
  HoneycombParams p;
  p.planarize = true;
  return p;
}

}  // namespace

TEST_CASE("honeycomb planarize: the structure of the plain step, and no concave edge on convex shapes") {
  // Shapes of docs/lateral_artifacts.md whose table row reaches zero: two rows of quads per side, a box of
  // 2x2x2 unit squares. All are convex with planar faces, so every concave edge would be an artifact.
  for (const auto& shape : {std::pair{"6-prism, 2 rows", test::prism_rows_soup(6, 2)},
                            std::pair{"8-prism, 2 rows", test::prism_rows_soup(8, 2)},
                            std::pair{"box 2x2x2", test::box_grid_soup(2, 2, 2)}}) {
    const char* name = shape.first;  // a plain copy: clang 14 cannot capture a structured binding
    CAPTURE(name);
    Mesh m = build_mesh(shape.second), plain = m;
    for (int step = 1; step <= 3; ++step) {
      CAPTURE(step);
      Mesh next = honeycomb(m, planarizing());
      check_honeycomb_structure(m, next);
      CHECK(concave_edges(next).concave == 0);
      plain = honeycomb(plain);
      if (step >= 2) CHECK(concave_edges(plain).concave > 0);  // the plain scheme's artifact, from step 2
      m = std::move(next);
    }
  }
}

TEST_CASE("honeycomb planarize: off, or on a mesh without a flat region, the plain step bit for bit") {
  const Mesh prism = build_mesh(test::prism_rows_soup(6, 3));
  HoneycombParams off;
  off.planarize = false;
  CHECK(mesh_hash(honeycomb(prism, off)) == mesh_hash(honeycomb(prism)));
  // No two neighbouring faces of the icosahedron, nor of a 5-ring torus, are coplanar.
  for (const PolygonSoup& soup : {test::icosahedron_soup(), test::torus_soup(8, 5)}) {
    const Mesh m = build_mesh(soup);
    CHECK(honeycomb(m, planarizing()) == honeycomb(m));
  }
  // The 3-row prism has coplanar quads: the rule moves vertices.
  CHECK(mesh_hash(honeycomb(prism, planarizing())) != mesh_hash(honeycomb(prism)));
}

TEST_CASE("honeycomb planarize: never more concave edges than the plain scheme, nor a rougher smooth shape") {
  // The rule keeps its planarization only when it bends no more than the plain step from the same mesh, and
  // acts on the first step only; whole runs are compared here, on the shapes where the rule without that
  // test did worse (docs/lateral_artifacts.md) and on a smooth torus whose top and bottom rings are flat.
  for (const auto& shape :
       {std::pair{"4-prism, 3 rows", test::prism_rows_soup(4, 3)},
        std::pair{"box 2x3x4", test::box_grid_soup(2, 3, 4)},
        std::pair{"octahedron split", test::split_around_centroids(test::octahedron_soup())},
        std::pair{"torus 8x6", test::torus_soup(8, 6)}}) {
    const char* name = shape.first;
    CAPTURE(name);
    Mesh fixed = build_mesh(shape.second), plain = fixed;
    for (int step = 1; step <= 3; ++step) {
      CAPTURE(step);
      fixed = honeycomb(fixed, planarizing());
      plain = honeycomb(plain);
      const ConcaveEdges a = concave_edges(fixed), b = concave_edges(plain);
      CHECK(a.concave <= b.concave);
      CHECK(a.mean_dihedral_degrees <= b.mean_dihedral_degrees);
    }
  }
}

TEST_CASE("honeycomb planarize: after the first step (every inner vertex 3-valent), the plain step") {
  const Mesh once = honeycomb(build_mesh(test::prism_rows_soup(6, 3)), planarizing());
  CHECK(honeycomb(once, planarizing()) == honeycomb(once));
}

TEST_CASE("honeycomb planarize: the boundary curve stays exactly as it is") {
  // The 2x2x2 box without its top (faces 4 to 7 of box_grid_soup: the bottom's 4 come first), so that the
  // step has faces to planarize; the boundary rule's vertices (on the hole) are those of the plain step.
  const PolygonSoup box = test::box_grid_soup(2, 2, 2);
  PolygonSoup soup;
  soup.positions = box.positions;
  for (std::size_t f = 0; f < box.num_faces(); ++f) {
    if (f < 4 || f >= 8) soup.add_face(box.face(f));
  }
  const Mesh m = build_mesh(soup);
  const Mesh plain = honeycomb(m), fixed = honeycomb(m, planarizing());
  // Under the boundary rule the counts are those of docs/boundaries.md; the rule changes none of them.
  REQUIRE(plain.vertex_capacity() == fixed.vertex_capacity());
  CHECK(fixed.num_vertices() == plain.num_vertices());
  CHECK(fixed.num_edges() == plain.num_edges());
  CHECK(fixed.num_faces() == plain.num_faces());
  REQUIRE(validate(fixed).valid());
  std::size_t on_hole = 0, moved = 0;
  for (VertexId v : plain.vertices()) {
    bool hole = false;
    for (CornerId c : plain.corners(v)) hole = hole || plain.is_hole(plain.face(c));
    if (hole) {
      ++on_hole;
      CHECK(fixed.position(v) == plain.position(v));
    } else {
      moved += fixed.position(v) != plain.position(v);
    }
  }
  CHECK(on_hole > 0);
  CHECK(moved > 0);
}

TEST_CASE("honeycomb-zw planarize: the structure of the plain step, every CCV on its face's plane") {
  const Mesh m = build_mesh(test::prism_rows_soup(6, 2));
  ZhangWangParams p;
  p.planarize = true;
  const Mesh out = zhang_wang_honeycomb(m, p);
  check_honeycomb_structure(m, out);
  for (FaceId f : out.faces()) {
    const auto q = face_point(out, f);
    REQUIRE(q.has_value());
    const double distance = glm::dot(face_normal(out, f), *q - face_centroid(out, f));
    CHECK(std::abs(distance) < 1e-12);
  }
}

TEST_CASE("mesh_info_json: the shape fields for closed meshes only") {
  const std::string closed = mesh_info_json(build_mesh(l_prism_soup()), {.shape = true, .indent = -1});
  CHECK(closed.find("\"concave_edges\":1,") != std::string::npos);
  CHECK(closed.find("\"worst_concave_degrees\":90") != std::string::npos);
  CHECK(mesh_info_json(build_mesh(l_prism_soup()), {.indent = -1}).find("concave") == std::string::npos);
  CHECK(mesh_info_json(build_mesh(test::grid_soup(2, 2)), {.shape = true}).find("concave") ==
        std::string::npos);
}

TEST_CASE("concave_edges flags the edge, and render's concave colouring its two faces") {
  // The L-shaped prism: the vertical edge at the reflex corner (1, 1) is the only concave edge; its faces
  // are the two side quads that meet there.
  const Mesh l_prism = build_mesh(l_prism_soup());
  std::vector<bool> flags;
  concave_edges(l_prism, 1e-9, &flags);
  REQUIRE(flags.size() == l_prism.edge_capacity());
  std::vector<EdgeId> flagged;
  for (EdgeId e : l_prism.edges()) {
    if (flags[e.index()]) flagged.push_back(e);
  }
  REQUIRE(flagged.size() == 1);
  const glm::dvec3 a = l_prism.position(l_prism.from(flagged[0])),
                   b = l_prism.position(l_prism.to(flagged[0]));
  CHECK(a.x == 1.0);
  CHECK(a.y == 1.0);
  CHECK(b.x == 1.0);
  CHECK(b.y == 1.0);
  const std::vector<Rgba> colors = face_colors(l_prism, parse_color_by("concave"));
  for (FaceId f : l_prism.faces()) {
    const bool beside = f == l_prism.face(flagged[0], 0) || f == l_prism.face(flagged[0], 1);
    CHECK(colors[f.index()] == (beside ? concave_color : plain_color));
  }
  // A convex shape has no red face.
  const Mesh prism = build_mesh(test::prism_rows_soup(6, 3));
  for (const Rgba& c : face_colors(prism, parse_color_by("concave"))) CHECK(c == plain_color);
}

namespace {

// The largest distance of a face's corners from its plane, over the surface faces.
double worst_nonplanarity(const Mesh& m) {
  double worst = 0.0;
  for (FaceId f : m.faces()) {
    if (m.is_hole(f)) continue;
    const FacePlane plane = face_plane(m, f);
    for (CornerId c : m.corners(f))
      worst = std::max(worst, std::abs(plane.distance(m.position(m.vertex(c)))));
  }
  return worst;
}

// Whether p lies on the surface of the box [-1, 1]^3 (one coordinate at +-1, the others within).
bool on_cube(const glm::dvec3& p) {
  const double big = std::max({std::abs(p.x), std::abs(p.y), std::abs(p.z)});
  return std::abs(big - 1.0) < 1e-12;
}

}  // namespace

TEST_CASE("hexagonalize: the cube, counted by hand; the shape and the orientation kept, every face planar") {
  // Every edge of the cube is sharp and every vertex a corner of three (8 hubs); each edge gets two points.
  // V' = 2E + C + H = 24 + 24 + 8, E' = 3E + C + (3 per hub) = 36 + 24 + 24, F' = F + V + (2 per vertex) = 6
  // + 8 + 16: on each side, the shrunken square and four corner pieces.
  const Mesh cube = test::cube();
  const Mesh out = test::apply_and_check(cube, "hexagonalize", {}, {.v = 48, .e = 72, .f = 24}).mesh;
  CHECK(test::signed_volume(out) == doctest::Approx(8.0));
  for (VertexId v : out.vertices()) {
    CHECK(out.valence(v) == 3);
    CHECK(on_cube(out.position(v)));
  }
  CHECK(worst_nonplanarity(out) < 1e-12);
  std::size_t hexagons = 0;
  for (FaceId f : out.faces()) hexagons += out.size(f) == 6;
  CHECK(hexagons == 24);  // the corner pieces (with a straight angle where the cut meets the edge)
  CHECK(concave_edges(out).concave == 0);
}

TEST_CASE("hexagonalize: the 6-gonal prism with 3 rows per side, counted in closed form") {
  // V = 24, E = 42, F = 20. Sharp: the 18 vertical edges (60 degrees) and the 12 cap edges (90); the 12
  // edges between rows are flat. The 12 cap vertices have 3 sharp edges (hubs), the 12 others two in line
  // (cut by one edge). C = 2 x 30. V' = 84 + 60 + 12, E' = 126 + 60 + 12 + 3 x 12, F' = 20 + 24 + 2 x 12
  // + 12.
  const Mesh prism = build_mesh(test::prism_rows_soup(6, 3));
  const Mesh out = test::apply_and_check(prism, "hexagonalize", {}, {.v = 132, .e = 192, .f = 60}).mesh;
  for (VertexId v : out.vertices()) CHECK(out.valence(v) == 3);
  CHECK(worst_nonplanarity(out) < 1e-12);
  CHECK(test::signed_volume(out) == doctest::Approx(test::signed_volume(prism)));
  CHECK(concave_edges(out).concave == 0);
  // A plain honeycomb step from the result makes no concave edge either.
  CHECK(concave_edges(honeycomb(out)).concave == 0);
}

TEST_CASE("hexagonalize: with no sharp edge, the honeycomb's topology with the points on their faces") {
  // angle = 90: the prism's bends (60 and exactly 90 degrees) are not more than that, so nothing is cut:
  // V' = 2E, E' = 3E, F' = F + V as for a honeycomb step. The points stay on their faces: the copy of face f
  // (handle f) has f's normal, and its centroid is f's (the mean of the edge midpoints is the centroid, and
  // each point is halfway from its midpoint to the centroid). The faces around the old vertices cut across
  // the prism's edges, so the volume shrinks.
  const Mesh prism = build_mesh(test::prism_rows_soup(6, 3));
  for (double angle : {90.0, 180.0}) {
    CAPTURE(angle);
    const Mesh out =
        test::apply_and_check(prism, "hexagonalize", {{"angle", angle}}, {.v = 60, .e = 84, .f = 24}).mesh;
    CHECK(out.num_vertices() == 2 * prism.num_edges());
    for (VertexId v : out.vertices()) CHECK(out.valence(v) == 3);
    for (FaceId f : prism.faces()) {
      CHECK(glm::length(face_normal(out, f) - face_normal(prism, f)) < 1e-12);
      CHECK(glm::length(face_centroid(out, f) - face_centroid(prism, f)) < 1e-12);
    }
    CHECK(test::signed_volume(out) < test::signed_volume(prism));
  }
}

TEST_CASE("hexagonalize: an open grid is cut along its border, which keeps its place") {
  // The flat 3 x 2 grid: V = 12, E = 17, F = 6 + 1 hole, B = 10 border edges, no other sharp edge. Each
  // border vertex has two sharp edges (a hub), each border edge its midpoint: V' = 2E + H = 34 + 10,
  // E' = 3E - B + (2 per hub) = 51 - 10 + 20, F' = F + V + (1 per border vertex) - B + 1 hole = 6 + 12 + 1.
  const Mesh grid = build_mesh(test::grid_soup(3, 2));
  const Mesh out = test::apply_and_check(grid, "hexagonalize", {}, {.v = 32, .e = 44, .f = 12}).mesh;
  REQUIRE(out.num_hole_faces() == 1);
  for (FaceId f : out.faces()) {
    if (!out.is_hole(f)) continue;
    CHECK(out.size(f) == 20);
    for (CornerId c : out.corners(f)) {
      const glm::dvec3 p = out.position(out.vertex(c));
      CHECK(p.z == 0.0);
      CHECK((p.x == 0.0 || p.x == 3.0 || p.y == 0.0 || p.y == 2.0));
    }
  }
  CHECK(worst_nonplanarity(out) == 0.0);
}

TEST_CASE("hexagonalize: named attributes carried to the elements that stand for an element of their kind") {
  // The cube with a distinct value on every element (its index + 1; 0 the default) and a point sphere. By
  // hand (see the counts above): each vertex's hub keeps its value (8 vertices); each face's shrunken square
  // (6 faces: centroid and normal the face's); each edge's 5 edges: the two halves of its crossing (from a
  // point of a face to a point on the edge) and the three along it (hub, point, point, hub); each corner c's
  // 3 corners at the point of c (one in the shrunken square, two in the piece of c's vertex, at the points of
  // c and prev(c)) lie in c's face. Everything else reads the default: 56 - 8 vertices, 84 - 60 edges,
  // 30 - 6 faces, 168 - 72 corners.
  Mesh cube = test::cube();
  const VertexId lone = cube.create_vertex({5.0, 0.0, 0.0});
  cube.add_attribute(ElementKind::vertex, "v", AttributeValue(0));
  cube.add_attribute(ElementKind::edge, "e", AttributeValue(0));
  cube.add_attribute(ElementKind::face, "f", AttributeValue(0));
  cube.add_attribute(ElementKind::corner, "c", AttributeValue(glm::dvec3(0.0)));
  for (VertexId v : cube.vertices())
    cube.set_attribute_value(ElementKind::vertex, "v", v.index(), int(v.index()) + 1);
  for (EdgeId e : cube.edges())
    cube.set_attribute_value(ElementKind::edge, "e", e.index(), int(e.index()) + 1);
  for (FaceId f : cube.faces())
    cube.set_attribute_value(ElementKind::face, "f", f.index(), int(f.index()) + 1);
  for (CornerId c : cube.corners()) {
    cube.set_attribute_value(ElementKind::corner, "c", c.index(), glm::dvec3(c.index() + 1, 0.0, 0.0));
  }
  const Mesh out = test::apply_and_check(cube, "hexagonalize", {}, {.v = 48, .e = 72, .f = 24}).mesh;
  const auto value = [&](ElementKind kind, const char* name, std::uint32_t i) {
    return std::get<int>(out.attribute_value(kind, name, i));
  };
  std::size_t carried = 0;
  for (VertexId v : out.vertices()) {
    const int k = value(ElementKind::vertex, "v", v.index());
    if (k == 0) continue;
    ++carried;
    CHECK(out.position(v) == cube.position(VertexId(std::uint32_t(k - 1))));
  }
  CHECK(carried == 9);  // 8 hubs and the point sphere
  carried = 0;
  for (FaceId f : out.faces()) {
    const int k = value(ElementKind::face, "f", f.index());
    if (k == 0 || out.is_point_sphere(out.vertex(out.first_corner(f)))) continue;
    ++carried;
    const FaceId source(std::uint32_t(k - 1));
    CHECK(out.size(f) == 4);
    CHECK(glm::length(face_centroid(out, f) - face_centroid(cube, source)) < 1e-12);
    CHECK(glm::length(face_normal(out, f) - face_normal(cube, source)) < 1e-12);
  }
  CHECK(carried == 6);
  std::vector<int> edges_of(cube.edge_capacity(), 0);
  for (EdgeId e : out.edges()) {
    const int k = value(ElementKind::edge, "e", e.index());
    if (k == 0) continue;
    const EdgeId source(std::uint32_t(k - 1));
    ++edges_of[source.index()];
    // One end of the edge is on the input edge.
    const glm::dvec3 a = cube.position(cube.from(source)), b = cube.position(cube.to(source));
    const auto on_edge = [&](VertexId v) {
      const glm::dvec3 p = out.position(v);
      return glm::length(glm::cross(p - a, b - a)) < 1e-12 && glm::dot(p - a, b - p) >= 0.0;
    };
    CHECK((on_edge(out.from(e)) || on_edge(out.to(e))));
  }
  for (EdgeId e : cube.edges()) CHECK(edges_of[e.index()] == 5);
  std::vector<int> corners_of(cube.corner_capacity(), 0);
  carried = 0;
  for (CornerId c : out.corners()) {
    const double k = std::get<glm::dvec3>(out.attribute_value(ElementKind::corner, "c", c.index())).x;
    if (k == 0.0) continue;
    const CornerId source(std::uint32_t(k) - 1);
    ++corners_of[source.index()];
    ++carried;
    if (cube.is_point_sphere(cube.vertex(source))) continue;
    const FaceId f = cube.face(source);
    CHECK(std::abs(glm::dot(out.position(out.vertex(c)) - face_centroid(cube, f), face_normal(cube, f))) <
          1e-12);
  }
  CHECK(corners_of[cube.corner(lone).index()] == 1);
  CHECK(carried == 72 + 1);
}

TEST_CASE("hexagonalize: a hole keeps its face attribute") {
  Mesh grid = build_mesh(test::grid_soup(3, 2));
  grid.add_attribute(ElementKind::face, "mark", AttributeValue(false));
  for (FaceId f : grid.faces()) {
    if (grid.is_hole(f)) grid.set_attribute_value(ElementKind::face, "mark", f.index(), true);
  }
  const Mesh out = test::apply_and_check(grid, "hexagonalize", {}, {.v = 32, .e = 44, .f = 12}).mesh;
  for (FaceId f : out.faces()) {
    CHECK(std::get<bool>(out.attribute_value(ElementKind::face, "mark", f.index())) == out.is_hole(f));
  }
}

TEST_CASE("hexagonalize: refusals leave the mesh unchanged") {
  const Mesh cube = test::cube();
  CHECK(test::refused_parameter(cube, "hexagonalize", {{"angle", -1.0}}) == "angle");
  CHECK(test::refused_parameter(cube, "hexagonalize", {{"angle", 181.0}}) == "angle");
  CHECK_THROWS_AS(check_hexagonalize(cube, {std::nan("")}), ParameterError);
  // A 2-gon: an edge inserted between two neighbouring corners of a face.
  Mesh two_gon = cube;
  const CornerId c = two_gon.first_corner(FaceId(0));
  two_gon.insert_edge(c, two_gon.next(c));
  test::check_refusal(two_gon, "hexagonalize", {}, "mesh", "2-gon");
  // An edge with one face on both sides: a new vertex joined to a corner of a face.
  Mesh dangling = cube;
  const VertexId lone = dangling.create_vertex({0.0, 0.0, 1.0});
  dangling.insert_edge(dangling.corner(lone), dangling.first_corner(FaceId(0)));
  test::check_refusal(dangling, "hexagonalize", {}, "mesh", "on both sides");
}
