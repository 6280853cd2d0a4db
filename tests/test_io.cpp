// Mesh file reading and writing: round trips, format details, every kind of bad input, atomic writes.

#include <doctest/doctest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <optional>
#include <sstream>
#include <string>
#include <type_traits>
#include <vector>

#include <dlfl/build_mesh.h>
#include <dlfl/create_face_manifold.h>
#include <dlfl/errors.h>
#include <dlfl/io/atomic_file.h>
#include <dlfl/io/mesh_io.h>
#include <dlfl/io/obj.h>
#include <dlfl/io/off.h>
#include <dlfl/io/ply.h>
#include <dlfl/mesh.h>
#include "little_endian_bytes.h"
#include "test_helpers.h"

namespace fs = std::filesystem;
using namespace dlfl;
using test::read_text;
using test::ScratchDir;
using test::write_text;

namespace {

// Doubles that a sloppy writer would not read back exactly.
const double third = 1.0 / 3.0;
const double denormal = 5e-324;
const double largest = std::numeric_limits<double>::max();

// A cube, faces counter-clockwise seen from outside, with awkward coordinates (the topology does not care).
PolygonSoup cube_soup() {
  PolygonSoup s;
  s.positions = {{0.1, 1e-300, -0.0},         {third, 123456789.123456789, -1e-310},
                 {-0.1, 2.0 / 3.0, denormal}, {largest, -2.2250738585072014e-308, 0.1 + 0.2},
                 {-0.0, -0.0, 1e300},         {3.141592653589793, 2.718281828459045, -1e-5},
                 {1e22, 1e23, -third},        {-123456789.123456789, 4.35, 9007199254740993.0}};
  s.add_face({0, 2, 3, 1});
  s.add_face({4, 5, 7, 6});
  s.add_face({0, 1, 5, 4});
  s.add_face({2, 6, 7, 3});
  s.add_face({0, 4, 6, 2});
  s.add_face({1, 3, 7, 5});
  return s;
}

// The cube without its face {4, 5, 7, 6}: an open box with one square hole.
PolygonSoup open_box_soup() {
  PolygonSoup cube = cube_soup();
  PolygonSoup s;
  s.positions = cube.positions;
  for (std::size_t f = 0; f < cube.num_faces(); ++f) {
    if (f != 1) s.add_face(cube.face(f));
  }
  return s;
}

// A 3x3 grid of quads on 4x4 vertices, vertex (i, j) = 4j + i, seen from +z.
PolygonSoup grid_soup() {
  PolygonSoup s;
  for (std::uint32_t j = 0; j < 4; ++j) {
    for (std::uint32_t i = 0; i < 4; ++i)
      s.positions.push_back({0.1 * i, j / 3.0, i == j ? -0.0 : 1e-300 * i});
  }
  for (std::uint32_t j = 0; j < 3; ++j) {
    for (std::uint32_t i = 0; i < 3; ++i) {
      const std::uint32_t v = 4 * j + i;
      s.add_face({v, v + 1, v + 5, v + 4});
    }
  }
  return s;
}

std::size_t count_holes(const Mesh& m) {
  std::size_t holes = 0;
  for (FaceId f : m.faces()) holes += m.is_hole(f) ? 1 : 0;
  return holes;
}

// Positions equal bit for bit (so -0.0 differs from 0.0), in vertex handle order.
bool same_bits(const std::vector<glm::dvec3>& a, const std::vector<glm::dvec3>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(glm::dvec3)) == 0;
}

// The polygon formats with their extension, reader and writer (PLY written binary), listed here rather than
// taken from the library's own dispatch (mesh_io.cpp), which these tests check. JSON holds a mesh, not
// polygons.
struct PolygonFormat {
  MeshFormat format;
  const char* extension;
  ParsedPolygons (*parse)(std::istream&, const std::string&);
  void (*write)(std::ostream&, const PolygonSoup&);
};
const PolygonFormat polygon_formats[] = {
    {MeshFormat::obj, "obj", parse_obj, write_obj},
    {MeshFormat::off, "off", parse_off, write_off},
    {MeshFormat::ply, "ply", parse_ply,
     [](std::ostream& out, const PolygonSoup& soup) { write_ply(out, soup, true); }},
};

const PolygonFormat& polygon_format(MeshFormat format) {
  const auto it = std::find_if(std::begin(polygon_formats), std::end(polygon_formats),
                               [&](const PolygonFormat& f) { return f.format == format; });
  REQUIRE(it != std::end(polygon_formats));
  return *it;
}

