#include <dlfl/schemes/detail/boundary_points.h>

#include <optional>
#include <string>

#include <dlfl/errors.h>

namespace dlfl::detail {
std::optional<ConstAttribute<VertexId, bool>> sharp_marks(const Mesh& mesh, const char* scheme) {
  try {
    return mesh.find_attribute<VertexId, bool>(sharp_vertex_attribute);
  } catch (const InvalidArgument& e) {
    throw InvalidArgument(std::string(scheme) + ": the vertex attribute '" +
                          std::string(sharp_vertex_attribute) +
                          "' that marks sharp boundary vertices must be boolean (" + e.what() + ")");
  }
}

bool has_hole(const Mesh& mesh) {
  for (FaceId f : mesh.faces()) {
    if (mesh.is_hole(f)) return true;
  }
  return false;
}

std::vector<bool> sharp_boundary_vertices(const Mesh& mesh, const BoundaryOptions& options,
                                          const char* scheme) {
  std::vector<bool> sharp(mesh.vertex_capacity(), false);
  if (options.rule != BoundaryRule::curve) return sharp;
  const auto marks = sharp_marks(mesh, scheme);
  // A vertex is on the boundary when one of its corners lies in a hole: one pass over the holes' corners.
  for (FaceId f : mesh.faces()) {
    if (!mesh.is_hole(f)) continue;
    for (CornerId c : mesh.corners(f)) {
      const VertexId v = mesh.vertex(c);
      if ((marks && (*marks)[v]) || (options.sharp_corners && mesh.valence(v) == 2)) sharp[v.index()] = true;
    }
  }
  return sharp;
}

void mark_sharp(Mesh& result, std::span<const std::uint32_t> vertices) {
  if (vertices.empty()) return;
  const VertexAttribute<bool> marks = result.add_vertex_attribute<bool>(sharp_vertex_attribute, false);
  for (std::uint32_t v : vertices) marks[VertexId(v)] = true;
}

}  // namespace dlfl::detail
