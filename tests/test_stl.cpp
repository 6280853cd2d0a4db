// STL: binary and text writing of the same triangles (n - 2 per face), reading back by welding identical
// positions (to a mesh equal in counts, positions and triangles for a triangle mesh), and the refusals of the
// reader with their line or byte, and of the writer with no file left.

#include <doctest/doctest.h>

#include <cstdint>
#include <cstring>
#include <glm/geometric.hpp>
#include <sstream>
#include <string>
#include <vector>

#include <dlfl/build_mesh.h>
#include <dlfl/io/mesh_io.h>
#include <dlfl/io/stl.h>
#include "test_helpers.h"
#include "tool_runner.h"
#include "triangle_meshes.h"

using namespace dlfl;
using namespace dlfl::test;

namespace {

std::string stl_of(const Mesh& m, bool binary) {
  std::ostringstream out;
  write_stl(out, m, binary);
  return out.str();
}

ParsedPolygons parsed(const std::string& data) {
  std::istringstream in(data);
  return parse_stl(in, "t.stl");
}

glm::dvec3 as_float(const glm::dvec3& p) { return glm::dvec3(glm::vec3(p)); }

// The IoError that parsing `data` throws (REQUIREd), for its message and line.
IoError refusal(const std::string& data) {
  try {
    parsed(data);
  } catch (const IoError& e) {
    return e;
  }
  FAIL("no IoError");
  return IoError("");
}

bool mentions(const IoError& e, const std::string& text) {
  CAPTURE(e.what());
  return std::string(e.what()).find(text) != std::string::npos;
}

std::string facet(const std::string& a, const std::string& b, const std::string& c) {
  return "facet normal 0 0 1\n outer loop\n  vertex " + a + "\n  vertex " + b + "\n  vertex " + c +
         "\n endloop\nendfacet\n";
}

// A binary STL of the given triangles (9 floats each), written here byte by byte.
std::string binary_stl(const std::vector<std::array<float, 9>>& triangles, const std::string& header = "") {
  std::string s(80, '\0');
  std::memcpy(s.data(), header.data(), std::min<std::size_t>(header.size(), 80));
  auto u32 = [&](std::uint32_t v) {
    for (int i = 0; i < 4; ++i) s.push_back(char((v >> (8 * i)) & 0xFF));
  };
  u32(std::uint32_t(triangles.size()));
  for (const auto& t : triangles) {
    for (int i = 0; i < 3; ++i) u32(0);  // the normal, which readers need not trust
    for (float x : t) {
      std::uint32_t bits;
      std::memcpy(&bits, &x, 4);
      u32(bits);
    }
    s.append(2, '\0');
  }
  return s;
}

}  // namespace

TEST_CASE("stl: binary and text hold the same triangles, n - 2 per face") {
  for (const PolygonSoup& soup : {cube_soup(), dodecahedron_soup(), icosahedron_soup(), grid_soup(3, 2)}) {
    const Mesh m = build_mesh(soup);
    std::size_t triangles = 0;
    for (std::size_t f = 0; f < soup.num_faces(); ++f) triangles += soup.face(f).size() - 2;
    const std::string binary = stl_of(m, true), text = stl_of(m, false);
    CHECK(binary.size() == 84 + 50 * triangles);
    CHECK(binary.substr(0, 5) != "solid");  // else readers may take it for text
    std::uint32_t count;
    std::memcpy(&count, binary.data() + 80, 4);
    CHECK(count == triangles);
    CHECK(text.starts_with("solid "));
    const ParsedPolygons from_binary = parsed(binary), from_text = parsed(text);
    CHECK(from_binary.soup.num_faces() == triangles);
    CHECK(from_binary.soup.positions == from_text.soup.positions);
    CHECK(from_binary.soup.indices == from_text.soup.indices);
    CHECK(from_binary.soup.offsets == from_text.soup.offsets);
    // Welded: as many vertices as the mesh has, each at a position of the mesh rounded to float.
    CHECK(from_binary.soup.positions.size() == soup.positions.size());
  }
}

