#pragma once
// Internal to the schemes: the input check of the triangle schemes (Loop, sqrt(3)).

#include <optional>
#include <string_view>

#include <dlfl/mesh.h>

namespace dlfl::detail {

/// Which hole faces a scheme on triangles takes: triangular ones only (Loop with boundary=hole subdivides
/// them like faces), any (a boundary rule keeps them whole), or none (sqrt(3) with boundary=hole).
enum class TriangleHoles { triangles, any, refused };

/// Refuses, in face order, a point sphere, a face that is not a triangle and the holes that `holes` does not
/// take: TopologyError "SCHEME: f3 has 4 corners; TITLE needs triangles" and the like, naming the handles of
/// `mesh` (check the input, not a compacted copy). `title` names the scheme in prose ("Loop subdivision").
void require_triangles(const Mesh& mesh, std::string_view scheme, std::string_view title,
                       TriangleHoles holes);

/// The start of a triangle scheme: `require_triangles` on the input, then the input by dense handles
/// 0 .. count-1 (`dense_mesh`). Not copied: `mesh()` may be its own compacted copy of the input.
class DenseTriangles {
 public:
  DenseTriangles(const Mesh& input, std::string_view scheme, std::string_view title, TriangleHoles holes);
  DenseTriangles(const DenseTriangles&) = delete;
  DenseTriangles& operator=(const DenseTriangles&) = delete;

  /// The input, handles 0 .. count-1.
  const Mesh& mesh() const { return *mesh_; }

 private:
  std::optional<Mesh> storage_;
  const Mesh* mesh_ = nullptr;
};

}  // namespace dlfl::detail
