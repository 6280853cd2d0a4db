// The .glb writer, read back by a small glTF parser written here from the specification (header, chunks,
// accessors, buffer views), independent of the writer: counts from the faces (n - 2 triangles each), the
// bounds from the positions, each triangle on its face, in its plane and facing its way.

#include <doctest/doctest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include <dlfl/build_mesh.h>
#include <dlfl/geometry.h>
#include <dlfl/io/gltf.h>
#include <dlfl/io/mesh_io.h>
#include "test_helpers.h"
#include "test_meshes.h"
#include "tool_runner.h"

using namespace dlfl;
using namespace dlfl::test;
using nlohmann::json;

namespace {

std::uint32_t u32_at(const std::string& bytes, std::size_t at) {
  REQUIRE(at + 4 <= bytes.size());
  const auto b = [&](std::size_t i) { return std::uint32_t(static_cast<unsigned char>(bytes[at + i])); };
  return b(0) | b(1) << 8 | b(2) << 16 | b(3) << 24;
}

float f32_at(const std::string& bytes, std::size_t at) {
  const std::uint32_t bits = u32_at(bytes, at);
  float f;
  std::memcpy(&f, &bits, 4);
  return f;
}

// A .glb file as the specification lays it out: a 12-byte header, a JSON chunk, a BIN chunk.
struct Glb {
  json doc;
  std::string bin;

