#include <dlfl/dense_mesh.h>

namespace dlfl {

const Mesh& dense_mesh(const Mesh& mesh, std::optional<Mesh>& storage) {
  if (mesh.vertex_capacity() == mesh.num_vertices() && mesh.edge_capacity() == mesh.num_edges() &&
      mesh.face_capacity() == mesh.num_faces() && mesh.corner_capacity() == mesh.num_corners()) {
    return mesh;
  }
  storage = mesh;
  storage->compact();
  return *storage;
}

DenseCounts dense_counts(const Mesh& mesh) {
  return {static_cast<std::uint32_t>(mesh.num_vertices()), static_cast<std::uint32_t>(mesh.num_edges()),
          static_cast<std::uint32_t>(mesh.num_faces()), static_cast<std::uint32_t>(mesh.num_corners())};
}

}  // namespace dlfl
