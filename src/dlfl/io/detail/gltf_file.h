#pragma once
// A .glb file prepared for writing, so that write_mesh can refuse a mesh before it stages any file (gltf.h).
// Internal to the library.

#include <cstddef>
#include <iosfwd>
#include <string>

#include <dlfl/io/detail/triangles.h>
#include <dlfl/mesh.h>

namespace dlfl::io_detail {

class GlbFile {
 public:
  /// Triangulates `mesh` and makes the JSON chunk; throws IoError naming `file` as write_glb documents. The
  /// mesh must outlive the object.
  GlbFile(const Mesh& mesh, const std::string& file);
  /// Writes the whole file.
  void write(std::ostream& out) const;

 private:
  const Mesh& mesh_;
  MeshTriangles triangles_;
  std::string json_;  // padded with spaces to 4 bytes
  std::size_t bin_bytes_ = 0;
};

}  // namespace dlfl::io_detail