  // The values of a scalar or vector accessor of 4-byte components, as doubles, after checking its type.
  std::vector<double> values(int accessor, int component_type, const std::string& type) const {
    const json& a = doc.at("accessors").at(accessor);
    CHECK(a.at("componentType") == component_type);
    CHECK(a.at("type") == type);
    const int width = type == "VEC3" ? 3 : 1;
    const std::size_t count = a.at("count");
    const json& view = doc.at("bufferViews").at(int(a.at("bufferView")));
    CHECK(view.at("buffer") == 0);
    const std::size_t offset =
        view.value("byteOffset", std::size_t{0}) + a.value("byteOffset", std::size_t{0});
    CHECK(offset % 4 == 0);
    CHECK(count * width * 4 <= std::size_t(view.at("byteLength")));
    REQUIRE(offset + count * width * 4 <= bin.size());
    std::vector<double> out;
    for (std::size_t i = 0; i < count * width; ++i) {
      const std::size_t at = offset + 4 * i;
      out.push_back(component_type == 5126 ? double(f32_at(bin, at)) : double(u32_at(bin, at)));
    }
    return out;
  }
};

Glb parse_glb(const std::string& bytes) {
  REQUIRE(bytes.size() >= 28);
  CHECK(bytes.substr(0, 4) == "glTF");
  CHECK(u32_at(bytes, 4) == 2);
  CHECK(u32_at(bytes, 8) == bytes.size());
  const std::uint32_t json_length = u32_at(bytes, 12);
  CHECK(json_length % 4 == 0);
  CHECK(bytes.substr(16, 4) == "JSON");
  REQUIRE(20 + json_length + 8 <= bytes.size());
  const std::string text = bytes.substr(20, json_length);
  // Padded with spaces after the closing brace.
  const std::size_t end = text.find_last_of('}');
  REQUIRE(end != std::string::npos);
  CHECK(text.find_first_not_of(' ', end + 1) == std::string::npos);
  CHECK(text.size() - end - 1 < 4);
  Glb glb;
  glb.doc = json::parse(text);
  const std::size_t bin_at = 20 + json_length;
  const std::uint32_t bin_length = u32_at(bytes, bin_at);
  CHECK(bin_length % 4 == 0);
  CHECK(bytes.substr(bin_at + 4, 4) == std::string("BIN\0", 4));
  CHECK(bin_at + 8 + bin_length == bytes.size());
  glb.bin = bytes.substr(bin_at + 8, bin_length);
  const std::size_t buffer_length = glb.doc.at("buffers").at(0).at("byteLength");
  CHECK(buffer_length <= bin_length);
  CHECK(bin_length - buffer_length < 4);
  CHECK(glb.bin.find_first_not_of('\0', buffer_length) == std::string::npos);  // zero padding
  return glb;
}

std::string glb_bytes(const Mesh& m) {
  std::ostringstream out;
  write_glb(out, m);
  return out.str();
}

glm::dvec3 as_float(const glm::dvec3& p) { return glm::dvec3(glm::vec3(p)); }

// Checks a .glb file against the mesh it was written from: what the issue asks of it, derived from the
// mesh's faces, not from the writer.
void check_glb(const Mesh& m, const std::string& bytes) {
  const Glb glb = parse_glb(bytes);
  CHECK(glb.doc.at("asset").at("version") == "2.0");
  const json& primitive = glb.doc.at("meshes").at(0).at("primitives").at(0);
  CHECK(primitive.value("mode", 4) == 4);
  const json& attributes = primitive.at("attributes");
  const std::vector<double> position = glb.values(attributes.at("POSITION"), 5126, "VEC3");
  const std::vector<double> normal = glb.values(attributes.at("NORMAL"), 5126, "VEC3");
  const std::vector<double> face = glb.values(attributes.at("_FACE_INDEX"), 5126, "SCALAR");
  const std::vector<double> index = glb.values(primitive.at("indices"), 5125, "SCALAR");

  // Counts: the corners of the faces written, and n - 2 triangles per face.
  std::size_t corners = 0, triangles = 0;
  glm::dvec3 low(INFINITY), high(-INFINITY);
  for (FaceId f : m.faces()) {
    if (m.is_hole(f) || m.size(f) < 3) continue;
    corners += m.size(f);
    triangles += m.size(f) - 2;
    for (CornerId c : m.corners(f)) {
      low = glm::min(low, as_float(m.position(m.vertex(c))));
      high = glm::max(high, as_float(m.position(m.vertex(c))));
    }
  }
  REQUIRE(position.size() == 3 * corners);
  REQUIRE(normal.size() == 3 * corners);
  REQUIRE(face.size() == corners);
  REQUIRE(index.size() == 3 * triangles);

  // min and max: the bounds of the faces' corners, and of the data.
  const json& accessor = glb.doc.at("accessors").at(int(attributes.at("POSITION")));
  CHECK(accessor.at("min") == json{low.x, low.y, low.z});
  CHECK(accessor.at("max") == json{high.x, high.y, high.z});
  for (std::size_t i = 0; i < corners; ++i) {
    for (int k = 0; k < 3; ++k) {
      CHECK(position[3 * i + k] >= low[k]);
      CHECK(position[3 * i + k] <= high[k]);
    }
  }

  // Each triangle: one face's three vertices, each at a corner of that face with its normal; per face, n - 2
  // triangles facing its way whose areas sum to its area.
  auto point = [&](std::size_t v) {
    return glm::dvec3(position[3 * v], position[3 * v + 1], position[3 * v + 2]);
  };
  std::map<std::uint32_t, std::size_t> triangles_of;
  std::map<std::uint32_t, double> area_of;
  for (std::size_t t = 0; t < triangles; ++t) {
    const auto a = std::size_t(index[3 * t]), b = std::size_t(index[3 * t + 1]),
               c = std::size_t(index[3 * t + 2]);
    REQUIRE(a < corners);
    REQUIRE(b < corners);
    REQUIRE(c < corners);
    CHECK(face[a] == face[b]);
    CHECK(face[a] == face[c]);
    const FaceId f(static_cast<std::uint32_t>(face[a]));
    REQUIRE(f.index() < m.face_capacity());
    REQUIRE(m.is_alive(f));
    CHECK_FALSE(m.is_hole(f));
    const glm::dvec3 n = face_normal(m, f);
    for (std::size_t v : {a, b, c}) {
      bool on_face = false;
      for (CornerId corner : m.corners(f))
        on_face = on_face || point(v) == as_float(m.position(m.vertex(corner)));
      CHECK(on_face);
      CHECK(glm::dvec3(normal[3 * v], normal[3 * v + 1], normal[3 * v + 2]) == as_float(n));
    }
    const glm::dvec3 twice_area = glm::cross(point(b) - point(a), point(c) - point(a));
    CHECK(glm::dot(twice_area, n) > 0.0);  // facing the face's way: not folded over
    ++triangles_of[f.index()];
    area_of[f.index()] += glm::length(twice_area) / 2;
  }
  for (FaceId f : m.faces()) {
    if (m.is_hole(f) || m.size(f) < 3) continue;
    CAPTURE(f.index());
    CHECK(triangles_of[f.index()] == m.size(f) - 2);
    CHECK(area_of[f.index()] == doctest::Approx(face_area(m, f)).epsilon(1e-6));
  }
}

// An L-shaped prism: two non-convex planar hexagons (area 3) and six side quads. The hexagons start at a
// corner from which a fan of triangles would fold over the reflex corner.
PolygonSoup l_prism_soup() {
  PolygonSoup s;
  const double l[6][2] = {{2, 0}, {2, 1}, {1, 1}, {1, 2}, {0, 2}, {0, 0}};
  for (double z : {0.0, 1.0}) {
    for (const auto& p : l) s.positions.push_back({p[0], p[1], z});
  }
  s.add_face({6, 7, 8, 9, 10, 11});  // top, counter-clockwise from above
  s.add_face({5, 4, 3, 2, 1, 0});    // bottom, facing down
  for (std::uint32_t i = 0; i < 6; ++i) {
    const std::uint32_t j = (i + 1) % 6;
    s.add_face({i, j, j + 6, i + 6});
  }
  return s;
}

}  // namespace