TEST_CASE("stl: a triangle mesh reads back with its counts, its positions and its triangles") {
  for (const PolygonSoup& soup : closed_triangle_soups()) {
    const Mesh m = build_mesh(soup);
    for (bool binary : {true, false}) {
      CAPTURE(binary);
      const ParsedPolygons back = parsed(stl_of(m, binary));
      const Mesh again = build_mesh(back, "t.stl");
      CHECK(again.num_vertices() == m.num_vertices());
      CHECK(again.num_edges() == m.num_edges());
      CHECK(again.num_faces() == m.num_faces());
      // Triangle by triangle, in face order, the same corners from the first one, rounded to float.
      REQUIRE(back.soup.num_faces() == soup.num_faces());
      for (std::size_t f = 0; f < soup.num_faces(); ++f) {
        for (int k = 0; k < 3; ++k) {
          CHECK(back.soup.positions[back.soup.face(f)[k]] == as_float(soup.positions[soup.face(f)[k]]));
        }
      }
    }
  }
}

TEST_CASE("stl: an open triangle mesh gets its hole back; facet normals are the faces' normals") {
  const Mesh m = build_mesh(triangulated(grid_soup(2, 2)));
  const Mesh again = read_mesh(scratch_file("open.stl", stl_of(m, true)));
  CHECK(again.num_hole_faces() == 1);
  CHECK(again.num_faces() == m.num_faces());
  const std::string binary = stl_of(m, true);
  for (std::size_t t = 0; t < 8; ++t) {
    float n[3];
    std::memcpy(n, binary.data() + 84 + 50 * t, 12);
    CHECK(glm::dvec3(n[0], n[1], n[2]) == glm::dvec3(0, 0, 1));  // the grid lies in z = 0, facing +z
  }
}

TEST_CASE("stl: the reader takes what other writers make") {
  SUBCASE("a binary file whose header starts with 'solid' (its size decides)") {
    const std::string data = binary_stl({{0, 0, 0, 1, 0, 0, 0, 1, 0}}, "solid made by some CAD program");
    const ParsedPolygons p = parsed(data);
    CHECK(p.soup.num_faces() == 1);
    CHECK(p.soup.positions.at(1) == glm::dvec3(1, 0, 0));
  }
  SUBCASE("text: words across lines, several solids, -0 welded with 0, CRLF line ends") {
    const std::string data =
        "solid a\r\n" + facet("0 0 0", "1 0 0", "0 1 0") + "endsolid a\r\nsolid b\n" +
        "facet normal 0 0 -1 outer loop vertex -0 0 0 vertex 0 1 0\nvertex 1e0 0 0 endloop\n"
        "endfacet\nendsolid\n";
    const ParsedPolygons p = parsed(data);
    REQUIRE(p.soup.num_faces() == 2);
    CHECK(p.soup.positions.size() == 3);
    CHECK(p.soup.face(1)[0] == 0);
    CHECK(p.soup.face(1)[2] == 1);
  }
}

