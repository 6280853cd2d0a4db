// STL, binary and text: see stl.h.

#include <array>
#include <limits>
#include <ostream>
#include <span>
#include <vector>

#include <dlfl/io/detail/text_io.h>
#include <dlfl/io/detail/triangles.h>
#include <dlfl/io/stl.h>

namespace dlfl {

namespace io_detail {
namespace {

constexpr std::size_t header_bytes = 84;    // an 80-byte header and the triangle count
constexpr std::size_t triangle_bytes = 50;  // a normal, three corners (12 float32) and a 16-bit attribute

std::uint64_t binary_size(std::uint64_t triangles) { return header_bytes + triangle_bytes * triangles; }

std::uint32_t binary_count(std::string_view data) {
  std::uint32_t count;
  std::memcpy(&count, data.data() + 80, 4);
  return little_endian(count);
}

bool starts_with_solid(std::string_view data) {
  const std::size_t start = data.find_first_not_of(" \t\r\n\f\v");
  return start != std::string_view::npos && data.substr(start).starts_with("solid");
}

std::string binary_size_note(std::string_view data) {
  const std::uint32_t count = binary_count(data);
  return "as binary STL, its " + std::to_string(data.size()) + " bytes do not match the " +
         std::to_string(count) + " triangles that it declares (84 + 50 x " + std::to_string(count) + " = " +
         std::to_string(binary_size(count)) + " bytes)";
}

// The vertices of the corners: identical positions become one vertex, numbered in order of first appearance,
// through an open-addressing table of vertex numbers.
void weld(std::span<const glm::dvec3> corners, PolygonSoup& soup) {
  std::size_t size = 16;
  while (size < 2 * corners.size()) size *= 2;
  constexpr std::uint32_t empty = std::numeric_limits<std::uint32_t>::max();
  std::vector<std::uint32_t> table(size, empty);
  auto bits = [](double x) {
    std::uint64_t b;
    x += 0.0;  // -0 becomes +0, which compares equal to it
    std::memcpy(&b, &x, 8);
    return b;
  };
  soup.indices.reserve(corners.size());
  for (const glm::dvec3& p : corners) {
    std::uint64_t h = bits(p.x) * 0x9E3779B97F4A7C15ull;
    h = (h ^ bits(p.y)) * 0xC2B2AE3D27D4EB4Full;
    h = (h ^ bits(p.z)) * 0x165667B19E3779F9ull;
    std::size_t i = static_cast<std::size_t>(h >> 32) & (size - 1);
    while (table[i] != empty && soup.positions[table[i]] != p) i = (i + 1) & (size - 1);
    if (table[i] == empty) {
      table[i] = static_cast<std::uint32_t>(soup.positions.size());
      soup.positions.push_back(p);
    }
    soup.indices.push_back(table[i]);
  }
  soup.offsets.reserve(corners.size() / 3 + 1);
  for (std::size_t i = 3; i <= corners.size(); i += 3) soup.offsets.push_back(static_cast<std::uint32_t>(i));
}

// The polygons of the triangles' corners, read at `lines` (text) or from binary data; a triangle whose
// corners weld to fewer than three vertices is refused, as it has no area.
ParsedPolygons polygons(std::span<const glm::dvec3> corners, std::vector<std::size_t> lines,
                        const std::string& name, bool binary) {
  if (corners.size() > max_indices) throw IoError("too many triangles", name);
  ParsedPolygons parsed;
  weld(corners, parsed.soup);
  for (std::size_t i = 0; i < parsed.soup.num_faces(); ++i) {
    const auto t = parsed.soup.face(i);
    if (t[0] != t[1] && t[1] != t[2] && t[2] != t[0]) continue;
    const std::string where =
        binary ? "triangle " + std::to_string(i + 1) + " (byte " + std::to_string(binary_size(i)) + ")"
               : "triangle " + std::to_string(i + 1);
    throw IoError(where + " has two corners at the same position: it has no area", name, lines[i]);
  }
  parsed.face_lines = std::move(lines);
  parsed.vertex_lines.resize(parsed.soup.positions.size());  // a vertex has no one line: it is welded
  return parsed;
}

ParsedPolygons parse_binary(std::string_view data, const std::string& name) {
  const std::uint32_t count = binary_count(data);
  if (data.size() != binary_size(count)) {
    const std::string position =
        data.size() < binary_size(count)
            ? "the file ends in triangle " + std::to_string((data.size() - header_bytes) / triangle_bytes + 1)
            : "bytes follow the last triangle from byte " + std::to_string(binary_size(count));
    throw IoError(
        "not an STL file: it does not start with 'solid', and " + binary_size_note(data) + ": " + position,
        name);
  }
  std::vector<glm::dvec3> corners;
  corners.reserve(std::size_t{3} * count);
  const char* at = data.data() + header_bytes;
  for (std::uint32_t i = 0; i < count; ++i, at += triangle_bytes) {
    for (int k = 0; k < 3; ++k) {
      std::array<float, 3> xyz;
      for (int j = 0; j < 3; ++j) {
        std::memcpy(&xyz[j], at + 12 * (k + 1) + 4 * j, 4);
        xyz[j] = little_endian(xyz[j]);
        if (!std::isfinite(xyz[j])) {
          throw IoError("triangle " + std::to_string(std::uint64_t{i} + 1) + " (byte " +
                            std::to_string(binary_size(i)) + "): coordinate " + std::to_string(j + 1) +
                            " of corner " + std::to_string(k + 1) + " is not finite",
                        name);
        }
      }
      corners.emplace_back(xyz[0], xyz[1], xyz[2]);
    }
  }
  return polygons(corners, std::vector<std::size_t>(count, 0), name, true);
}

// The words of an STL text, read across line ends.
class Words {
 public:
  Words(std::string_view text, const std::string& name) : s_(text, name, false) {}

