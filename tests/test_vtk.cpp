// VTK legacy unstructured grids (dlfl/cells/vtk.h): the vertex-order mapping on a hand-made unit cube, ASCII
// and binary round trips with bit-identical positions, version 5 files, and every bad-input error with its
// line.

#include <doctest/doctest.h>

#include <bit>
#include <cmath>
#include <limits>
#include <random>
#include <sstream>
#include <string>
#include <vector>

#include <dlfl/cells/cell_io.h>
#include <dlfl/cells/vtk.h>
#include <dlfl/errors.h>
#include "cell_file_helpers.h"

using namespace dlfl;

namespace {

// The corner of the unit cube whose coordinates are the bits of k: where tensor vertex k must sit.
glm::dvec3 tensor_corner(std::uint32_t k) {
  return {double(k & 1), double((k >> 1) & 1), double((k >> 2) & 1)};
}

// Points listed in VTK's hexahedron order: bottom square counter-clockwise, then the top one.
const std::string unit_cube_vtk =
    "# vtk DataFile Version 3.0\n"
    "unit cube\n"
    "ASCII\n"
    "DATASET UNSTRUCTURED_GRID\n"
    "POINTS 8 double\n"
    "0 0 0  1 0 0  1 1 0\n"
    "0 1 0  0 0 1  1 0 1\n"
    "1 1 1  0 1 1\n"
    "CELLS 4 28\n"
    "8 0 1 2 3 4 5 6 7\n"  // HEXAHEDRON: cycles
    "4 0 1 2 3\n"          // QUAD: a cycle
    "8 0 1 3 2 4 5 7 6\n"  // VOXEL: already tensor order
    "4 0 1 3 2\n"          // PIXEL: already tensor order
    "CELL_TYPES 4\n"
    "12\n"
    "9\n"
    "11\n"
    "8\n";

// Two cells on four points; the error cases below change one line of it (lines numbered from 1).
std::vector<std::string> base_lines() {
  return {"# vtk DataFile Version 3.0",
          "title",
          "ASCII",
          "DATASET UNSTRUCTURED_GRID",
          "POINTS 4 double",
          "0 0 0",  // line 6
          "1 0 0",
          "1 1 0",
          "0 1 0",
          "CELLS 2 8",  // line 10
          "4 0 1 2 3",
          "2 0 2",  // line 12
          "CELL_TYPES 2",
          "9",
          "3"};  // line 15
}

std::string join(const std::vector<std::string>& lines) {
  std::string text;
  for (const std::string& l : lines) text += l + "\n";
  return text;
}

std::string with_line(int line, const std::string& replacement) {
  auto lines = base_lines();
  lines[std::size_t(line - 1)] = replacement;
  return join(lines);
}

// Every vertex position type a double can take, and random bit patterns.
CellComplex awkward_complex() {
  CellComplex c;
  c.positions = {{0.1, 1.0 / 3.0, -0.0},
                 {5e-324, 1e308, -2.5},
                 {std::nextafter(1.0, 2.0), -1e-300, 123456789.123456789},
                 {std::numbers::pi, std::numbers::e, 1e22}};
  std::mt19937_64 random(7);
  while (c.positions.size() < 12) {
    glm::dvec3 p;
    for (int k = 0; k < 3; ++k) {
      do p[k] = std::bit_cast<double>(random());
      while (!std::isfinite(p[k]));
    }
    c.positions.push_back(p);
  }
  c.add_cell({3});
  c.add_cell({0, 1});
  c.add_cell({4, 5, 7, 6});
  c.add_cell({11});
  c.add_cell({0, 1, 2, 3, 8, 9, 10, 11});
  c.add_cell({6, 2});
  return c;
}

IoError parse_error(const std::string& text) {
  try {
    parse_vtk(text, "bad.vtk");
  } catch (const IoError& e) {
    return e;
  }
  FAIL("no IoError");
  return IoError("");
}

}  // namespace

TEST_CASE("vtk: the vertex order of hexahedra and quads is mapped to tensor order on read") {
  const CellComplex c = parse_vtk(unit_cube_vtk, "cube.vtk");
  REQUIRE(c.num_cells() == 4);
  CHECK(c.dimension(0) == 3);
  CHECK(c.dimension(1) == 2);
  CHECK(c.dimension(2) == 3);
  CHECK(c.dimension(3) == 2);
  for (std::size_t i = 0; i < 4; ++i) {
    const auto cell = c.cell(i);
    for (std::uint32_t k = 0; k < cell.size(); ++k) CHECK(c.positions[cell[k]] == tensor_corner(k));
  }
}

