#include "dlfl/statistics.h"

#include <glm/common.hpp>
#include <vector>

namespace dlfl {

MeshStatistics statistics(const Mesh& mesh) {
  MeshStatistics s;
  // Count with flat arrays (sizes are small integers) and fold into the maps at the end.
  std::vector<std::size_t> sizes, valences;
  auto bump = [](std::vector<std::size_t>& h, std::uint32_t k) {
    if (k >= h.size()) h.resize(k + 1, 0);
    ++h[k];
  };
  for (FaceId f : mesh.faces()) {
    if (mesh.is_hole(f)) {
      ++s.holes;
      continue;
    }
    bump(sizes, mesh.size(f));
  }
  std::vector<std::uint32_t> valence(mesh.vertex_capacity(), 0);
  for (EdgeId e : mesh.edges()) {
    ++valence[mesh.from(e).index()];
    ++valence[mesh.to(e).index()];
  }
  bool first = true;
  for (VertexId v : mesh.vertices()) {
    bump(valences, valence[v.index()]);
    s.point_spheres += valence[v.index()] == 0;
    const glm::dvec3& p = mesh.position(v);
    s.bbox_min = first ? p : glm::min(s.bbox_min, p);
    s.bbox_max = first ? p : glm::max(s.bbox_max, p);
    first = false;
  }
  for (std::uint32_t k = 0; k < sizes.size(); ++k) {
    if (sizes[k]) s.face_sizes[k] = sizes[k];
  }
  for (std::uint32_t k = 0; k < valences.size(); ++k) {
    if (valences[k]) s.valences[k] = valences[k];
  }
  return s;
}

}  // namespace dlfl
