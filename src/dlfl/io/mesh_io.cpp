#include <dlfl/io/mesh_io.h>
#include <dlfl/io/obj.h>
#include <dlfl/io/off.h>
#include <dlfl/io/parsed_polygons.h>
#include <dlfl/io/ply.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <fstream>
#include <istream>
#include <system_error>

#include <dlfl/build_mesh.h>
#include <dlfl/errors.h>
#include <dlfl/io/atomic_file.h>
#include <dlfl/io/detail/text_io.h>
#include <dlfl/io/json_mesh.h>

namespace dlfl {

MeshFormat format_for_path(const std::filesystem::path& path) {
  const std::string ext = io_detail::lower_extension(path);
  if (ext == ".obj") return MeshFormat::obj;
  if (ext == ".off") return MeshFormat::off;
  if (ext == ".ply") return MeshFormat::ply;
  if (ext == ".json") return MeshFormat::json;
  if (ext.empty()) throw IoError("no file extension; expected .obj, .off, .ply or .json", path.string());
  throw IoError(
      "unknown mesh file extension '" + path.extension().string() + "'; expected .obj, .off, .ply or .json",
      path.string());
}

Mesh build_mesh(const ParsedPolygons& parsed, const std::string& name) {
  try {
    return dlfl::build_mesh(parsed.soup, parsed.numbering);
  } catch (const PolygonError& e) {
    const auto& lines = e.element() == PolygonError::Element::face ? parsed.face_lines : parsed.vertex_lines;
    throw IoError(e.what(), name, e.index() < lines.size() ? lines[e.index()] : 0);
  } catch (const InvalidArgument& e) {
    // Only a soup too large for 32-bit handles gets here, as the parsers check everything else.
    throw IoError(e.what(), name);
  }
}

// The polygon readers take a stream alike: all of it into memory, then the parser proper on the text, as
// read_mesh does with a file.
ParsedPolygons parse_obj(std::istream& in, const std::string& name) {
  return io_detail::parse_obj_text(io_detail::read_all(in, name), name);
}
ParsedPolygons parse_off(std::istream& in, const std::string& name) {
  return io_detail::parse_off_text(io_detail::read_all(in, name), name);
}
ParsedPolygons parse_ply(std::istream& in, const std::string& name) {
  return io_detail::parse_ply_text(io_detail::read_all(in, name), name);
}

namespace {

// A byte that no text file holds: NUL and the other C0 controls but \t \n \v \f \r, and DEL. Bytes from
// 0x80 up are allowed (UTF-8 in comments and names).
constexpr bool is_binary_byte(unsigned char c) { return c < 9 || (c >= 14 && c < 32) || c == 127; }

// Refuses text with a binary byte, naming its line (1-based). Scanned in blocks with a branch-free test that
// the compiler vectorises, so that checking a large file costs a few milliseconds, not a second parse.
void check_text(std::string_view text, const std::string& name) {
  const auto* bytes = reinterpret_cast<const unsigned char*>(text.data());
  constexpr std::size_t block = 4096;
  for (std::size_t begin = 0; begin < text.size(); begin += block) {
    const std::size_t end = std::min(text.size(), begin + block);
    std::uint8_t found = 0;  // bytes throughout, so that the loop runs 16 or 32 bytes a step
    for (std::size_t i = begin; i < end; ++i) {
      const std::uint8_t c = bytes[i];
      found |= std::uint8_t(c < 9) | std::uint8_t(std::uint8_t(c - 14) < 18) | std::uint8_t(c == 127);
    }
    if (found == 0) continue;
    std::size_t at = begin;
    while (!is_binary_byte(bytes[at])) ++at;
    const auto line = static_cast<std::size_t>(
                          std::count(text.begin(), text.begin() + static_cast<std::ptrdiff_t>(at), '\n')) +
                      1;
    throw IoError("binary data at line " + std::to_string(line) + " (byte " +
                      std::to_string(unsigned(bytes[at])) + "): not a text file",
                  name, line);
  }
}

// A PLY file is text up to the end of its header; a binary one goes on in binary.
std::string_view ply_header(std::string_view text) {
  const std::size_t end = text.find("end_header");
  return end == std::string_view::npos ? text : text.substr(0, end);
}

Mesh with_vertices(Mesh mesh, const std::string& name) {
  if (mesh.num_vertices() == 0) throw IoError("no vertices: the file holds no mesh", name);
  return mesh;
}

Mesh read_mesh_text(MeshFormat format, const std::string& text, const std::string& name) {
  check_text(format == MeshFormat::ply ? ply_header(text) : std::string_view(text), name);
  if (text.find_first_not_of(" \t\n\v\f\r") == std::string::npos)
    throw IoError("no vertices: the file is empty", name);
  switch (format) {
    case MeshFormat::obj:
      return build_mesh(io_detail::parse_obj_text(text, name), name);
    case MeshFormat::off:
      return build_mesh(io_detail::parse_off_text(text, name), name);
    case MeshFormat::ply:
      break;
    case MeshFormat::json: {
      nlohmann::json doc = nlohmann::json::parse(text, nullptr, false);
      if (doc.is_discarded()) throw IoError("not valid JSON", name);
      return mesh_from_json(doc, name);
    }
  }
  return build_mesh(io_detail::parse_ply_text(text, name), name);
}

}  // namespace

Mesh read_mesh(const std::filesystem::path& path) {
  const MeshFormat format = format_for_path(path);
  const std::string name = path.string();
  return with_vertices(read_mesh_text(format, io_detail::read_file(path), name), name);
}

ValidationReport validate_mesh_file(const std::filesystem::path& path, std::size_t max_violations) {
  const MeshFormat format = format_for_path(path);
  if (format != MeshFormat::json) return validate(read_mesh(path), max_violations);
  const std::string name = path.string();
  const std::string text = io_detail::read_file(path);
  check_text(text, name);
  nlohmann::json doc = nlohmann::json::parse(text, nullptr, false);
  if (doc.is_discarded())
    throw IoError(text.empty() ? "no vertices: the file is empty" : "not valid JSON", name);
  return validate_json_mesh(doc, name, max_violations);
}

void write_mesh(const Mesh& mesh, const std::filesystem::path& path, const WriteOptions& options) {
  const MeshFormat format = format_for_path(path);
  if (mesh.num_vertices() == 0) throw IoError("no vertices: an empty mesh makes no mesh file", path.string());
  FileBatch own;
  FileBatch& batch = options.batch ? *options.batch : own;
  if (format == MeshFormat::json) {
    const std::string text = mesh_to_json(mesh).dump();
    batch.stage(path, [&](std::ostream& out) { out << text << '\n'; });
    if (!options.batch) own.commit();
    return;
  }
  // Converting first means a mesh that an indexed polygon file cannot hold fails before any file is touched.
  const PolygonSoup soup = to_polygons(mesh);
  const bool binary = format == MeshFormat::ply && options.binary_ply;
  batch.stage(
      path,
      [&](std::ostream& out) {
        switch (format) {
          case MeshFormat::obj:
            write_obj(out, soup);
            break;
          case MeshFormat::off:
            write_off(out, soup);
            break;
          case MeshFormat::ply:
            write_ply(out, soup, binary);
            break;
          case MeshFormat::json:
            break;  // handled above
        }
      },
      binary);
  if (!options.batch) own.commit();
}

}  // namespace dlfl
