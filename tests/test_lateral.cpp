// Lateral artifacts (docs/lateral_artifacts.md): the concave-edge measure, the honeycomb's `planarize`
// rule and the `hexagonalize` operation. Expected values come from hand computation (the comments), closed
// form counts and invariants.

#include <doctest/doctest.h>

#include <cmath>
#include <cstdint>
#include <glm/geometric.hpp>
#include <vector>

#include <dlfl/analysis/concave_edges.h>
#include <dlfl/analysis/mesh_info.h>
#include <dlfl/build_mesh.h>
#include <dlfl/errors.h>
#include <dlfl/geometry.h>
#include <dlfl/mesh_hash.h>
#include <dlfl/schemes/honeycomb.h>
#include <dlfl/schemes/zhang_wang_honeycomb.h>
#include <dlfl/validate.h>
#include "lateral_meshes.h"
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
  for (const auto& [name, soup] : {std::pair{"6-prism, 2 rows", test::prism_rows_soup(6, 2)},
                                   std::pair{"8-prism, 2 rows", test::prism_rows_soup(8, 2)},
                                   std::pair{"box 2x2x2", test::box_grid_soup(2, 2, 2)}}) {
    CAPTURE(name);
    Mesh m = build_mesh(soup), plain = m;
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

TEST_CASE("honeycomb planarize: the boundary curve stays exactly as it is") {
  // A flat open grid folded along x = 1, so that the step has faces to planarize; the boundary rule's
  // vertices (on the hole) are those of the plain step.
  PolygonSoup soup = test::grid_soup(3, 2);
  for (glm::dvec3& p : soup.positions) p.z = p.x > 1.0 ? 0.5 * (p.x - 1.0) : 0.0;
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
