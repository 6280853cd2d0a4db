#pragma once
// Summary figures of a mesh as the user sees it: the open surface (holes left out), its boundary loops,
// face-size and valence histograms, bounding box.

#include <cstdint>
#include <glm/vec3.hpp>
#include <map>

#include <dlfl/mesh.h>

namespace dlfl {

/// Figures of the open surface: the faces that are not holes, and the edges and vertices they use (point
/// spheres included). A boundary loop is usually closed by one hole face, and then the surface's vertices and
/// edges are all of the mesh's; but schemes that subdivide holes like faces (Catmull-Clark, Loop, MLCA) cover
/// one loop with several hole faces, whose inner edges and vertices are not part of the surface and are not
/// counted here (nor written to polygon files: see `to_polygons`).
struct MeshStatistics {
  std::size_t vertices = 0;  ///< vertices with a corner in a face that is not a hole
  std::size_t edges = 0;     ///< edges with a face that is not a hole on at least one side
  std::size_t faces = 0;     ///< faces that are not holes (point-sphere faces included)
  std::size_t corners = 0;   ///< corners of those faces
  std::size_t holes = 0;     ///< boundary loops: cycles of edges between a hole face and a face that is not
  std::size_t point_spheres = 0;                    ///< vertices without edges
  std::map<std::uint32_t, std::size_t> face_sizes;  ///< corners per face -> number of faces (holes excluded)
  std::map<std::uint32_t, std::size_t> valences;  ///< surface edges per surface vertex -> number of vertices
  glm::dvec3 bbox_min{0.0};                       ///< of the surface's vertices; all zero when there are none
  glm::dvec3 bbox_max{0.0};
};

/// O(size).
MeshStatistics statistics(const Mesh& mesh);

/// True for a vertex of the open surface: one with a corner in a face that is not a hole. False only for the
/// inner vertices of a hole covered by several hole faces. O(valence).
bool is_surface_vertex(const Mesh& mesh, VertexId v);

}  // namespace dlfl
