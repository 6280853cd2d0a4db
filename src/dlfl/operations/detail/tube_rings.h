#pragma once
// Internal to connect_faces: where the rings of a tube's new vertices go. Pure geometry, no mesh: the ends
// of the long edges at both faces, the faces' centroids and normals, and the curve and shape options in.

#include <glm/vec3.hpp>
#include <vector>

#include <dlfl/operations/connect_faces.h>

namespace dlfl::detail {

struct TubeRingsInput {
  glm::dvec3 centroid1{0.0};
  glm::dvec3 centroid2{0.0};
  /// Unit outward normals of the faces (zero for a degenerate face).
  glm::dvec3 normal1{0.0};
  glm::dvec3 normal2{0.0};
  /// Per long edge k: the position of its end in face1 and in face2.
  std::vector<glm::dvec3> ends1;
  std::vector<glm::dvec3> ends2;
  int segments = 1;
  TubeCurve curve = TubeCurve::line;
  double weight1 = 1.0;
  double weight2 = 1.0;
  double pinch = 1.0;
  double bubble = 0.0;
};

/// The positions of the ring vertices: ring j = 1 .. segments - 1 (at t = j / segments) on long edge k at
/// index (j - 1) m + k, m = ends1.size(). Always finite for finite input. O(segments x m).
std::vector<glm::dvec3> tube_ring_positions(const TubeRingsInput& input);

}  // namespace dlfl::detail
