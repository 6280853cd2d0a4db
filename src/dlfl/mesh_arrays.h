#pragma once
// The raw arrays of a DLFL mesh, handles included: the exact, lossless exchange form behind the native JSON
// format.

#include <cstdint>
#include <glm/vec3.hpp>
#include <string>
#include <vector>

#include <dlfl/mesh.h>
#include <dlfl/validate.h>

namespace dlfl {

/// Every element slot of a mesh, live or removed, indexed by handle, and every named attribute with a value
/// per slot. A removed slot is marked as documented per type (its attribute values are kept). Converting a
/// mesh to arrays and back gives a mesh equal to it under `operator==`, with the same capacities and the same
/// attribute values on removed slots too.
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
  };
  /// A named attribute (see `Mesh::attributes`); its type is that of `default_value`.
  struct Attribute {
    std::string name;
    ElementKind kind = ElementKind::vertex;
    AttributeValue default_value;
    std::vector<AttributeValue> values;  ///< one per slot of its element kind, live or removed
  };
  std::vector<Vertex> vertices;
  std::vector<Corner> corners;
  std::vector<Edge> edges;
  std::vector<Face> faces;
  std::vector<Attribute> attributes;  ///< `from` sorts them by (kind, name); `to_mesh` takes any order

  /// The arrays of a mesh. O(size).
  static MeshArrays from(const Mesh& mesh);
  /// The mesh these arrays describe. Every handle must be in range and the result must pass `validate`; each
  /// attribute needs a non-empty name unique for its kind, one value per slot, all of its default's type.
  /// Otherwise throws TopologyError naming the first problem. O(size).
  Mesh to_mesh() const;
  /// The validator's report (at most `max_violations` listed) on the mesh these arrays describe, for a tool
  /// that shows what is wrong with a saved state. Handles must be in range, as for `to_mesh`, which throws
  /// TopologyError otherwise. O(size).
  ValidationReport validate(std::size_t max_violations = 100) const;

 private:
  // The mesh of the arrays after the range and attribute checks, not yet validated.
  Mesh unvalidated_mesh() const;
};

}  // namespace dlfl
