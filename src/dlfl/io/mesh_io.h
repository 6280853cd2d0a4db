#pragma once
// Reading and writing meshes: OBJ, OFF, PLY (ASCII and binary little-endian), and the native JSON format
// (which keeps the full DLFL structure). Format by file extension.

#include <cstddef>
#include <filesystem>
#include <iosfwd>
#include <string>
#include <vector>

#include <dlfl/mesh.h>
#include <dlfl/polygon_soup.h>

namespace dlfl {

enum class MeshFormat { obj, off, ply, json };

/// The format for a path's extension (.obj, .off, .ply, .json; case-insensitive). Throws IoError naming the
/// path for any other extension.
MeshFormat format_for_path(const std::filesystem::path& path);

/// A parsed file: the polygons plus, for error messages, the file line of each vertex and face (0 where a
/// line does not apply, as in binary PLY).
struct ParsedPolygons {
  PolygonSoup soup;
  std::vector<std::size_t> vertex_lines;
  std::vector<std::size_t> face_lines;
};

/// Parsers. `name` is used in error messages. They throw IoError with the name and line for malformed or
/// truncated input, out-of-range indices and non-finite coordinates. OBJ accepts `v`, `f` with `v`, `v/vt`,
/// `v//vn`, `v/vt/vn` and negative (relative) indices, comments and ignores other statements.
ParsedPolygons parse_obj(std::istream& in, const std::string& name);
ParsedPolygons parse_off(std::istream& in, const std::string& name);
/// PLY, ASCII or binary_little_endian: reads the vertex x/y/z (float or double) and the face vertex_indices
/// list, skipping other properties and elements.
ParsedPolygons parse_ply(std::istream& in, const std::string& name);

/// Writers. Coordinates are written so that they read back bit-identical (shortest round-trip decimal in
/// text, doubles in binary PLY).
void write_obj(std::ostream& out, const PolygonSoup& soup);
void write_off(std::ostream& out, const PolygonSoup& soup);
void write_ply(std::ostream& out, const PolygonSoup& soup, bool binary);

/// Builds the mesh from parsed polygons, turning a PolygonError into an IoError at the offending file line.
Mesh build_mesh(const ParsedPolygons& parsed, const std::string& name);

/// Reads a mesh file, format by extension. Boundary loops become hole faces (see build_mesh). A .json file is
/// the native format and comes back exactly as saved, handles included.
Mesh read_mesh(const std::filesystem::path& path);

struct WriteOptions {
  bool binary_ply = true;  ///< PLY only: binary little-endian (default) or ASCII
};

/// Writes a mesh, format by extension. Polygon formats omit hole faces and point spheres' faces; the native
/// .json format keeps everything, 2-gons and handles included. Atomic: the data go to a temporary file in the
/// same folder that is renamed over `path` only when complete, so a failure never leaves a partial file.
/// Throws IoError (file not writable) or TopologyError (the mesh has a 2-gon or a multi-edge, which an
/// indexed polygon file cannot hold).
void write_mesh(const Mesh& mesh, const std::filesystem::path& path, const WriteOptions& options = {});

}  // namespace dlfl