ParsedPolygons parse(MeshFormat format, const std::string& text, const std::string& name) {
  std::istringstream in(text);
  return polygon_format(format).parse(in, name);
}

// What a parse must give: the polygons, and the line each vertex and each face came from.
struct Expected {
  std::vector<glm::dvec3> positions;
  std::vector<std::uint32_t> offsets, indices;
  std::vector<std::size_t> vertex_lines, face_lines;
};
void check_parsed(const ParsedPolygons& parsed, const Expected& expected) {
  CHECK(parsed.soup.positions == expected.positions);
  CHECK(parsed.soup.offsets == expected.offsets);
  CHECK(parsed.soup.indices == expected.indices);
  CHECK(parsed.vertex_lines == expected.vertex_lines);
  CHECK(parsed.face_lines == expected.face_lines);
}

// Parses and builds `text`, and checks that this fails with an IoError at `line` whose message has
// `fragment`.
void check_error(MeshFormat format, const std::string& text, std::size_t line, const std::string& fragment) {
  const std::string name = std::string("bad.") + polygon_format(format).extension;
  CAPTURE(text);
  std::optional<IoError> error;
  try {
    build_mesh(parse(format, text, name), name);
  } catch (const IoError& e) {
    error = e;
  }
  REQUIRE(error.has_value());
  const std::string message = error->what();
  CAPTURE(message);
  CHECK(error->file() == name);
  CHECK(error->line() == line);
  const std::string location = line == 0 ? name + ": " : name + ":" + std::to_string(line) + ": ";
  CHECK(message.rfind(location, 0) == 0);
  CHECK(message.find(fragment) != std::string::npos);
}

// One bad input for check_error: the text after a head, the line of the error and a fragment of its message.
struct BadInput {
  std::string text;
  std::size_t line;
  const char* fragment;
};

// check_error for every case, each with `head` put before its text.
void check_errors(MeshFormat format, const std::string& head, const std::vector<BadInput>& cases) {
  for (const BadInput& c : cases) check_error(format, head + c.text, c.line, c.fragment);
}

// Little-endian bytes for hand-made binary PLY files, independent of the host's byte order.
struct Bytes {
  std::string data;
  template <class T>
  Bytes& put(T value) {
    put_little_endian(data, value);
    return *this;
  }
};

const std::string tetra_obj =
    "v 0 0 0\n"
    "v 1 0 0\n"
    "v 0 1 0\n"
    "v 0 0 1\n";

}  // namespace

// ---- round trips
// -----------------------------------------------------------------------------------------------

TEST_CASE("io: round trip through every format keeps counts and faces and exact positions") {
  struct Case {
    const char* name;
    PolygonSoup soup;
    std::size_t vertices, edges, faces, holes;
  };
  // Counts by hand: the cube has 12 edges; the open box keeps them and gains one hole face; the grid has
  // 4 rows and 4 columns of 3 edges each, and one hole around its border.
  const Case cases[] = {{"closed cube", cube_soup(), 8, 12, 6, 0},
                        {"open box", open_box_soup(), 8, 12, 6, 1},
                        {"grid", grid_soup(), 16, 24, 10, 1}};
  struct Target {
    const char* file;
    bool binary;
  };
  const Target targets[] = {{"m.obj", true}, {"m.off", true}, {"m.ply", false}, {"m.ply", true}};
  for (const Case& c : cases) {
    const Mesh original = build_mesh(c.soup);
    REQUIRE(original.num_vertices() == c.vertices);
    REQUIRE(original.num_edges() == c.edges);
    REQUIRE(original.num_faces() == c.faces);
    REQUIRE(count_holes(original) == c.holes);
    for (const Target& t : targets) {
      CAPTURE(c.name);
      CAPTURE(t.file);
      CAPTURE(t.binary);
      ScratchDir dir;
      write_mesh(original, dir / t.file, {t.binary});
      CHECK(dir.entries() == std::vector<std::string>{t.file});
      const Mesh back = read_mesh(dir / t.file);
      CHECK(back.num_vertices() == c.vertices);
      CHECK(back.num_edges() == c.edges);
      CHECK(back.num_faces() == c.faces);
      CHECK(count_holes(back) == c.holes);
      const PolygonSoup polygons = to_polygons(back);
      CHECK(same_bits(polygons.positions, c.soup.positions));
      // Hole faces are not written, so the faces read back are exactly the hand-written ones.
      CHECK(polygons.offsets == c.soup.offsets);
      CHECK(polygons.indices == c.soup.indices);
      // The mesh builder is deterministic, so the same polygons give the very same mesh.
      CHECK(back == original);
    }
  }
}

