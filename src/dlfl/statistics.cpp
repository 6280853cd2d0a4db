#include <dlfl/statistics.h>

#include <glm/common.hpp>
#include <vector>

namespace dlfl {

namespace {

// The number of boundary loops. A boundary half-edge is a hole-side corner whose edge has a face that is not
// a hole across it. Along a loop, the next one starts where this one ends: turn around that vertex through
// the hole faces (next_around_vertex crosses the corner's own edge) until the edge across is the surface
// again. Every corner is passed at most once per loop, so this is O(corners).
std::size_t count_boundary_loops(const Mesh& mesh) {
  auto is_boundary = [&](CornerId c) {
    return mesh.is_hole(mesh.face(c)) && mesh.edge(c).valid() && !mesh.is_hole(mesh.face(mesh.opposite(c)));
  };
  std::vector<bool> seen(mesh.corner_capacity(), false);
  std::size_t loops = 0;
  for (CornerId start : mesh.corners()) {
    if (seen[start.index()] || !is_boundary(start)) continue;
    ++loops;
    CornerId c = start;
    do {
      seen[c.index()] = true;
      c = mesh.next(c);
      while (!is_boundary(c)) c = mesh.next_around_vertex(c);
    } while (c != start);
  }
  return loops;
}

}  // namespace

bool is_surface_vertex(const Mesh& mesh, VertexId v) {
  for (CornerId c : mesh.corners(v)) {
    if (!mesh.is_hole(mesh.face(c))) return true;
  }
  return false;
}

MeshStatistics statistics(const Mesh& mesh) {
  MeshStatistics s;
  // Count with flat arrays (sizes are small integers) and fold into the maps at the end.
  std::vector<std::size_t> sizes, valences;
  auto bump = [](std::vector<std::size_t>& h, std::uint32_t k) {
    if (k >= h.size()) h.resize(k + 1, 0);
    ++h[k];
  };
  bool any_hole = false;
  for (FaceId f : mesh.faces()) {
    if (mesh.is_hole(f)) {
      any_hole = true;
      continue;
    }
    ++s.faces;
    s.corners += mesh.size(f);
    bump(sizes, mesh.size(f));
  }
  std::vector<std::uint32_t> valence(mesh.vertex_capacity(), 0);
  for (EdgeId e : mesh.edges()) {
    if (mesh.is_hole(mesh.face(e, 0)) && mesh.is_hole(mesh.face(e, 1))) continue;  // inside a hole
    ++s.edges;
    ++valence[mesh.from(e).index()];
    ++valence[mesh.to(e).index()];
  }
  bool first = true;
  for (VertexId v : mesh.vertices()) {
    if (any_hole && !is_surface_vertex(mesh, v)) continue;
    ++s.vertices;
    bump(valences, valence[v.index()]);
    s.point_spheres += mesh.is_point_sphere(v);
    const glm::dvec3& p = mesh.position(v);
    s.bbox_min = first ? p : glm::min(s.bbox_min, p);
    s.bbox_max = first ? p : glm::max(s.bbox_max, p);
    first = false;
  }
  if (any_hole) s.holes = count_boundary_loops(mesh);
  for (std::uint32_t k = 0; k < sizes.size(); ++k) {
    if (sizes[k]) s.face_sizes[k] = sizes[k];
  }
  for (std::uint32_t k = 0; k < valences.size(); ++k) {
    if (valences[k]) s.valences[k] = valences[k];
  }
  return s;
}

}  // namespace dlfl
