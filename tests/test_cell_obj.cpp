// OBJ for cell complexes (dlfl/cells/cell_obj.h, dlfl/cells/cell_io.h): points, polylines and quads, round
// trips, errors with their lines, and which files the tool must read as cell complexes.

#include <doctest/doctest.h>

#include <sstream>
#include <string>
#include <vector>

#include <dlfl/cells/cell_io.h>
#include <dlfl/cells/cell_obj.h>
#include <dlfl/errors.h>
#include "cell_file_helpers.h"

using namespace dlfl;

namespace {

std::vector<std::uint32_t> cell_of(const CellComplex& c, std::size_t i) {
  return {c.cell(i).begin(), c.cell(i).end()};
}

std::size_t error_line(const std::string& text) {
  try {
    parse_cell_obj(text, "bad.obj");
  } catch (const IoError& e) {
    CHECK(e.file() == "bad.obj");
    return e.line();
  }
  FAIL("no IoError");
  return 0;
}

}  // namespace

TEST_CASE("cell obj: p, l and f statements become 0-, 1- and 2-cells") {
  const std::string text =
      "# a unit square with a crease curve and a corner\n"
      "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0 1.0\n"  // a w value is ignored
      "vn 0 0 1\n"
      "f 1//1 2//1 3//1 4//1\n"
      "l 1 2 3\n"
      "p 4 -4\n"
      "g ignored\n";
  const CellComplex c = parse_cell_obj(text, "square.obj");
  REQUIRE(c.positions.size() == 4);
  REQUIRE(c.num_cells() == 5);
  // The face cycle (0,0) (1,0) (1,1) (0,1) in tensor order: vertex k at the corner whose coordinates are the
  // bits of k.
  REQUIRE(c.dimension(0) == 2);
  for (std::uint32_t k = 0; k < 4; ++k) {
    CHECK(c.positions[c.cell(0)[k]] == glm::dvec3(double(k & 1), double((k >> 1) & 1), 0.0));
  }
  CHECK(cell_of(c, 1) == std::vector<std::uint32_t>{0, 1});
  CHECK(cell_of(c, 2) == std::vector<std::uint32_t>{1, 2});
  CHECK(cell_of(c, 3) == std::vector<std::uint32_t>{3});
  CHECK(cell_of(c, 4) == std::vector<std::uint32_t>{0});  // -4: four back from the end
}

TEST_CASE("cell obj: round trips keep every cell and every position bit") {
  CellComplex c;
  c.positions = {{0.1, 1.0 / 3.0, -0.0},
                 {5e-324, 1e308, -2.5},
                 {std::nextafter(1.0, 2.0), -1e-300, 7},
                 {1, 2, 3},
                 {4, 5, 6}};
  c.add_cell({0, 1, 3, 2});
  c.add_cell({4, 0});
  c.add_cell({2});
  c.add_cell({1, 4});
  std::ostringstream out;
  write_cell_obj(out, c);
  test::check_identical(parse_cell_obj(out.str(), "rt.obj"), c);
  // The quad is written as its cycle.
  CHECK(out.str().find("\nf 1 2 3 4\n") != std::string::npos);
  test::ScratchDir dir;
  write_cell_complex(c, dir / "rt.obj");
  test::check_identical(read_cell_complex(dir / "rt.obj"), c);
  CHECK(dir.entries().size() == 1);
}

TEST_CASE("cell obj: bad input is an IoError at its line, and nothing is written") {
  const std::string v = "v 0 0 0\nv 1 0 0\nv 1 1 0\n";
  CHECK(error_line(v + "f 1 2 3\n") == 4);  // a triangle: not a cell
  CHECK(error_line(v + "v 0 1 0\nv 0 2 0\nf 1 2 3 4 5\n") == 6);
  CHECK(error_line(v + "l 1\n") == 4);
  CHECK(error_line(v + "p\n") == 4);
  CHECK(error_line(v + "l 1 2\nl 2 9\n") == 5);  // checked after the whole file, reported at its line
  CHECK(error_line(v + "l 1 0\n") == 4);
  CHECK(error_line(v + "l 1 -7\n") == 4);
  CHECK(error_line(v + "l 1 2 2\n") == 4);  // a segment from 2 to 2
  CHECK(error_line(v + "v 1 nan 0\n") == 4);
  CHECK(error_line("v 0 0\n") == 1);
  CHECK_THROWS_WITH_AS(parse_cell_obj(v + "f 1 2 3\n", "t.obj"), doctest::Contains("face has 3 vertices"),
                       IoError);

  test::ScratchDir dir;
  test::write_text(dir / "bad.obj", v + "f 1 2 3\n");
  CHECK_THROWS_AS(write_cell_complex(read_cell_complex(dir / "bad.obj"), dir / "out.obj"), IoError);
  // OBJ has no hexahedron: refused before any file is touched.
  CellComplex hex;
  for (int k = 0; k < 8; ++k) hex.positions.push_back({double(k & 1), double((k >> 1) & 1), double(k >> 2)});
  hex.add_cell({0, 1, 2, 3, 4, 5, 6, 7});
  CHECK_THROWS_WITH_AS(write_cell_complex(hex, dir / "out.obj"), doctest::Contains("hexahedron"), IoError);
  std::ostringstream sink;
  CHECK_THROWS_AS(write_cell_obj(sink, hex), IoError);
  CHECK(dir.entries().size() == 1);
}

TEST_CASE("cell obj: which files are cell complexes") {
  test::ScratchDir dir;
  test::write_text(dir / "curve.obj", "v 0 0 0\nv 1 0 0\n  l 1 2\n");
  test::write_text(dir / "points.obj", "v 0 0 0\np 1\n");
  test::write_text(dir / "mesh.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n# l 1 2 in a comment\nlx 1\n");
  test::write_text(dir / "mesh.off", "OFF\n");
  test::write_text(dir / "any.VTK", "not even vtk");
  CHECK(is_cell_complex_file(dir / "curve.obj"));
  CHECK(is_cell_complex_file(dir / "points.obj"));
  CHECK_FALSE(is_cell_complex_file(dir / "mesh.obj"));
  CHECK_FALSE(is_cell_complex_file(dir / "mesh.off"));
  CHECK(is_cell_complex_file(dir / "any.VTK"));
  CHECK_FALSE(is_cell_complex_file(dir / "missing.obj"));
  CHECK_THROWS_AS(read_cell_complex(dir / "mesh.off"), IoError);
}
