#pragma once
// The raw arrays of a DLFL mesh, handles included: the exact, lossless exchange form behind the native JSON
// format.

#include <cstdint>
#include <glm/vec3.hpp>
#include <optional>
#include <vector>

#include <dlfl/mesh.h>

namespace dlfl {

/// Every element slot of a mesh, live or removed, indexed by handle. A removed slot is marked as documented
/// per type. Converting a mesh to arrays and back gives a mesh equal to it under `operator==`, with the same
/// capacities.
struct MeshArrays {
  struct Vertex {
    glm::dvec3 position{0.0};
    CornerId corner;  ///< invalid for a removed vertex
  };
  struct Corner {
    VertexId vertex;  ///< invalid for a removed corner
    FaceId face;
    CornerId next;
    CornerId prev;
    EdgeId edge;  ///< invalid for a point sphere's corner
  };
  struct Edge {
    CornerId corner0;  ///< invalid for a removed edge
    CornerId corner1;
  };
  struct Face {
    CornerId corner;
    std::uint32_t size = 0;
    bool alive = false;
    bool hole = false;
    std::optional<glm::dvec3> point;  ///< the face's control point, if set (see Mesh::face_point)
  };
  std::vector<Vertex> vertices;
  std::vector<Corner> corners;
  std::vector<Edge> edges;
  std::vector<Face> faces;

  /// The arrays of a mesh. O(size).
  static MeshArrays from(const Mesh& mesh);
  /// The mesh these arrays describe. Every handle must be in range and the result must pass `validate`;
  /// otherwise throws TopologyError naming the first problem. O(size).
  Mesh to_mesh() const;
};

}  // namespace dlfl