TEST_CASE("vtk: written hexahedra and quads are in VTK order again") {
  CellComplex c;
  for (std::uint32_t k = 0; k < 8; ++k) c.positions.push_back(tensor_corner(k));
  c.add_cell({0, 1, 2, 3, 4, 5, 6, 7});
  c.add_cell({0, 1, 2, 3});
  std::ostringstream out;
  write_vtk(out, c, false);
  const std::string text = out.str();
  // The hexahedron's VTK points must run around the bottom (0,0,0) (1,0,0) (1,1,0) (0,1,0), then the top:
  // tensor vertices 0 1 3 2 4 5 7 6; the quad's cycle is 0 1 3 2.
  CHECK(text.find("\n8 0 1 3 2 4 5 7 6\n4 0 1 3 2\n") != std::string::npos);
  CHECK(text.find("CELL_TYPES 2\n12\n9\n") != std::string::npos);
  CHECK(text.starts_with("# vtk DataFile Version 3.0\n"));
}

TEST_CASE("vtk: ASCII and binary round trips keep every cell and every position bit") {
  const CellComplex c = awkward_complex();
  test::ScratchDir dir;
  for (bool binary : {false, true}) {
    const auto path = dir / (binary ? "b.vtk" : "a.vtk");
    write_vtk(c, path, binary);
    test::check_identical(read_vtk(path), c);
    // Through the entry points too.
    write_cell_complex(c, dir / "c.vtk", {.binary_vtk = binary});
    test::check_identical(read_cell_complex(dir / "c.vtk"), c);
    CHECK((test::read_text(dir / "c.vtk").find("BINARY\n") != std::string::npos) == binary);
  }
  CHECK(dir.entries().size() == 3);  // no temporary files left
}

TEST_CASE("vtk: binary data is big-endian") {
  CellComplex c;
  c.positions = {{1.0, -2.0, 0.5}, {0, 0, 0}};
  c.add_cell({0, 1});
  std::ostringstream out;
  write_vtk(out, c, true);
  const std::string data = out.str();
  const std::size_t at = data.find("POINTS 2 double\n");
  REQUIRE(at != std::string::npos);
  // 1.0 is 0x3FF0000000000000: most significant byte first.
  const std::string one = data.substr(at + 16, 8);
  CHECK(one == std::string("\x3F\xF0\0\0\0\0\0\0", 8));
  // The cell list: count 2, then 0 and 1 as 32-bit big-endian integers.
  const std::size_t cells = data.find("CELLS 1 3\n");
  REQUIRE(cells != std::string::npos);
  CHECK(data.substr(cells + 10, 12) == std::string("\0\0\0\x02\0\0\0\0\0\0\0\x01", 12));
}

TEST_CASE("vtk: poly vertices and poly lines are split; attributes after the cells are ignored") {
  const std::string text =
      "# vtk DataFile Version 2.0\nt\nASCII\nDATASET UNSTRUCTURED_GRID\nPOINTS 4 float\n"
      "0 0 0 1 0 0 2 0 0 3 0 0\nCELLS 2 9\n3 0 1 2\n4 0 1 2 3\nCELL_TYPES 2\n2\n4\n"
      "POINT_DATA 4\nSCALARS s float 1\nLOOKUP_TABLE default\n0 1 2 3\n";
  const CellComplex c = parse_vtk(text, "poly.vtk");
  REQUIRE(c.num_cells() == 6);
  for (std::size_t i = 0; i < 3; ++i) {
    CHECK(c.dimension(i) == 0);
    CHECK(c.cell(i)[0] == i);
  }
  for (std::uint32_t i = 0; i < 3; ++i) {
    CHECK(c.dimension(3 + i) == 1);
    CHECK(c.cell(3 + i)[0] == i);
    CHECK(c.cell(3 + i)[1] == i + 1);
  }
  CHECK(c.positions[3] == glm::dvec3(3, 0, 0));
}

TEST_CASE("vtk: version 5 files with OFFSETS and CONNECTIVITY, and METADATA blocks") {
  const std::string text =
      "# vtk DataFile Version 5.1\nt\nASCII\nDATASET UNSTRUCTURED_GRID\nPOINTS 4 float\n"
      "0 0 0 1 0 0 1 1 0 0 1 0\nMETADATA\nINFORMATION 1\nNAME SOME_KEY LOCATION vtkDataArray\nDATA 1 2\n\n"
      "CELLS 3 6\nOFFSETS vtktypeint64\n0 4 6\nCONNECTIVITY vtktypeint64\n"
      "0 1 2 3 0 2\nCELL_TYPES 2\n9\n3\n";
  const CellComplex c = parse_vtk(text, "v5.vtk");
  REQUIRE(c.num_cells() == 2);
  CHECK(std::vector<std::uint32_t>(c.cell(0).begin(), c.cell(0).end()) ==
        std::vector<std::uint32_t>{0, 1, 3, 2});
  CHECK(std::vector<std::uint32_t>(c.cell(1).begin(), c.cell(1).end()) == std::vector<std::uint32_t>{0, 2});
}

