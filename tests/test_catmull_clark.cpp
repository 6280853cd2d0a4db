// Catmull-Clark: counts, valences, hand-derived positions, affine invariance, errors. (Agreement with CGAL's
// implementation is in tests/oracle.)

#include <doctest/doctest.h>

#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>

#include <dlfl/errors.h>
#include <dlfl/schemes/catmull_clark.h>
#include <dlfl/validate.h>
#include "scheme_meshes.h"
#include "test_helpers.h"
#include "test_meshes.h"

using namespace dlfl;
using test::require_valid;

namespace {

void check_counts(const Mesh& in) {
  const Mesh out = catmull_clark(in);
  const auto before = validate(in);
  const auto after = validate(out);
  REQUIRE(after.valid());
  // Every corner becomes a quad; edges: each old edge splits in two, each corner adds the edge from its face
  // point to the edge point of its outgoing edge.
  CHECK(out.num_faces() == in.num_corners());
  CHECK(out.num_vertices() == in.num_vertices() + in.num_edges() + in.num_faces());
  CHECK(out.num_edges() == 2 * in.num_edges() + in.num_corners());
  for (FaceId f : out.faces()) CHECK(out.size(f) == 4);
  REQUIRE(after.components.size() == before.components.size());
  for (std::size_t i = 0; i < before.components.size(); ++i) {
    CHECK(after.components[i].genus == before.components[i].genus);
  }
  // Valences: old vertices keep theirs, edge points get 4, face points get their face's size.
  std::uint32_t v = 0;
  for (VertexId old : in.vertices()) CHECK(out.valence(VertexId(v++)) == in.valence(old));
  for (std::size_t e = 0; e < in.num_edges(); ++e) CHECK(out.valence(VertexId(v++)) == 4);
  for (FaceId f : in.faces()) CHECK(out.valence(VertexId(v++)) == in.size(f));
}

}  // namespace

TEST_CASE("catmull-clark: counts and valences on meshes of several genera and face mixes") {
  check_counts(test::tetrahedron());
  check_counts(test::cube());
  check_counts(test::dodecahedron());
  check_counts(test::mixed_polyhedron());
  check_counts(build_mesh(test::torus_soup(7, 5)));
  check_counts(build_mesh(test::genus_soup(3)));
}

TEST_CASE("catmull-clark: the cube by hand") {
  const Mesh out = catmull_clark(test::cube());
  // Vertex (-1,-1,-1), n = 3: Q = average of the face centres (-1,0,0), (0,-1,0), (0,0,-1) = -(1/3)(1,1,1);
  // R = average of the edge midpoints (0,-1,-1), (-1,0,-1), (-1,-1,0) = -(2/3)(1,1,1); S has weight n-3 = 0.
  // (Q + 2R)/3 = -(5/9)(1,1,1).
  const glm::dvec3 corner = out.position(VertexId(0));
  CHECK(corner.x == doctest::Approx(-5.0 / 9.0).epsilon(1e-15));
  CHECK(corner.y == doctest::Approx(-5.0 / 9.0).epsilon(1e-15));
  CHECK(corner.z == doctest::Approx(-5.0 / 9.0).epsilon(1e-15));
  // Every edge point of the cube: the average of two corners (a unit edge midpoint at distance sqrt 2) and
  // two face centres at distance 1, e.g. ((-1,-1,-1) + (1,-1,-1) + (0,-1,0) + (0,0,-1))/4 = (0,-3/4,-3/4).
  const Mesh cube = test::cube();
  for (std::uint32_t e = 0; e < 12; ++e) {
    const glm::dvec3 p = out.position(VertexId(8 + e));
    const glm::dvec3 a = glm::abs(p);
    // Two coordinates are 3/4 in magnitude and one is 0.
    CHECK(a.x + a.y + a.z == doctest::Approx(1.5).epsilon(1e-15));
    CHECK(std::min({a.x, a.y, a.z}) == 0.0);
  }
  // Face points are the face centroids: the unit axis points.
  for (std::uint32_t f = 0; f < 6; ++f)
    CHECK(glm::length(out.position(VertexId(20 + f))) == doctest::Approx(1.0));
}

TEST_CASE("catmull-clark: affine invariance") {
  const Mesh in = build_mesh(test::torus_soup(6, 4));
  const glm::dmat3 a(1.2, 0.3, -0.1, 0.2, 0.9, 0.4, -0.3, 0.1, 1.1);
  const glm::dvec3 shift(0.5, -2.0, 3.0);
  Mesh moved = in;
  for (VertexId v : moved.vertices()) moved.set_position(v, a * moved.position(v) + shift);
  const Mesh x = catmull_clark(moved);
  const Mesh y = catmull_clark(in);
  REQUIRE(x.num_vertices() == y.num_vertices());
  for (VertexId v : x.vertices()) {
    const glm::dvec3 d = x.position(v) - (a * y.position(v) + shift);
    CHECK(std::max({std::abs(d.x), std::abs(d.y), std::abs(d.z)}) < 1e-12);
  }
}

TEST_CASE("catmull-clark: point spheres are refused and tombstones do not matter") {
  Mesh m = test::cube();
  const VertexId p = m.create_vertex({5, 5, 5});
  CHECK_THROWS_AS(catmull_clark(m), TopologyError);
  m.delete_vertex(p);  // now a tombstone: same result as the plain cube
  const Mesh a = catmull_clark(m);
  const Mesh b = catmull_clark(test::cube());
  CHECK(a == b);
}

TEST_CASE("catmull-clark: with boundary=hole, hole faces are subdivided and their quads stay holes") {
  const Mesh in = build_mesh(test::grid_soup(3, 2));  // 6 quads and one hole of 10 corners
  const Mesh out = catmull_clark(in, {BoundaryRule::hole});
  require_valid(out);
  std::size_t holes = 0;
  for (FaceId f : out.faces()) holes += out.is_hole(f);
  CHECK(holes == 10);
  CHECK(out.num_faces() == 24 + 10);
}