TEST_CASE("io: the awkward doubles survive with the sign of zero") {
  ScratchDir dir;
  const Mesh cube = build_mesh(cube_soup());
  write_mesh(cube, dir / "c.obj");
  const Mesh back = read_mesh(dir / "c.obj");
  CHECK(std::signbit(back.position(VertexId(0)).z));
  CHECK(back.position(VertexId(0)).x == 0.1);
  CHECK(back.position(VertexId(0)).y == 1e-300);
  CHECK(back.position(VertexId(1)).x == third);
  CHECK(back.position(VertexId(1)).y == 123456789.123456789);
  CHECK(back.position(VertexId(2)).z == denormal);
  CHECK(back.position(VertexId(3)).x == largest);
  CHECK(back.position(VertexId(3)).z == 0.1 + 0.2);
  CHECK(back.position(VertexId(3)).z != 0.3);
}

TEST_CASE("io: writers produce the expected text and bytes") {
  PolygonSoup tetra;
  tetra.positions = {{0.1, -0.0, 1e-300}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  tetra.add_face({0, 2, 1});
  tetra.add_face({0, 1, 3});
  tetra.add_face({0, 3, 2});
  tetra.add_face({1, 2, 3});
  ScratchDir dir;
  const Mesh m = build_mesh(tetra);

  SUBCASE("obj: 1-based indices, shortest decimals") {
    write_mesh(m, dir / "t.obj");
    CHECK(read_text(dir / "t.obj") ==
          "v 0.1 -0 1e-300\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n");
  }
  SUBCASE("off") {
    write_mesh(m, dir / "t.off");
    CHECK(read_text(dir / "t.off") ==
          "OFF\n4 4 0\n0.1 -0 1e-300\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n");
  }
  SUBCASE("ply ascii") {
    write_mesh(m, dir / "t.ply", {.binary = false});
    CHECK(read_text(dir / "t.ply") ==
          "ply\nformat ascii 1.0\nelement vertex 4\nproperty double x\nproperty double y\nproperty double z\n"
          "element face 4\nproperty list uchar uint vertex_indices\nend_header\n"
          "0.1 -0 1e-300\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n");
  }
  SUBCASE("ply binary is the default") {
    write_mesh(m, dir / "t.ply");
    Bytes expected;
    expected.data =
        "ply\nformat binary_little_endian 1.0\nelement vertex 4\nproperty double x\nproperty double y\n"
        "property double z\nelement face 4\nproperty list uchar uint vertex_indices\nend_header\n";
    for (const glm::dvec3& p : tetra.positions) expected.put(p.x).put(p.y).put(p.z);
    for (std::size_t f = 0; f < tetra.num_faces(); ++f) {
      expected.put(std::uint8_t{3});
      for (std::uint32_t i : tetra.face(f)) expected.put(i);
    }
    CHECK(read_text(dir / "t.ply") == expected.data);
  }
}

TEST_CASE("io: a face of more than 255 vertices gets a uint count in PLY") {
  // One 300-gon: an open disc whose boundary is a 300-gon hole.
  PolygonSoup disc;
  std::vector<std::uint32_t> face;
  for (std::uint32_t i = 0; i < 300; ++i) {
    disc.positions.push_back({std::cos(i * 0.02), std::sin(i * 0.02), 0.0});
    face.push_back(i);
  }
  disc.add_face(face);
  const Mesh m = build_mesh(disc);
  ScratchDir dir;
  for (bool binary : {true, false}) {
    CAPTURE(binary);
    write_mesh(m, dir / "disc.ply", {binary});
    const std::string content = read_text(dir / "disc.ply");
    CHECK(content.find("property list uint uint vertex_indices\n") != std::string::npos);
    CHECK(content.substr(0, content.find("end_header")).find("uchar") == std::string::npos);
    const Mesh back = read_mesh(dir / "disc.ply");
    CHECK(back.num_faces() == 2);
    CHECK(back.num_edges() == 300);
    const PolygonSoup polygons = to_polygons(back);
    CHECK(polygons.indices == disc.indices);
    CHECK(same_bits(polygons.positions, disc.positions));
  }
}

// ---- format details
// ----------------------------------------------------------------------------------------------

TEST_CASE("io: obj index forms and relative indices and comments and ignored statements") {
  const std::string text =
      "# a square and more\n"              // 1
      "mtllib square.mtl\n"                // 2
      "o square\n"                         // 3
      "v 0 0 0\n"                          // 4
      "v 1 0 0 1.0\n"                      // 5: w component
      "v 1 1 0 0.5 0.25 1\n"               // 6: vertex colour
      "  v\t0 1 0  \r\n"                   // 7: blanks and CRLF
      "vt 0 0\n"                           // 8
      "vn 0 0 1\n"                         // 9
      "g group\n"                          // 10
      "s off\n"                            // 11
      "usemtl red\n"                       // 12
      "\n"                                 // 13
      "f 1/1/1 2/2/1 3/3/1 # a comment\n"  // 14
      "f 1//1 3//1 4//1\n"                 // 15
      "l 1 2\n"                            // 16
      "f -4/1 -2 -1\n"                     // 17: relative to the 4 vertices so far
      "vp 0.5\n"                           // 18
      "v 2 0 0\n"                          // 19
      "v 2 1 0\n"                          // 20
      "f 2 5 6 3\n"                        // 21
      "f -5 -2 -1\n";                      // 22: relative to 6 vertices
  check_parsed(parse(MeshFormat::obj, text, "square.obj"),
               {.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {2, 0, 0}, {2, 1, 0}},
                .offsets = {0, 3, 6, 9, 13, 16},
                .indices = {0, 1, 2, 0, 2, 3, 0, 2, 3, 1, 4, 5, 2, 1, 4, 5},
                .vertex_lines = {4, 5, 6, 7, 19, 20},
                .face_lines = {14, 15, 17, 21, 22}});
}

