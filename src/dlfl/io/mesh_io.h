#pragma once
// Reading and writing mesh files, format by extension: OBJ, OFF, PLY (ASCII and binary little-endian), and
// the native JSON format (which keeps the full DLFL structure). Each format's parser and writer has its own
// header: obj.h, off.h, ply.h, json_mesh.h.

#include <cstddef>
#include <filesystem>
#include <string>

#include <dlfl/errors.h>
#include <dlfl/mesh.h>

namespace dlfl {

enum class MeshFormat { obj, off, ply, json };

/// The format for a path's extension (.obj, .off, .ply, .json; case-insensitive). Throws IoError naming the
/// path for any other extension.
MeshFormat format_for_path(const std::filesystem::path& path);

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
