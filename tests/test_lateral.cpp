// Lateral artifacts (docs/lateral_artifacts.md): the concave-edge measure, the honeycomb's `planarize`
// rule and the `hexagonalize` operation. Expected values come from hand computation (the comments), closed
// form counts and invariants.

#include <doctest/doctest.h>

#include <cmath>
#include <cstdint>
#include <vector>

#include <dlfl/analysis/concave_edges.h>
#include <dlfl/build_mesh.h>
#include <dlfl/errors.h>
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
