// Cell complexes at their limits: malformed offsets, absurd iteration counts and outputs a format cannot hold
// are refused with an error before anything is read out of range or any long work starts.

#include <doctest/doctest.h>

#include <climits>
#include <filesystem>
#include <string>

#include <dlfl/cells/cell_complex.h>
#include <dlfl/cells/cell_io.h>
#include <dlfl/cells/convert.h>
#include <dlfl/cells/mlca_subdivide.h>
#include <dlfl/errors.h>

using namespace dlfl;

TEST_CASE("cells limits: offsets that run past the index list are refused before any cell is read") {
  // Cell 0 claims indices 0..7 of a list of 4: reading it would run off the end.
  CellComplex c;
  c.positions.assign(8, glm::dvec3(0.0));
  c.indices = {0, 1, 2, 3};
  c.offsets = {0, 8, 4};
  CHECK_THROWS_WITH_AS(check_cell_complex(c), doctest::Contains("run past the index list at cell 0"),
                       InvalidArgument);
  PolygonSoup soup;
  soup.positions.assign(1000, glm::dvec3(0.0));
  soup.indices = {0, 1, 2, 3, 4};
  soup.offsets = {0, 100, 5};
  CHECK_THROWS_WITH_AS(polygons_to_quads(soup), doctest::Contains("run past the index list at face 0"),
                       InvalidArgument);
}

TEST_CASE("cells limits: iteration counts beyond 32-bit indices are refused at once") {
  CellComplex hex;
  for (int k = 0; k < 8; ++k) hex.positions.push_back({double(k & 1), double((k >> 1) & 1), double(k >> 2)});
  hex.add_cell({0, 1, 2, 3, 4, 5, 6, 7});
  // One hexahedron after t steps: 8^t cells of 8 indices = 2^(3t + 3). t = 9 gives 2^30: fine in principle;
  // t = 10 gives 2^33: too many. Huge counts must not overflow the estimate into acceptance.
  for (int t : {10, 1000, INT_MAX}) {
    CAPTURE(t);
    CHECK_THROWS_WITH_AS(mlca_subdivide(hex, t), doctest::Contains("32 bits"), InvalidArgument);
  }
  // Points alone never change, so any number of steps is one step, and INT_MAX of them return at once.
  CellComplex points;
  points.positions = {{1, 2, 3}, {4, 5, 6}};
  points.add_cell({0});
  points.add_cell({1});
  const CellComplex same = mlca_subdivide(points, INT_MAX);
  CHECK(same.positions == points.positions);
  CHECK(same.num_cells() == 2);
}

TEST_CASE("cells limits: an output that cannot hold the complex is known before any work") {
  CellComplex hex;
  hex.positions.assign(8, glm::dvec3(0.0));
  hex.add_cell({0, 1, 2, 3, 4, 5, 6, 7});
  CHECK_THROWS_WITH_AS(check_cell_complex_output(hex, "out.obj"), doctest::Contains("hexahedron"), IoError);
  CHECK_THROWS_AS(check_cell_complex_output(hex, "out.ply"), IoError);
  CHECK_NOTHROW(check_cell_complex_output(hex, "out.vtk"));
  CellComplex quad;
  quad.positions.assign(4, glm::dvec3(0.0));
  quad.add_cell({0, 1, 2, 3});
  CHECK_NOTHROW(check_cell_complex_output(quad, "out.obj"));
  CHECK_FALSE(std::filesystem::exists("out.obj"));  // a check, not a write
}
