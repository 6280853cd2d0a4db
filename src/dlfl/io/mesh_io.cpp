#include <dlfl/io/mesh_io.h>
#include <dlfl/io/obj.h>
#include <dlfl/io/off.h>
#include <dlfl/io/parsed_polygons.h>
#include <dlfl/io/ply.h>
#include <dlfl/io/stl.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <fstream>
#include <istream>
#include <system_error>

#include <dlfl/build_mesh.h>
#include <dlfl/errors.h>
#include <dlfl/io/atomic_file.h>
#include <dlfl/io/detail/file_bytes.h>
#include <dlfl/io/detail/gltf_file.h>
#include <dlfl/io/detail/text_io.h>
#include <dlfl/io/detail/triangles.h>
#include <dlfl/io/json_mesh.h>

namespace dlfl {

MeshFormat format_for_path(const std::filesystem::path& path) {
  const std::string ext = io_detail::lower_extension(path);
  if (ext == ".obj") return MeshFormat::obj;
  if (ext == ".off") return MeshFormat::off;
  if (ext == ".ply") return MeshFormat::ply;
  if (ext == ".json") return MeshFormat::json;
  if (ext == ".stl") return MeshFormat::stl;
  if (ext == ".glb") return MeshFormat::glb;
  constexpr const char* known = ".obj, .off, .ply, .stl, .json or .glb";
  if (ext.empty()) throw IoError(std::string("no file extension; expected ") + known, path.string());
  throw IoError("unknown mesh file extension '" + path.extension().string() + "'; expected " + known,
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
ParsedPolygons parse_stl(std::istream& in, const std::string& name) {
  return io_detail::parse_stl_text(io_detail::read_all(in, name), name);
}

namespace {

// A PLY file is text up to the end of its header; a binary one goes on in binary.
std::string_view ply_header(std::string_view text) {
  const std::size_t end = text.find("end_header");
  return end == std::string_view::npos ? text : text.substr(0, end);
}

Mesh with_vertices(Mesh mesh, const std::string& name) {
  if (mesh.num_vertices() == 0) throw IoError("no vertices: the file holds no mesh", name);
  return mesh;
}

Mesh read_mesh_text(MeshFormat format, std::string_view text, const std::string& name) {
  io_detail::check_text(format == MeshFormat::ply ? ply_header(text) : text, name);
  if (text.find_first_not_of(" \t\n\v\f\r") == std::string_view::npos)
    throw IoError("no vertices: the file is empty", name);
  switch (format) {
    case MeshFormat::obj:
      return build_mesh(io_detail::parse_obj_text(text, name), name);
    case MeshFormat::off:
      return build_mesh(io_detail::parse_off_text(text, name), name);
    case MeshFormat::ply:
    case MeshFormat::stl:
    case MeshFormat::glb:
      break;  // PLY below; STL and glTF are not text, see read_mesh
    case MeshFormat::json: {
      nlohmann::json doc = nlohmann::json::parse(text.begin(), text.end(), nullptr, false);
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
  if (format == MeshFormat::glb) {
    throw IoError("glTF is an output format here; read OBJ, OFF, PLY, STL or the native JSON", name);
  }
  if (format == MeshFormat::stl) {
    const io_detail::FileBytes bytes(path);
    return with_vertices(build_mesh(io_detail::parse_stl_text(bytes.view(), name), name), name);
  }
  const io_detail::FileBytes bytes(path);
  return with_vertices(read_mesh_text(format, bytes.view(), name), name);
}

ValidationReport validate_mesh_file(const std::filesystem::path& path, std::size_t max_violations) {
  const MeshFormat format = format_for_path(path);
  if (format != MeshFormat::json) return validate(read_mesh(path), max_violations);
  const std::string name = path.string();
  const std::string text = io_detail::read_file(path);
  io_detail::check_text(text, name);
  nlohmann::json doc = nlohmann::json::parse(text, nullptr, false);
  if (doc.is_discarded())
    throw IoError(text.empty() ? "no vertices: the file is empty" : "not valid JSON", name);
  return validate_json_mesh(doc, name, max_violations);
}

namespace {

// Stages the mesh in `batch`. Whatever a format cannot hold is refused before the file is staged.
void stage_mesh(const Mesh& mesh, const std::filesystem::path& path, MeshFormat format, bool binary,
                FileBatch& batch) {
  const std::string name = path.string();
  switch (format) {
    case MeshFormat::json: {
      const std::string text = mesh_to_json(mesh).dump();
      batch.stage(path, [&](std::ostream& out) { out << text << '\n'; });
      return;
    }
    case MeshFormat::glb: {
      const io_detail::GlbFile glb(mesh, name);
      batch.stage(
          path, [&](std::ostream& out) { glb.write(out); }, true);
      return;
    }
    case MeshFormat::stl: {
      const io_detail::MeshTriangles triangles = io_detail::mesh_triangles(mesh, name);
      batch.stage(
          path, [&](std::ostream& out) { io_detail::write_stl_triangles(out, mesh, triangles, binary); },
          binary);
      return;
    }
    case MeshFormat::obj:
    case MeshFormat::off:
    case MeshFormat::ply:
      break;
  }
  const PolygonSoup soup = to_polygons(mesh);
  binary = binary && format == MeshFormat::ply;
  batch.stage(
      path,
      [&](std::ostream& out) {
        if (format == MeshFormat::obj) write_obj(out, soup);
        if (format == MeshFormat::off) write_off(out, soup);
        if (format == MeshFormat::ply) write_ply(out, soup, binary);
      },
      binary);
}

}  // namespace

void write_mesh(const Mesh& mesh, const std::filesystem::path& path, const WriteOptions& options) {
  const MeshFormat format = format_for_path(path);
  if (mesh.num_vertices() == 0) throw IoError("no vertices: an empty mesh makes no mesh file", path.string());
  FileBatch own;
  stage_mesh(mesh, path, format, options.binary, options.batch ? *options.batch : own);
  if (!options.batch) own.commit();
}

}  // namespace dlfl