TEST_CASE("io: obj faces may name vertices defined further down") {
  const ParsedPolygons parsed = parse(MeshFormat::obj, "f 1 2 3\nv 0 0 0\nv 1 0 0\nv 0 1 0\n", "late.obj");
  CHECK(parsed.soup.indices == std::vector<std::uint32_t>{0, 1, 2});
  CHECK(parsed.face_lines == std::vector<std::size_t>{1});
}

TEST_CASE("io: off variants and comments and colours") {
  SUBCASE("comments, blank lines and face colours") {
    const std::string text =
        "OFF\n"                     // 1
        "# four vertices\n"         // 2
        "4 2 0\n"                   // 3
        "\n"                        // 4
        "0 0 0\n"                   // 5
        "1 0 0  # comment\n"        // 6
        "1 1 0\n"                   // 7
        "0 1 0\n"                   // 8
        "3 0 1 2 255 0 0\n"         // 9: a colour after the indices
        "3 0 2 3 0.5 0.5 0.5 1\n";  // 10
    check_parsed(
        parse(MeshFormat::off, text, "s.off"),
        {{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}, {0, 3, 6}, {0, 1, 2, 0, 2, 3}, {5, 6, 7, 8}, {9, 10}});
  }
  SUBCASE("COFF with vertex colours, counts on the header line") {
    const std::string text = "COFF 3 1\n0 0 0 255 0 0 255\n1 0 0 0 255 0 255\n0 1 0 0 0 255 255\n3 2 0 1\n";
    const ParsedPolygons parsed = parse(MeshFormat::off, text, "c.off");
    CHECK(parsed.soup.positions == std::vector<glm::dvec3>{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}});
    CHECK(parsed.soup.indices == std::vector<std::uint32_t>{2, 0, 1});
  }
  SUBCASE("NOFF with normals") {
    const std::string text = "NOFF\n3 1 3\n0 0 0 0 0 1\n1 0 0 0 0 1\n0 1 0 0 0 1\n3 0 1 2\n";
    const ParsedPolygons parsed = parse(MeshFormat::off, text, "n.off");
    CHECK(parsed.soup.positions == std::vector<glm::dvec3>{{0, 0, 0}, {1, 0, 0}, {0, 1, 0}});
    CHECK(parsed.soup.indices == std::vector<std::uint32_t>{0, 1, 2});
  }
}