TEST_CASE("glb: a cube, an icosahedron and a non-convex prism read back by an independent parser") {
  SUBCASE("cube: 24 vertices, 12 triangles") {
    const Mesh m = cube();
    const std::string bytes = glb_bytes(m);
    check_glb(m, bytes);
    const Glb glb = parse_glb(bytes);
    CHECK(glb.doc.at("accessors").at(0).at("count") == 24);
    CHECK(glb.doc.at("accessors").at(3).at("count") == 36);
  }
  SUBCASE("icosahedron: positions rounded to float, bounds of the rounded values") {
    check_glb(build_mesh(icosahedron_soup()), glb_bytes(build_mesh(icosahedron_soup())));
  }
  SUBCASE("L prism: the reflex corner is not folded over") {
    const Mesh m = build_mesh(l_prism_soup());
    CHECK(face_area(m, FaceId(0)) == doctest::Approx(3.0));
    check_glb(m, glb_bytes(m));
  }
}

TEST_CASE("glb: hole faces and 2-gons are left out, point spheres too") {
  SUBCASE("an open grid: its boundary is a hole face, not drawn") {
    const Mesh m = build_mesh(grid_soup(3, 2));
    REQUIRE(m.num_hole_faces() == 1);
    const std::string bytes = glb_bytes(m);
    check_glb(m, bytes);
    CHECK(parse_glb(bytes).doc.at("accessors").at(3).at("count") == 3 * 2 * 6);
  }
  SUBCASE("a tetrahedron with a 2-gon split off a face, and a point sphere beside it") {
    Mesh m = tetrahedron();
    const CornerId c = m.first_corner(FaceId(0));
    m.insert_edge(c, m.next(c));  // the 2-gon (c, next c) and the face's triangle again
    m.create_vertex({5, 5, 5});
    std::size_t two_gons = 0;
    for (FaceId f : m.faces()) two_gons += m.size(f) == 2;
    REQUIRE(two_gons == 1);
    const std::string bytes = glb_bytes(m);
    check_glb(m, bytes);
    const Glb glb = parse_glb(bytes);
    CHECK(glb.doc.at("accessors").at(3).at("count") == 4 * 3);
    CHECK(glb.doc.at("accessors").at(0).at("max") == json{1.0, 1.0, 1.0});  // not the point sphere at 5
  }
}

TEST_CASE("glb: refusals leave no file, and an existing file as it was") {
  ScratchDir dir;
  write_text(dir / "old.glb", "old");
  SUBCASE("no triangle: a single point sphere") {
    Mesh m;
    m.create_vertex({0, 0, 0});
    CHECK(error_message<IoError>([&] { write_mesh(m, dir / "new.glb"); }).find("no triangles") !=
          std::string::npos);
    CHECK_THROWS_AS(write_mesh(m, dir / "old.glb"), IoError);
    std::ostringstream out;
    CHECK_THROWS_AS(write_glb(out, m), IoError);
    CHECK(out.str().empty());
  }
  SUBCASE("a coordinate beyond float32") {
    Mesh m = cube();
    m.set_position(VertexId(3), {0, 0, 1e39});
    CHECK(error_message<IoError>([&] { write_mesh(m, dir / "new.glb"); }).find("v3") != std::string::npos);
    CHECK_THROWS_AS(write_mesh(m, dir / "old.glb"), IoError);
  }
  CHECK(dir.entries() == std::vector<std::string>{"old.glb"});
  CHECK(read_text(dir / "old.glb") == "old");
}

TEST_CASE("glb: read_mesh refuses it, as glTF is written only") {
  const auto path = scratch_file("written.glb", glb_bytes(cube()));
  CHECK(error_message<IoError>([&] { read_mesh(path); }).find("output format") != std::string::npos);
}

#ifdef DLFL_TOOL
TEST_CASE("glb: dlfl convert and subdivide choose it by extension") {
  ScratchDir dir;
  const std::string out = (dir / "cube.glb").string();
  REQUIRE(run("convert " + example("cube.obj") + " '" + out + "'").exit_code == 0);
  const Mesh cube_obj = read_mesh(std::string(DLFL_SOURCE_DIR) + "/data/cube.obj");
  check_glb(cube_obj, read_text(out));
  const std::string sub = (dir / "cc.glb").string();
  REQUIRE(run("subdivide " + example("cube.obj") + " -s catmull-clark -n 1 -o '" + sub + "'").exit_code == 0);
  CHECK(parse_glb(read_text(sub)).doc.at("accessors").at(3).at("count") == 24 * 2 * 3);  // 24 quads
}
#endif
