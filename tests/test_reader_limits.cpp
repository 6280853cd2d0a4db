// Readers against headers that claim more than their file holds: an element, point or cell count of billions
// in a file of a few hundred bytes must fail at once, naming the count, before anything is allocated for it
// or read (the fuzz harnesses run with a 2 GB limit and would report any such allocation, docs/fuzzing.md).

#include <doctest/doctest.h>

#include <chrono>
#include <cstdint>
#include <cstring>
#include <sstream>
#include <string>

#include <dlfl/cells/vtk.h>
#include <dlfl/errors.h>
#include <dlfl/io/off.h>
#include <dlfl/io/ply.h>

using namespace dlfl;

namespace {

ParsedPolygons read_ply(const std::string& text) {
  std::istringstream in(text);
  return parse_ply(in, "limits.ply");
}

std::string ply_header(const char* format, const char* vertices, const char* faces) {
  return std::string("ply\nformat ") + format + " 1.0\nelement vertex " + vertices +
         "\nproperty float x\nproperty float y\nproperty float z\nelement face " + faces +
         "\nproperty list uchar int vertex_indices\nend_header\n";
}

// A few complete little-endian float vertices, so that the data are not empty.
std::string binary_vertices(int n) {
  std::string data;
  for (int i = 0; i < 3 * n; ++i) {
    const float x = 0.5f * float(i);
    char bytes[4];
    std::memcpy(bytes, &x, 4);  // the test hosts are little-endian, as PLY binary_little_endian is
    data.append(bytes, 4);
  }
  return data;
}

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

TEST_CASE("reader limits: a PLY vertex or face count beyond the file fails at once, naming the element") {
  struct Case {
    const char* what;
    std::string text;
    const char* element;
  };
  const Case cases[] = {
      {"ascii vertices", ply_header("ascii", "4000000000", "1") + "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n",
       "'vertex'"},
      {"ascii faces", ply_header("ascii", "3", "4000000000") + "0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n", "'face'"},
      {"binary vertices", ply_header("binary_little_endian", "4000000000", "0") + binary_vertices(4),
       "'vertex'"},
      {"binary faces", ply_header("binary_little_endian", "3", "4000000000") + binary_vertices(3), "'face'"},
  };
  for (const Case& c : cases) {
    CAPTURE(c.what);
    CHECK(c.text.size() < 300);
    CHECK_THROWS_WITH_AS(read_ply(c.text), doctest::Contains(c.element), IoError);
    CHECK_THROWS_WITH_AS(read_ply(c.text), doctest::Contains("far more than the"), IoError);
    try {
      read_ply(c.text);
    } catch (const IoError& e) {
      CHECK(e.line() >= 3);  // the element's header line
      CHECK(e.line() <= 7);
    }
  }
  // A file that holds its elements reads; one merely cut short reads up to its end, where the error names the
  // element (test_io.cpp).
  const std::string fits = ply_header("binary_little_endian", "4", "0") + binary_vertices(4);
  CHECK(read_ply(fits).soup.positions.size() == 4);
  const std::string cut = ply_header("binary_little_endian", "8", "0") + binary_vertices(4);
  CHECK_THROWS_WITH_AS(read_ply(cut), doctest::Contains("vertex 4: the file ends early"), IoError);
}

TEST_CASE("reader limits: a PLY element without properties costs nothing, whatever its count") {
  // Nothing is read for such an element; walking 4e9 of them one by one took seconds.
  for (const char* format : {"ascii", "binary_little_endian"}) {
    CAPTURE(format);
    std::string text = std::string("ply\nformat ") + format +
                       " 1.0\nelement junk 4000000000\nelement vertex 1\nproperty float x\nproperty float y\n"
                       "property float z\nend_header\n";
    text += std::string(format) == "ascii" ? "1 2 3\n" : binary_vertices(1);
    const auto start = std::chrono::steady_clock::now();
    const ParsedPolygons parsed = read_ply(text);
    CHECK(seconds_since(start) < 2.0);
    REQUIRE(parsed.soup.positions.size() == 1);
  }
}

TEST_CASE("reader limits: VTK POINTS, CELLS and CELL_TYPES counts beyond the file fail at once") {
  const std::string head = "# vtk DataFile Version 3.0\nt\n";
  const std::string points = "POINTS 3 float\n0 0 0 1 0 0 0 1 0\n";
  struct Case {
    const char* what;
    std::string text;
    const char* message;
  };
  const Case cases[] = {
      {"ascii POINTS", head + "ASCII\nDATASET UNSTRUCTURED_GRID\nPOINTS 4000000000 float\n0 0 0\n",
       "POINTS count is 4000000000"},
      {"binary POINTS",
       head + "BINARY\nDATASET UNSTRUCTURED_GRID\nPOINTS 4000000000 double\n" + std::string(24, '\0'),
       "POINTS count is 4000000000"},
      {"ascii CELLS count",
       head + "ASCII\nDATASET UNSTRUCTURED_GRID\n" + points + "CELLS 4000000000 8\n2 0 1\n",
       "CELLS count is 4000000000"},
      {"ascii CELLS size",
       head + "ASCII\nDATASET UNSTRUCTURED_GRID\n" + points + "CELLS 1 4000000000\n2 0 1\n",
       "CELLS size is 4000000000"},
      {"binary CELLS",
       head + "BINARY\nDATASET UNSTRUCTURED_GRID\nPOINTS 1 float\n" + std::string(12, '\0') +
           "\nCELLS 3000000000 3000000000\n" + std::string(8, '\0'),
       "CELLS count is 3000000000"},
      {"CELL_TYPES",
       head + "ASCII\nDATASET UNSTRUCTURED_GRID\n" + points + "CELLS 1 3\n2 0 1\nCELL_TYPES 4000000000\n3\n",
       "CELL_TYPES count is 4000000000"},
      {"version 5 OFFSETS",
       "# vtk DataFile Version 5.1\nt\nASCII\nDATASET UNSTRUCTURED_GRID\n" + points +
           "CELLS 4000000000 2\nOFFSETS vtktypeint64\n0 2\n",
       "CELLS offset count is 4000000000"},
      {"beyond 32 bits", head + "ASCII\nDATASET UNSTRUCTURED_GRID\nPOINTS 40000000000 float\n0 0 0\n",
       "exceeds the 32-bit limit"},
  };
  for (const Case& c : cases) {
    CAPTURE(c.what);
    CHECK(c.text.size() < 300);
    CHECK_THROWS_WITH_AS(parse_vtk(c.text, "limits.vtk"), doctest::Contains(c.message), IoError);
  }
}

TEST_CASE("reader limits: OFF counts beyond the file fail at the end of the data, having reserved little") {
  // The OFF reader reserves no more than the rest of the file can hold and stops at its end.
  std::istringstream in("OFF\n4000000000 4000000000 0\n0 0 0\n1 0 0\n0 1 0\n");
  const auto start = std::chrono::steady_clock::now();
  CHECK_THROWS_WITH_AS(parse_off(in, "limits.off"),
                       doctest::Contains("file ends after 3 of 4000000000 vertices"), IoError);
  CHECK(seconds_since(start) < 2.0);
}