TEST_CASE("io: ply ascii skips other properties and elements") {
  const std::string text =
      "ply\n"                                   // 1
      "format ascii 1.0\n"                      // 2
      "comment made by hand\n"                  // 3
      "element vertex 4\n"                      // 4
      "property float nx\n"                     // 5
      "property double x\n"                     // 6
      "property float y\n"                      // 7
      "property float z\n"                      // 8
      "property uchar red\n"                    // 9
      "element material 1\n"                    // 10
      "property list uchar float weights\n"     // 11
      "element face 2\n"                        // 12
      "property uchar flags\n"                  // 13
      "property list uchar int vertex_index\n"  // 14
      "property list uchar float texcoord\n"    // 15
      "element edge 1\n"                        // 16
      "property int vertex1\n"                  // 17
      "property int vertex2\n"                  // 18
      "end_header\n"                            // 19
      "0.5 0 0 0 255\n"                         // 20
      "0.5 1 0 0 255\n"                         // 21
      "0.5 1 1 0 255\n"                         // 22
      "0.5 0.1 1 0 255\n"                       // 23
      "3 0.25 0.5 0.75\n"                       // 24
      "7 3 0 1 2 6 0 0 1 0 1 1\n"               // 25
      "7 3 0 2 3 0\n"                           // 26
      "0 1\n";                                  // 27
  check_parsed(parse(MeshFormat::ply, text, "s.ply"),
               {.positions = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0.1, 1, 0}},
                .offsets = {0, 3, 6},
                .indices = {0, 1, 2, 0, 2, 3},
                .vertex_lines = {20, 21, 22, 23},
                .face_lines = {25, 26}});
}

namespace {
// A binary PLY square: vertices with float x y z and a uchar; faces with a flag and a ushort/int index list;
// then an edge element with a list, to be skipped.
Bytes binary_square(std::int32_t last_index = 3, std::uint16_t second_face_size = 3, float y3 = 0.1f) {
  Bytes b;
  b.data =
      "ply\nformat binary_little_endian 1.0\ncomment hand made\nelement vertex 4\nproperty float x\n"
      "property float y\nproperty float z\nproperty uchar red\nelement face 2\nproperty uchar flags\n"
      "property list ushort int vertex_indices\nelement edge 1\nproperty list uchar uint "
      "vertices\nend_header\n";
  b.put(0.0f).put(0.0f).put(0.0f).put(std::uint8_t{255});
  b.put(1.0f).put(0.0f).put(0.0f).put(std::uint8_t{255});
  b.put(1.0f).put(1.0f).put(0.0f).put(std::uint8_t{255});
  b.put(0.0f).put(y3).put(-0.5f).put(std::uint8_t{255});
  b.put(std::uint8_t{7}).put(std::uint16_t{3}).put(std::int32_t{0}).put(std::int32_t{1}).put(std::int32_t{2});
  b.put(std::uint8_t{7}).put(second_face_size).put(std::int32_t{0}).put(std::int32_t{2});
  if (second_face_size > 2) b.put(last_index);
  b.put(std::uint8_t{2}).put(std::uint32_t{0}).put(std::uint32_t{1});
  return b;
}
}  // namespace

TEST_CASE("io: ply binary with float coordinates and extra properties") {
  const ParsedPolygons parsed = parse(MeshFormat::ply, binary_square().data, "b.ply");
  const std::vector<glm::dvec3> positions = {
      {0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, static_cast<double>(0.1f), -0.5}};
  CHECK(parsed.soup.positions == positions);
  CHECK(parsed.soup.offsets == std::vector<std::uint32_t>{0, 3, 6});
  CHECK(parsed.soup.indices == std::vector<std::uint32_t>{0, 1, 2, 0, 2, 3});
  // Binary data have no lines.
  CHECK(parsed.vertex_lines == std::vector<std::size_t>{0, 0, 0, 0});
  CHECK(parsed.face_lines == std::vector<std::size_t>{0, 0});
}

namespace {
// A stream buffer that hands out its text in small pieces and cannot seek, like a pipe.
class PipeBuffer : public std::streambuf {
 public:
  explicit PipeBuffer(std::string text) : text_(std::move(text)) {}

 protected:
  int_type underflow() override {
    if (pos_ == text_.size()) return traits_type::eof();
    const std::size_t n = std::min<std::size_t>(1000, text_.size() - pos_);
    char* p = text_.data() + pos_;
    setg(p, p, p + n);
    pos_ += n;
    return traits_type::to_int_type(*p);
  }

 private:
  std::string text_;
  std::size_t pos_ = 0;
};
}  // namespace

