// The two MLCA implementations agree: the DLFL scheme `mlca` (dlfl/schemes/mlca_polygons.h, built on
// Catmull-Clark's connectivity) and the cell-complex `mlca_subdivide` (dlfl/cells/mlca_subdivide.h,
// multi-linear subdivision through a hash of shared sub-faces, then averaging). They share no code, so
// agreement on meshes with extraordinary vertices (where MLCA differs from Catmull-Clark) checks both.

#include <doctest/doctest.h>

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <vector>

#include <dlfl/build_mesh.h>
#include <dlfl/cells/convert.h>
#include <dlfl/cells/mlca_subdivide.h>
#include <dlfl/schemes/mlca_polygons.h>
#include "test_meshes.h"

using namespace dlfl;

namespace {

// A quad polygon soup as 2-cells: the cycle a b c d is the tensor-order cell (a, b, d, c).
CellComplex quads_as_cells(const PolygonSoup& soup) {
  CellComplex c;
  c.positions.assign(soup.positions.begin(), soup.positions.end());
  for (std::size_t f = 0; f < soup.num_faces(); ++f) {
    const auto q = soup.face(f);
    REQUIRE(q.size() == 4);
    c.add_cell({q[0], q[1], q[3], q[2]});
  }
  return c;
}

// The largest distance from a point of `a` to the nearest unused point of `b` (greedy; the meshes are small
// and their points far apart compared with the tolerance, so greedy matching is exact here).
double worst_match(const std::vector<glm::dvec3>& a, std::vector<glm::dvec3> b) {
  double worst = 0;
  for (const glm::dvec3& p : a) {
    auto best = b.begin();
    for (auto it = b.begin(); it != b.end(); ++it) {
      if (glm::length(*it - p) < glm::length(*best - p)) best = it;
    }
    worst = std::max(worst, glm::length(*best - p));
    b.erase(best);
  }
  return worst;
}

// Same number of vertices, input vertex i at the same place in both (both keep input vertices first, in
// order), and the same set of positions to 1e-12.
void check_same(const Mesh& ours, const CellComplex& cells, std::size_t input_vertices) {
  const PolygonSoup soup = to_polygons(ours);
  REQUIRE(soup.positions.size() == cells.positions.size());
  CHECK(soup.num_faces() == cells.num_cells());
  for (std::size_t i = 0; i < input_vertices; ++i) {
    CAPTURE(i);
    CHECK(glm::length(soup.positions[i] - cells.positions[i]) < 1e-12);
  }
  CHECK(worst_match(soup.positions, {cells.positions.begin(), cells.positions.end()}) < 1e-12);
}

}  // namespace

TEST_CASE("mlca agree: the DLFL scheme and the cell complex give the same cube after two steps") {
  // The cube's vertices are 3-valent: MLCA's vertex rule is not Catmull-Clark's there.
  const PolygonSoup cube = test::cube_soup();
  check_same(mlca(mlca(build_mesh(cube))), mlca_subdivide(quads_as_cells(cube), 2), cube.positions.size());
}

TEST_CASE("mlca agree: a genus-2 quad surface and a triangle mesh split to quads") {
  const PolygonSoup genus2 = test::genus_soup(2);
  check_same(mlca(build_mesh(genus2)), mlca_subdivide(quads_as_cells(genus2), 1), genus2.positions.size());
  // Triangles: the DLFL scheme splits them itself; the cell path splits with polygons_to_quads (section 3.3).
  const PolygonSoup tetra = test::tetrahedron_soup();
  check_same(mlca(build_mesh(tetra)), mlca_subdivide(polygons_to_quads(tetra), 1), tetra.positions.size());
}