TEST_CASE("vtk: every bad input is an IoError naming the file and line") {
  struct Case {
    const char* what;
    std::string text;
    std::size_t line;
    const char* message;
  };
  auto truncated = base_lines();
  truncated.resize(8);  // POINTS 4, but only three points
  auto no_types = base_lines();
  no_types.resize(12);
  // The base file with one line changed, then whole files.
  const std::vector<Case> cases = {
      {"unsupported cell type", with_line(15, "5"), 15, "unsupported type 5 (TRIANGLE)"},
      {"wrong vertex count", with_line(15, "1"), 12, "VERTEX has 2 points; it needs 1"},
      {"index out of range", with_line(12, "2 0 4"), 12, "uses point 4 but there are 4 points"},
      {"negative index", with_line(12, "2 0 -1"), 12, "uses point -1"},
      {"repeated vertex", with_line(11, "4 0 1 1 3"), 11, "uses point 1 twice"},
      {"NaN", with_line(7, "nan 0 0"), 7, "point 1 has a non-finite coordinate"},
      {"infinity", with_line(8, "1 inf 0"), 8, "point 2 has a non-finite coordinate"},
      {"bad number", with_line(6, "0 x 0"), 6, "bad coordinate of point 0 'x'"},
      {"bad header", with_line(1, "# vtk Data"), 1, "bad header"},
      {"bad encoding", with_line(3, "TEXT"), 3, "expected ASCII or BINARY"},
      {"other dataset", with_line(4, "DATASET POLYDATA"), 4, "unsupported dataset 'POLYDATA'"},
      {"type count", with_line(13, "CELL_TYPES 3"), 13, "CELL_TYPES has 3 entries for 2 cells"},
      {"cells size", with_line(10, "CELLS 2 9"), 0, "CELLS size 9 but the lists hold 8"},
      {"negative count", with_line(10, "CELLS -2 8"), 10, "CELLS count is negative"},
      {"huge count", with_line(5, "POINTS 99999999 double"), 5,
       "POINTS count is 99999999 but the file is too short"},
      {"truncated points", join(truncated), 0, "truncated file"},
      {"truncated cells", join(no_types), 0, "CELLS without CELL_TYPES"},
      {"empty file", "", 0, "truncated file"},
  };
  for (const Case& c : cases) {
    INFO(c.what);
    const IoError e = parse_error(c.text);
    CHECK(e.file() == "bad.vtk");
    CHECK(std::string(e.what()).find(c.message) != std::string::npos);
    if (c.line != 0) CHECK(e.line() == c.line);
  }
  {
    auto lines = base_lines();
    lines[9] = "CELLS 2 7";
    lines[10] = "3 0 1 2";  // a QUAD with 3 points
    const IoError e = parse_error(join(lines));
    CHECK(e.line() == 11);
    CHECK(std::string(e.what()).find("QUAD has 3 points; it needs 4") != std::string::npos);
  }
  {
    auto lines = base_lines();
    lines[9] = "CELLS 2 7";
    lines[11] = "1 0";  // a POLY_LINE of one point
    lines[14] = "4";
    const IoError e = parse_error(join(lines));
    CHECK(e.line() == 12);
    CHECK(std::string(e.what()).find("POLY_LINE has 1 points; it needs at least 2") != std::string::npos);
  }
}