TEST_CASE("io: parsers read large unseekable streams") {
  // 80x80 quads: 6561 vertices, 6400 faces, a few hundred kB, several times the first read chunk.
  PolygonSoup grid;
  for (std::uint32_t j = 0; j <= 80; ++j) {
    for (std::uint32_t i = 0; i <= 80; ++i) grid.positions.push_back({i / 7.0, j / 11.0, (i * j) / 13.0});
  }
  for (std::uint32_t j = 0; j < 80; ++j) {
    for (std::uint32_t i = 0; i < 80; ++i) {
      const std::uint32_t v = 81 * j + i;
      grid.add_face({v, v + 1, v + 82, v + 81});
    }
  }
  for (const PolygonFormat& format : polygon_formats) {
    CAPTURE(format.extension);
    std::ostringstream out;
    format.write(out, grid);
    REQUIRE(out.str().size() > 3 * 65536);
    PipeBuffer pipe(out.str());
    std::istream in(&pipe);
    REQUIRE(in.rdbuf()->pubseekoff(0, std::ios::cur, std::ios::in) == std::streampos(-1));
    const ParsedPolygons parsed = format.parse(in, "pipe");
    CHECK(same_bits(parsed.soup.positions, grid.positions));
    CHECK(parsed.soup.offsets == grid.offsets);
    CHECK(parsed.soup.indices == grid.indices);
  }
}

TEST_CASE("io: format by extension") {
  CHECK(format_for_path("a/b/mesh.obj") == MeshFormat::obj);
  CHECK(format_for_path("MESH.OBJ") == MeshFormat::obj);
  CHECK(format_for_path("x.Off") == MeshFormat::off);
  CHECK(format_for_path("x.y.PLY") == MeshFormat::ply);
  CHECK(format_for_path("x.Stl") == MeshFormat::stl);
  CHECK(format_for_path("x.GLB") == MeshFormat::glb);
  CHECK_THROWS_WITH_AS(format_for_path("mesh.fbx"), doctest::Contains(".fbx"), IoError);
  CHECK_THROWS_WITH_AS(format_for_path("mesh.fbx"), doctest::Contains("mesh.fbx"), IoError);
  CHECK_THROWS_AS(format_for_path("mesh"), IoError);
  CHECK_THROWS_AS(format_for_path("obj"), IoError);

  ScratchDir dir;
  write_text(dir / "cube.fbx", "solid\n");
  CHECK_THROWS_WITH_AS(read_mesh(dir / "cube.fbx"), doctest::Contains(".fbx"), IoError);
  CHECK_THROWS_WITH_AS(write_mesh(build_mesh(cube_soup()), dir / "cube.dae"), doctest::Contains(".dae"),
                       IoError);
  CHECK(dir.entries() == std::vector<std::string>{"cube.fbx"});
}

// ---- bad input
// ------------------------------------------------------------------------------------------------

TEST_CASE("io: missing file") {
  ScratchDir dir;
  const fs::path path = dir / "missing.obj";
  try {
    read_mesh(path);
    FAIL("no exception");
  } catch (const IoError& e) {
    CHECK(std::string(e.what()).find("cannot open") != std::string::npos);
    CHECK(e.file() == path.string());
  }
}

TEST_CASE("io: read_mesh reports the file and line of a topology error") {
  ScratchDir dir;
  const fs::path path = dir / "bowtie.obj";
  // Two triangles sharing only vertex 1: a non-manifold vertex defined on line 2.
  write_text(path, "# bow tie\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv -1 0 0\nv -1 -1 0\nf 1 2 3\nf 1 4 5\n");
  try {
    read_mesh(path);
    FAIL("no exception");
  } catch (const IoError& e) {
    CHECK(e.file() == path.string());
    CHECK(e.line() == 2);
    CHECK(std::string(e.what()).rfind(path.string() + ":2: ", 0) == 0);
    CHECK(std::string(e.what()).find("non-manifold") != std::string::npos);
  }
}

