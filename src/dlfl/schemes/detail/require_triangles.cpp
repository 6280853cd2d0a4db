#include <dlfl/schemes/detail/require_triangles.h>

#include <string>

#include <dlfl/dense_mesh.h>
#include <dlfl/errors.h>

namespace dlfl::detail {

void require_triangles(const Mesh& mesh, std::string_view scheme, std::string_view title,
                       TriangleHoles holes) {
  for (FaceId f : mesh.faces()) {
    const std::uint32_t n = mesh.size(f);
    if (n == 3 && (holes != TriangleHoles::refused || !mesh.is_hole(f))) [[likely]]
      continue;
    if (n > 1 && holes == TriangleHoles::any && mesh.is_hole(f)) continue;
    const std::string prefix = std::string(scheme) + ": ";
    if (n == 1) {  // only a point sphere has a one-corner face (a self-loop is illegal)
      throw TopologyError(prefix + to_string(mesh.vertex(mesh.first_corner(f))) +
                          " is a point sphere (no edge)");
    }
    if (mesh.is_hole(f)) {
      throw TopologyError(
          prefix + to_string(f) + " is a hole (a boundary loop) with " + std::to_string(n) + " corners; " +
          std::string(title) +
          (holes == TriangleHoles::triangles
               ? " with boundary=hole needs triangles, holes included (boundary=curve takes "
                 "holes of any size)"
               : " with boundary=hole needs a closed triangle mesh (boundary=curve takes open "
                 "meshes)"));
    }
    throw TopologyError(prefix + to_string(f) + " has " + std::to_string(n) + " corners; " +
                        std::string(title) + " needs triangles");
  }
}

DenseTriangles::DenseTriangles(const Mesh& input, std::string_view scheme, std::string_view title,
                               TriangleHoles holes) {
  // On the input, so that errors name its own handles, not compacted ones.
  require_triangles(input, scheme, title, holes);
  mesh_ = &dense_mesh(input, storage_);
}

}  // namespace dlfl::detail