  /// The next word, or empty at the end of the text.
  std::string_view next() { return to_content() ? s_.token() : std::string_view{}; }
  double number(const char* what) {
    if (!to_content()) fail(std::string("the file ends before the ") + what);
    return s_.number(what);
  }
  /// A coordinate, rounded to float32 as binary STL stores it.
  double coordinate(const char* what) {
    const auto value = static_cast<float>(number(what));
    if (!std::isfinite(value)) fail(std::string(what) + " is beyond the range of 32-bit floats");
    return value;
  }
  void expect(std::string_view word) {
    const std::string_view w = next();
    if (w == word) return;
    if (w.empty()) fail("the file ends before '" + std::string(word) + "'");
    fail("expected '" + std::string(word) + "', found '" + std::string(w) + "'");
  }
  /// Skips the rest of the line (a solid's name).
  void skip_line() { ended_ = !s_.next_line(); }
  std::size_t line() const { return s_.line(); }
  [[noreturn]] void fail(const std::string& message) const { s_.fail(message); }

 private:
  bool to_content() {
    while (!ended_ && s_.at_eol()) ended_ = !s_.next_line();
    return !ended_;
  }
  LineScanner s_;
  bool ended_ = false;
};

ParsedPolygons parse_text(std::string_view text, const std::string& name) {
  Words words(text, name);
  words.expect("solid");
  words.skip_line();
  std::vector<glm::dvec3> corners;
  std::vector<std::size_t> lines;
  for (;;) {
    const std::string_view w = words.next();
    if (w == "facet") {
      lines.push_back(words.line());
      words.expect("normal");
      for (const char* what : {"normal's x", "normal's y", "normal's z"}) words.number(what);
      words.expect("outer");
      words.expect("loop");
      for (int k = 0; k < 3; ++k) {
        words.expect("vertex");
        glm::dvec3 p;
        p.x = words.coordinate("x coordinate");
        p.y = words.coordinate("y coordinate");
        p.z = words.coordinate("z coordinate");
        corners.push_back(p);
      }
      if (words.next() != "endloop") {
        words.fail("a facet needs exactly three vertices and then 'endloop': STL facets are triangles");
      }
      words.expect("endfacet");
    } else if (w == "endsolid") {
      words.skip_line();
      const std::string_view after = words.next();
      if (after.empty()) break;
      if (after != "solid")
        words.fail("expected 'solid' or the end of the file, found '" + std::string(after) + "'");
      words.skip_line();
    } else if (w.empty()) {
      words.fail("the file ends before 'endsolid'");
    } else {
      words.fail("expected 'facet' or 'endsolid', found '" + std::string(w) + "'");
    }
  }
  return polygons(corners, std::move(lines), name, false);
}

}  // namespace

ParsedPolygons parse_stl_text(std::string_view data, const std::string& name) {
  const bool solid = starts_with_solid(data);
  if (data.size() >= header_bytes && (!solid || data.size() == binary_size(binary_count(data)))) {
    return parse_binary(data, name);
  }
  if (!solid) {
    throw IoError("not an STL file: it does not start with 'solid', and at " + std::to_string(data.size()) +
                      " bytes it is shorter than the 84-byte header of binary STL",
                  name);
  }
  try {
    check_text(data, name);
  } catch (const IoError& e) {
    if (data.size() < header_bytes) throw;
    throw IoError("starts with 'solid' but holds binary data at line " + std::to_string(e.line()) + "; " +
                      binary_size_note(data),
                  name, e.line());
  }
  return parse_text(data, name);
}

void write_stl_triangles(std::ostream& out, const Mesh& mesh, const MeshTriangles& t, bool binary) {
  BlockWriter w(out);
  auto position = [&](std::uint32_t corner) {
    return glm::vec3(mesh.position(mesh.vertex(t.corners[corner])));
  };
  if (binary) {
    // Not "solid...", which would make readers take the file for text.
    std::array<char, 80> header{};
    const std::string_view title = "binary STL written by dlfl";
    std::copy(title.begin(), title.end(), header.begin());
    w.text({header.data(), header.size()});
    w.binary(static_cast<std::uint32_t>(t.num_triangles()));
    for (std::size_t i = 0; i < t.num_triangles(); ++i) {
      const glm::vec3 n(t.normals[t.triangle_face[i]]);
      for (const glm::vec3& v : {n, position(t.triangles[3 * i]), position(t.triangles[3 * i + 1]),
                                 position(t.triangles[3 * i + 2])}) {
        w.binary(v.x);
        w.binary(v.y);
        w.binary(v.z);
      }
      w.binary(std::uint16_t{0});
    }
  } else {
    auto floats = [&](const glm::vec3& v) {
      w.number(v.x);
      w.put(' ');
      w.number(v.y);
      w.put(' ');
      w.number(v.z);
      w.put('\n');
    };
    w.text("solid dlfl\n");
    for (std::size_t i = 0; i < t.num_triangles(); ++i) {
      w.text("  facet normal ");
      floats(glm::vec3(t.normals[t.triangle_face[i]]));
      w.text("    outer loop\n");
      for (int k = 0; k < 3; ++k) {
        w.text("      vertex ");
        floats(position(t.triangles[3 * i + k]));
      }
      w.text("    endloop\n  endfacet\n");
    }
    w.text("endsolid dlfl\n");
  }
  w.flush();
}

}  // namespace io_detail

void write_stl(std::ostream& out, const Mesh& mesh, bool binary, const std::string& name) {
  io_detail::write_stl_triangles(out, mesh, io_detail::mesh_triangles(mesh, name), binary);
}

}  // namespace dlfl
