#include <dlfl/schemes/detail/honeycomb_planarize.h>

#include <cmath>
#include <glm/geometric.hpp>
#include <vector>

#include <dlfl/analysis/concave_edges.h>
#include <dlfl/analysis/convex_polyhedron.h>
#include <dlfl/analysis/detail/planarize_moves.h>
#include <dlfl/geometry.h>

namespace dlfl::detail {
namespace {

constexpr double flat_tolerance = 1e-9;

bool on_boundary(const Mesh& mesh, VertexId v) {
  for (CornerId c : mesh.corners(v)) {
    if (mesh.is_hole(mesh.face(c))) return true;
  }
  return false;
}

}  // namespace

bool has_flat_region(const Mesh& mesh) {
  const double tolerance = flat_tolerance * bounding_box_diagonal(mesh);
  for (EdgeId e : mesh.edges()) {
    const FaceId f = mesh.face(mesh.corner(e, 0)), g = mesh.face(mesh.corner(e, 1));
    if (f == g || mesh.is_hole(f) || mesh.is_hole(g)) continue;
    const FacePlane pf = face_plane(mesh, f), pg = face_plane(mesh, g);
    if (pf.normal == glm::dvec3(0.0) || pg.normal == glm::dvec3(0.0)) continue;
    if (glm::length(pf.normal - pg.normal) > flat_tolerance) continue;
    if (std::abs(pf.distance(face_centroid(mesh, g))) <= tolerance &&
        std::abs(pg.distance(face_centroid(mesh, f))) <= tolerance)
      return true;
  }
  return false;
}

bool lateral_rule_applies(const Mesh& mesh) {
  bool control = false;
  for (VertexId v : mesh.vertices()) {
    if (mesh.valence(v) != 3 && !mesh.is_point_sphere(v) && !on_boundary(mesh, v)) {
      control = true;
      break;
    }
  }
  return control && has_flat_region(mesh);
}

bool planarize_new_faces(Mesh& result) {
  const ConcaveEdges plain = concave_edges(result);
  std::vector<glm::dvec3> plain_positions(result.vertex_capacity());
  std::vector<bool> fixed(result.vertex_capacity(), false);
  for (VertexId v : result.vertices()) {
    fixed[v.index()] = on_boundary(result, v);
    plain_positions[v.index()] = result.position(v);
  }
  for (int round = 0; round < lateral_planarize_rounds; ++round) {
    bool moved = false;
    for (const auto& [v, to] : planarize_moves(result)) {
      if (fixed[v.index()]) continue;
      result.set_position(v, to);
      moved = true;
    }
    if (!moved) break;
  }
  const ConcaveEdges planarized = concave_edges(result);
  if (planarized.concave <= plain.concave && planarized.mean_dihedral_degrees <= plain.mean_dihedral_degrees)
    return true;
  for (VertexId v : result.vertices()) result.set_position(v, plain_positions[v.index()]);
  return false;
}

}  // namespace dlfl::detail