TEST_CASE("vtk: bad binary data is an IoError naming the point") {
  CellComplex c;
  c.positions = {{1, 2, 3}, {4, 5, 6}};
  c.add_cell({0, 1});
  std::ostringstream out;
  write_vtk(out, c, true);
  std::string data = out.str();
  // A NaN in the y of point 1.
  std::string nan = data;
  const std::size_t at = nan.find("double\n") + 7 + 4 * 8;
  const double q = std::numeric_limits<double>::quiet_NaN();
  unsigned char bytes[8];
  std::memcpy(bytes, &q, 8);
  if constexpr (std::endian::native == std::endian::little) std::reverse(bytes, bytes + 8);
  nan.replace(at, 8, reinterpret_cast<const char*>(bytes), 8);
  CHECK_THROWS_WITH_AS(parse_vtk(nan, "n.vtk"), doctest::Contains("point 1 has a non-finite coordinate"),
                       IoError);
  // Cut inside the cell list.
  const std::string cut = data.substr(0, data.find("CELLS 1 3\n") + 10 + 5);
  CHECK_THROWS_WITH_AS(parse_vtk(cut, "c.vtk"), doctest::Contains("truncated file"), IoError);
  // A cell list whose count runs past the CELLS size.
  std::string long_count = data;
  long_count[long_count.find("CELLS 1 3\n") + 10 + 3] = 5;
  CHECK_THROWS_WITH_AS(parse_vtk(long_count, "l.vtk"), doctest::Contains("does not fit the CELLS count"),
                       IoError);
  // Cut inside the points.
  CHECK_THROWS_WITH_AS(parse_vtk(data.substr(0, at), "p.vtk"), doctest::Contains("truncated file"), IoError);
}

TEST_CASE("vtk: a failed read or write leaves no output file") {
  test::ScratchDir inputs, outputs;
  const std::vector<std::string> bad = {with_line(15, "5"), with_line(12, "2 0 4"),
                                        with_line(11, "4 0 1 1 3"), with_line(7, "nan 0 0"),
                                        with_line(1, "# vtk")};
  for (std::size_t i = 0; i < bad.size(); ++i) {
    const auto in = inputs / ("bad" + std::to_string(i) + ".vtk");
    test::write_text(in, bad[i]);
    const auto out = outputs / "out.vtk";
    CHECK_THROWS_AS(write_cell_complex(read_cell_complex(in), out), IoError);
    CHECK(outputs.entries().empty());
  }
  // Invalid complexes are refused before any file is touched, an existing file is left as it was.
  CellComplex c = awkward_complex();
  c.indices[3] = 99;  // out of range
  CHECK_THROWS_AS(write_cell_complex(c, outputs / "x.vtk"), InvalidArgument);
  CHECK_THROWS_AS(write_vtk(c, outputs / "y.vtk", true), InvalidArgument);
  c = awkward_complex();
  c.indices[4] = c.indices[3];  // a repeated vertex in the quad
  CHECK_THROWS_AS(write_cell_complex(c, outputs / "x.vtk"), InvalidArgument);
  CHECK(outputs.entries().empty());
  test::write_text(outputs / "keep.vtk", "old");
  CHECK_THROWS_AS(write_cell_complex(c, outputs / "keep.vtk"), InvalidArgument);
  CHECK(test::read_text(outputs / "keep.vtk") == "old");
  CHECK_THROWS_AS(read_cell_complex(inputs / "missing.vtk"), IoError);
  CHECK_THROWS_AS(write_cell_complex(awkward_complex(), outputs / "x.stl"), IoError);
  CHECK(outputs.entries().size() == 1);
}

TEST_CASE("vtk: binary version 5 files with float points and 64-bit offsets") {
  std::string data = "# vtk DataFile Version 5.1\nt\nBINARY\nDATASET UNSTRUCTURED_GRID\nPOINTS 2 float\n";
  auto put = [&](auto value) {
    unsigned char bytes[sizeof(value)];
    std::memcpy(bytes, &value, sizeof(value));
    if constexpr (std::endian::native == std::endian::little) std::reverse(bytes, bytes + sizeof(value));
    data.append(reinterpret_cast<const char*>(bytes), sizeof(value));
  };
  for (float x : {0.5f, -1.25f, 3.0f, 0.1f, 2.0f, -8.0f}) put(x);
  data += "\nCELLS 3 3\nOFFSETS vtktypeint64\n";
  for (std::int64_t x : {0, 2, 3}) put(x);
  data += "\nCONNECTIVITY vtktypeint64\n";
  for (std::int64_t x : {1, 0, 1}) put(x);
  data += "\nCELL_TYPES 2\n";
  for (std::int32_t x : {3, 1}) put(x);
  data += "\n";
  const CellComplex c = parse_vtk(data, "b5.vtk");
  REQUIRE(c.positions.size() == 2);
  CHECK(c.positions[0] == glm::dvec3(0.5, -1.25, 3.0));
  CHECK(c.positions[1] == glm::dvec3(double(0.1f), 2.0, -8.0));  // the float's value, exactly
  REQUIRE(c.num_cells() == 2);
  CHECK(c.cell(0)[0] == 1);
  CHECK(c.cell(0)[1] == 0);
  CHECK(c.cell(1)[0] == 1);
}
