#pragma once
// Summary figures of a mesh: face-size and valence histograms, bounding box, holes.

#include <cstdint>
#include <glm/vec3.hpp>
#include <map>

#include "dlfl/mesh.h"

namespace dlfl {

struct MeshStatistics {
  std::size_t holes = 0;                            ///< faces flagged as holes
  std::size_t point_spheres = 0;                    ///< vertices without edges
  std::map<std::uint32_t, std::size_t> face_sizes;  ///< corners per face -> number of faces (holes excluded)
  std::map<std::uint32_t, std::size_t> valences;    ///< edges per vertex -> number of vertices
  glm::dvec3 bbox_min{0.0};                         ///< all zero for an empty mesh
  glm::dvec3 bbox_max{0.0};
};

/// O(size).
MeshStatistics statistics(const Mesh& mesh);

}  // namespace dlfl