TEST_CASE("io: obj errors carry the line") {
  const auto obj = MeshFormat::obj;
  // Bad faces after a good tetrahedron; the last three are checked by the mesh builder, which reports them at
  // the line of the face.
  check_errors(obj, tetra_obj,
               {
                   {"f 1 2 5\n", 5, "vertex index 5 is out of range"},
                   {"f 1 2 3\n\nf 0 1 2\n", 7, "vertex index 0"},
                   {"f 1 x 3\n", 5, "bad vertex index 'x'"},
                   {"f 1 2\n", 5, "face has 2 vertices"},
                   {"f 1 2 3\nf 1 3 3\n", 6, "twice in a row"},
                   {"f 1 2 3\nf 1 2 4\n", 6, "same direction"},
                   {"v 1 1 1\nf 1 2 3\nf 2 1 4\n# third\nf 1 2 5\n", 9, "same direction"},
               });
  // Two closed tetrahedra touching at the tip (vertex 4, on line 5): no boundary, yet not a manifold.
  const std::string two_cones =
      "v 0 0 0\nv 1 0 0\nv 0 1 0\n# tip\nv 0 0 1\nv 1 1 2\nv 0 1 2\nv 1 0 2\n"
      "f 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n"
      "f 5 6 7\nf 5 4 6\nf 5 7 4\nf 6 4 7\n";
  // Whole files; the first and the last are checked by the mesh builder, which reports them at the line of
  // the vertex.
  check_errors(obj, "",
               {
                   {"# bow tie\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv -1 0 0\nv -1 -1 0\nf 1 2 3\nf 1 4 5\n", 2,
                    "non-manifold"},
                   {"v 0 0 0\nv 1 0 0\nv 0 1 0\nf -4 -2 -1\nv 0 0 1\n", 4, "out of range"},
                   {"v 0 0 0\nv 1 oops 0\n", 2, "bad y coordinate 'oops'"},
                   {"v 0 0 0\nv 1 0\n", 2, "missing z coordinate"},
                   {"v 0 0 0\n# c\nv 1 nan 0\n", 3, "not finite"},
                   {"v 0 0 0\nv inf 0 0\n", 2, "not finite"},
                   {"v 0 0 0\nv 0 0 -1e999\n", 2, "out of range"},
                   {two_cones, 5, "non-manifold"},
               });
}

TEST_CASE("io: off errors carry the line") {
  const auto off = MeshFormat::off;
  // Bad faces after four good vertices.
  check_errors(off, "OFF\n4 1 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n",
               {
                   {"3 0 1 4\n", 7, "vertex index 4 is out of range"},
                   {"3 0 -1 2\n", 7, "vertex index -1 is out of range"},
                   {"2 0 1\n", 7, "face has 2 vertices"},
                   {"3 0 1 1\n", 7, "twice in a row"},
               });
  check_errors(off, "",
               {
                   {"OFF\n4 1 0\n0 0 0\n1 0 0\n0 1 0\n", 5, "3 of 4 vertices"},
                   {"OFF\n4 2 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 1 2\n\n", 8, "1 of 2 faces"},
                   {"OFF\n3 1 0\n0 0 0\n1 nan 0\n0 1 0\n3 0 1 2\n", 4, "not finite"},
                   {"OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 -inf\n3 0 1 2\n", 5, "not finite"},
                   {"OFF\n3 x 0\n", 2, "bad face count 'x'"},
                   {"# no header\n3 1 0\n0 0 0\n", 2, "missing OFF header"},
                   {"OFX\n3 1 0\n", 1, "missing OFF header"},
                   {"4OFF\n3 1 0\n", 1, "unsupported"},
                   {"", 1, "missing OFF header"},
               });
}

TEST_CASE("io: ply ascii errors carry the line") {
  const auto ply = MeshFormat::ply;
  // Bad bodies after a good header of 9 lines.
  check_errors(
      ply,
      "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
      "element face 1\nproperty list uchar int vertex_indices\nend_header\n",
      {
          {"0 0 0\n1 0 0\n0 1 0\n3 0 1 3\n", 13, "vertex index 3 is out of range"},
          {"0 0 0\n1 0 0\n0 1 0\n2 0 1\n", 13, "face has 2 vertices"},
          {"0 0 0\n1 0 0\n0 1 0\n3 0 2 2\n", 13, "twice in a row"},
          {"0 0 0\nnan 0 0\n0 1 0\n3 0 1 2\n", 11, "not finite"},
          {"0 0 0\n1 0 0\n0 1 0\n3 0 1\n", 13, "ends in face 0"},
          {"0 0 0\n1 0 0\n", 11, "ends in vertex 2"},
          {"0 0 0\n1 0 z\n", 11, "bad z coordinate 'z'"},
      });
  // Bad headers.
  check_errors(
      ply, "",
      {
          {"plyx\n", 1, "not a PLY file"},
          {"ply\nformat ascii 1.0\nelement vertex 0\nproperty float x\n", 4, "end_header"},
          {"ply\nformat ascii 2.0\n", 2, "version"},
          {"ply\nformat binary_big_endian 1.0\nelement vertex 0\nend_header\n", 2, "unsupported"},
          {"ply\nformat ascii 1.0\nelement vertex 1\nproperty int8x x\nend_header\n", 4, "int8x"},
          {"ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nproperty float y\nend_header\n", 3,
           "x, y and z"},
      });
}

