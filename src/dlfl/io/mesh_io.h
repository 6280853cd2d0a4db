#pragma once
// Reading and writing mesh files, format by extension: OBJ, OFF, PLY (ASCII and binary little-endian), STL
// (binary and text), the native JSON format (which keeps the full DLFL structure), and glTF binary (written
// only). Each format's parser and writer has its own header: obj.h, off.h, ply.h, stl.h, json_mesh.h, gltf.h.

#include <cstddef>
#include <filesystem>
#include <string>

#include <dlfl/errors.h>
#include <dlfl/mesh.h>
#include <dlfl/validate.h>

namespace dlfl {

enum class MeshFormat { obj, off, ply, json, stl, glb };

/// The format for a path's extension (.obj, .off, .ply, .json, .stl, .glb; case-insensitive). Throws IoError
/// naming the path for any other extension.
MeshFormat format_for_path(const std::filesystem::path& path);

/// Reads a mesh file, format by extension. Boundary loops become hole faces (see build_mesh). A .json file is
/// the native format and comes back exactly as saved, handles included. An .stl file's identical corner
/// positions are welded into vertices (stl.h); a .glb file is refused (IoError), as glTF is written only.
/// Throws IoError naming the file (and the line, 1-based, where one is to blame) for anything malformed:
/// among others "no vertices" for an empty file or one without geometry, and "binary data at line N" for a
/// text format (OBJ, OFF, JSON, a PLY header) holding bytes that no text file has (NUL and the other control
/// characters but tab, line feed, carriage return, vertical tab and form feed).
Mesh read_mesh(const std::filesystem::path& path);

class FileBatch;

/// Reads a mesh file and validates it, listing up to `max_violations` violations: what `dlfl check` shows. A
/// .json file may hold any DLFL state, so its structure is reported rather than refused; any other reader
/// refuses a malformed file with IoError naming the file and line, as read_mesh does.
ValidationReport validate_mesh_file(const std::filesystem::path& path, std::size_t max_violations = 100);

struct WriteOptions {
  bool binary = true;  ///< PLY and STL: binary (default; little-endian) or ASCII
  /// When set, the file is only staged in this batch (atomic_file.h) and replaced when the batch commits,
  /// together with the batch's other files.
  FileBatch* batch = nullptr;
};

/// Writes a mesh, format by extension. Polygon formats omit hole faces and point spheres' faces; the native
/// .json format keeps everything, 2-gons and handles included. The triangle formats (.stl, .glb) write each
/// other face as n - 2 triangles, and leave 2-gons out, as they have no area (stl.h, gltf.h). A mesh without
/// vertices is refused, as read_mesh would refuse the file. Atomic: the data go to a temporary file in the
/// same folder that is renamed over `path` only when complete, so a failure never leaves a partial file.
/// Symbolic links are written through, and a replaced file keeps its permissions (FileBatch).
/// Throws IoError (file not writable, see check_writable; for .stl and .glb also a mesh with no triangle or a
/// coordinate beyond float32, and for .glb a face handle index of 2^24 or more) or TopologyError (OBJ, OFF,
/// PLY: the mesh has a 2-gon or a multi-edge, which an indexed polygon file cannot hold); a refused mesh
/// leaves every file as it was.
void write_mesh(const Mesh& mesh, const std::filesystem::path& path, const WriteOptions& options = {});

}  // namespace dlfl