TEST_CASE("stl: malformed files are refused with their line or byte") {
  const std::string one = facet("0 0 0", "1 0 0", "0 1 0");
  SUBCASE("neither text nor binary") {
    CHECK(mentions(refusal("hello"), "shorter than the 84-byte header"));
    CHECK(mentions(refusal(std::string(100, 'x')), "do not match the"));
  }
  SUBCASE("binary: truncated, or bytes after the last triangle") {
    const std::string data = binary_stl({{0, 0, 0, 1, 0, 0, 0, 1, 0}, {0, 0, 0, 0, 1, 0, 0, 0, 1}});
    CHECK(mentions(refusal(data.substr(0, 84 + 50 + 20)), "ends in triangle 2"));
    CHECK(mentions(refusal(data + "xy"), "from byte 184"));
  }
  SUBCASE("binary: a coordinate that is not finite, named with its triangle and byte") {
    const float inf = std::numeric_limits<float>::infinity();
    const IoError e = refusal(binary_stl({{0, 0, 0, 1, 0, 0, 0, 1, 0}, {0, 0, 0, 0, inf, 0, 0, 0, 1}}));
    CHECK(mentions(e, "triangle 2 (byte 134)"));
    CHECK(mentions(e, "coordinate 2 of corner 2"));
  }
  SUBCASE("binary: two corners at the same position") {
    CHECK(mentions(refusal(binary_stl({{0, 0, 0, 1, 0, 0, 0, 1, 0}, {0, 0, 0, 0, 1, 0, 0, 1, 0}})),
                   "triangle 2 (byte 134) has two corners at the same position"));
  }
  SUBCASE("text: grammar, numbers and triangles, at their lines") {
    const IoError grammar = refusal("solid x\n" + one + "facet normal 0 0 1\n outer lop\n");
    CHECK(grammar.line() == 10);
    CHECK(mentions(grammar, "expected 'loop', found 'lop'"));
    const IoError number = refusal("solid x\n" + facet("0 0 0", "1 nan 0", "0 1 0") + "endsolid x\n");
    CHECK(number.line() == 5);
    CHECK(mentions(number, "not finite"));
    const IoError four = refusal(
        "solid x\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\n"
        "vertex 0 1 0\nvertex 1 1 0\nendloop\nendfacet\nendsolid\n");
    CHECK(four.line() == 7);
    CHECK(mentions(four, "exactly three vertices"));
    const IoError flat = refusal("solid x\n" + one + facet("0 0 0", "0 0 0", "0 1 0") + "endsolid x\n");
    CHECK(flat.line() == 9);
    CHECK(mentions(flat, "triangle 2 has two corners at the same position"));
    CHECK(mentions(refusal("solid x\n" + one), "ends before 'endsolid'"));
    CHECK(mentions(refusal("solid x\n" + one + "endsolid x\nfacet"), "expected 'solid' or the end"));
  }
  SUBCASE("text that holds binary data: refused, with what it would be as binary") {
    const IoError e = refusal("solid x\n" + one + std::string("\0\0\0", 3) + std::string(60, ' '));
    CHECK(e.line() == 9);
    CHECK(mentions(e, "binary data at line 9"));
    CHECK(mentions(e, "as binary STL"));
  }
  SUBCASE("a file whose triangles do not make a surface: the mesh builder's refusal, at the line") {
    // Three triangles on one edge.
    const std::string data = "solid x\n" + one + facet("1 0 0", "0 0 0", "0 0 1") +
                             facet("0 0 0", "1 0 0", "0 0 -1") + "endsolid\n";
    const auto path = scratch_file("fan.stl", data);
    try {
      read_mesh(path);
      FAIL("read");
    } catch (const IoError& e) {
      CHECK(e.line() == 16);  // the third facet, which uses the edge in the first one's direction again
    }
  }
  SUBCASE("no triangle: no vertices") {
    CHECK(error_message<IoError>([] {
            read_mesh(scratch_file("empty.stl", "solid x\nendsolid x\n"));
          }).find("no vertices") != std::string::npos);
  }
}

TEST_CASE("stl: the writer refuses what STL cannot hold, leaving no file; 2-gons are left out") {
  ScratchDir dir;
  write_text(dir / "old.stl", "old");
  Mesh points;
  points.create_vertex({0, 0, 0});
  CHECK_THROWS_AS(write_mesh(points, dir / "new.stl"), IoError);
  CHECK_THROWS_AS(write_mesh(points, dir / "old.stl", {.binary = false}), IoError);
  Mesh far = cube();
  far.set_position(VertexId(0), {-1e300, 0, 0});
  CHECK_THROWS_AS(write_mesh(far, dir / "new.stl"), IoError);
  CHECK(dir.entries() == std::vector<std::string>{"old.stl"});
  CHECK(read_text(dir / "old.stl") == "old");

  Mesh m = tetrahedron();
  const CornerId c = m.first_corner(FaceId(0));
  m.insert_edge(c, m.next(c));  // a 2-gon: no area, no triangle
  REQUIRE(m.num_faces() == 5);
  CHECK(stl_of(m, true).size() == 84 + 50 * 4);
}

#ifdef DLFL_TOOL
TEST_CASE("stl: dlfl convert and edit choose it by extension, --ascii for text") {
  ScratchDir dir;
  const std::string binary = (dir / "cube.stl").string(), text = (dir / "cube_text.stl").string();
  REQUIRE(run("convert " + example("cube.obj") + " '" + binary + "'").exit_code == 0);
  REQUIRE(run("convert " + example("cube.obj") + " '" + text + "' --ascii").exit_code == 0);
  CHECK(read_text(binary).size() == 84 + 50 * 12);
  CHECK(read_text(text).starts_with("solid dlfl\n"));
  const std::string back = (dir / "back.obj").string();
  REQUIRE(run("convert '" + text + "' '" + back + "'").exit_code == 0);
  const Mesh m = read_mesh(back);
  CHECK(m.num_vertices() == 8);
  CHECK(m.num_faces() == 12);
  const std::string edited = (dir / "edited.stl").string();
  const Run r = run("edit '" + binary + "' --op 'triangulate' -o '" + edited + "' --ascii");
  CHECK(r.exit_code == 0);
  CHECK(read_text(edited).starts_with("solid dlfl\n"));
}
#endif