TEST_CASE("io: ply binary errors name the element") {
  const auto ply = MeshFormat::ply;
  const std::string square = binary_square().data;
  // The body is 4 vertices of 13 bytes, 2 faces of 15 and an edge of 9: cutting 10 bytes cuts into face 1.
  check_error(ply, square.substr(0, square.size() - 10), 0, "face 1: the file ends early");
  check_error(ply, square.substr(0, square.find("end_header\n") + 11 + 20), 0,
              "vertex 1: the file ends early");
  check_error(ply, binary_square(4).data, 0, "face 1: vertex index 4 is out of range");
  check_error(ply, binary_square(-1).data, 0, "face 1: vertex index -1 is out of range");
  check_error(ply, binary_square(3, 2).data, 0, "face 1: face has 2 vertices");
  check_error(ply, binary_square(3, 3, std::numeric_limits<float>::quiet_NaN()).data, 0,
              "vertex 3: coordinate is not finite");
  check_error(ply, binary_square(3, 3, std::numeric_limits<float>::infinity()).data, 0, "vertex 3");
  check_error(ply, binary_square(0).data, 0, "twice in a row");
}

// ---- atomic writes
// ----------------------------------------------------------------------------------------------

TEST_CASE("io: a mesh that cannot be written leaves no file behind") {
  // Two points: a face manifold of two 2-gons, which an indexed polygon file cannot hold.
  Mesh two_gon;
  const glm::dvec3 points[] = {{0, 0, 0}, {1, 0, 0}};
  create_face_manifold(two_gon, points);
  REQUIRE(two_gon.num_faces() == 2);

  ScratchDir dir;
  SUBCASE("no file before") {
    for (const char* name : {"two.obj", "two.off", "two.ply"}) {
      CHECK_THROWS_AS(write_mesh(two_gon, dir / name), TopologyError);
    }
    CHECK(dir.entries().empty());
  }
  SUBCASE("an existing file keeps its content") {
    write_text(dir / "keep.obj", "old content\n");
    CHECK_THROWS_AS(write_mesh(two_gon, dir / "keep.obj"), TopologyError);
    CHECK(read_text(dir / "keep.obj") == "old content\n");
    CHECK(dir.entries() == std::vector<std::string>{"keep.obj"});
  }
}

TEST_CASE("io: writing into a missing folder fails cleanly") {
  ScratchDir dir;
  const fs::path path = dir / "no_such_folder" / "cube.ply";
  try {
    write_mesh(build_mesh(cube_soup()), path);
    FAIL("no exception");
  } catch (const IoError& e) {
    CHECK(e.file() == path.string());
  }
  CHECK(dir.entries().empty());
}

TEST_CASE("io: write_atomically replaces the file only when the writer succeeds") {
  ScratchDir dir;
  const fs::path path = dir / "data.txt";
  write_text(path, "old");

  SUBCASE("success replaces the content") {
    write_atomically(path, [](std::ostream& out) { out << "new content"; });
    CHECK(read_text(path) == "new content");
    write_atomically(
        path, [](std::ostream& out) { out.write("\0\n\r\n", 4); }, true);
    CHECK(read_text(path) == std::string("\0\n\r\n", 4));
  }
  SUBCASE("the writer's exception propagates unchanged") {
    struct Boom {};
    CHECK_THROWS_AS(write_atomically(path,
                                     [](std::ostream& out) {
                                       out << std::string(3 << 20, 'x');  // more than any stream buffer
                                       throw Boom{};
                                     }),
                    Boom);
    CHECK(read_text(path) == "old");
  }
  SUBCASE("a stream error becomes an IoError") {
    CHECK_THROWS_WITH_AS(write_atomically(path,
                                          [](std::ostream& out) {
                                            out << "partial";
                                            out.setstate(std::ios::badbit);
                                          }),
                         doctest::Contains(path.string().c_str()), IoError);
    CHECK(read_text(path) == "old");
  }
  SUBCASE("a directory in the way cannot be replaced") {
    fs::create_directory(dir / "folder");
    CHECK_THROWS_WITH_AS(write_atomically(dir / "folder", [](std::ostream& out) { out << "x"; }),
                         doctest::Contains("folder"), IoError);
    CHECK(fs::is_directory(dir / "folder"));
    CHECK(fs::is_empty(dir / "folder"));
  }
  // No temporary file is left behind, whatever happened.
  std::vector<std::string> expected{"data.txt"};
  if (fs::exists(dir / "folder")) expected.push_back("folder");
  CHECK(dir.entries() == expected);
}
