#pragma once
// plane_cut: cuts the whole mesh along a plane (docs/modeling.md, "Cutting"). Every edge that crosses the
// plane is split where it crosses, and the section edges are drawn inside every crossed surface face, so that
// afterwards no edge crosses the plane: V+c, E+c+s, F+s for c crossed edges and s section edges. Optionally
// the faces on one side become hole faces. O(size of the mesh).

#include <cstdint>
#include <glm/vec3.hpp>
#include <vector>

#include <dlfl/mesh.h>
#include <dlfl/operations/transaction.h>

namespace dlfl {

/// Which side of the plane stays surface.
enum class PlaneKeep : std::uint8_t {
  both,   ///< nothing becomes a hole
  above,  ///< the side the normal points to stays; the faces with a vertex below become hole faces
  below,  ///< the other side stays
};

struct PlaneCutOptions {
  /// A point of the plane.
  glm::dvec3 point{0.0};
  /// The plane's normal (normalised; "above" is where it points).
  glm::dvec3 normal{0.0, 0.0, 1.0};
  PlaneKeep keep = PlaneKeep::both;
};

struct PlaneCutResult {
  /// The vertices put on the crossed edges, in the order of the edges' handles.
  std::vector<VertexId> vertices;
  /// The section edges drawn inside the crossed faces.
  std::vector<EdgeId> edges;
  /// The surface faces that became hole faces (keep above or below).
  std::vector<FaceId> holes;
};

/// Cuts the mesh along the plane through `point` with normal `normal`. A vertex closer to the plane than
/// 1e-12 times the largest coordinate difference between a vertex and `point` counts as on it: an edge
/// crosses only if its ends are strictly on opposite sides, and a face is crossed where its boundary passes
/// from one side to the other (through a vertex on the plane or a new one); a face that only touches the
/// plane, or lies in it, is left as it is. Inside a non-convex face the crossings are paired along the
/// plane's line, so that the section edges lie inside the face. Hole faces get no section edges. Refusals
/// (ParameterError naming "point" or "normal", before any change): a point or normal not finite, a zero
/// normal, distances that would not be finite.
PlaneCutResult plane_cut(Transaction& tx, const PlaneCutOptions& options);

/// The checks of plane_cut.
void check_plane_cut(const Mesh& mesh, const PlaneCutOptions& options);

}  // namespace dlfl
