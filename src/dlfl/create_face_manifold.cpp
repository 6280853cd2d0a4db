#include <dlfl/create_face_manifold.h>

#include <cmath>

#include <dlfl/errors.h>

namespace dlfl {

FaceManifold create_face_manifold(Mesh& mesh, std::span<const glm::dvec3> positions,
                                  std::span<VertexId> vertices, std::span<CornerId> front_corners,
                                  std::span<CornerId> back_corners) {
  const std::size_t n = positions.size();
  if (n < 2) throw InvalidArgument("create_face_manifold: needs at least 2 points, got " + std::to_string(n));
  for (std::size_t i = 0; i < n; ++i) {
    const auto& p = positions[i];
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) {
      throw InvalidArgument("create_face_manifold: point " + std::to_string(i) + " is not finite");
    }
  }
  for (std::size_t s : {vertices.size(), front_corners.size(), back_corners.size()}) {
    if (s != 0 && s != n)
      throw InvalidArgument("create_face_manifold: an output span does not have one slot per point");
  }

  // (a) one point sphere per point. Corner p_i is v_i's point-sphere corner.
  const CornerId first = CornerId(mesh.corner_capacity());
  const std::uint32_t base = first.index();
  auto sphere_corner = [&](std::size_t i) { return CornerId(base + static_cast<std::uint32_t>(i)); };
  for (std::size_t i = 0; i < n; ++i) {
    VertexId v = mesh.create_vertex(positions[i]);
    if (!vertices.empty()) vertices[i] = v;
  }
  // create_vertex appends one corner each, so p_i = base + i. Each p_i is v_i's only corner until the next
  // step (vertices of valence below 2 need no corner choice, as the paper remarks). (b) the edges.
  // insert_edge(p_i, p_{i+1}) puts a new corner at v_i (leaving towards v_{i+1}) unless p_i is still a point
  // sphere, and reuses p_{i+1} (a point sphere) as the corner leaving v_{i+1} towards v_i.
  for (std::size_t i = 0; i + 1 < n; ++i) {
    InsertEdgeResult r = mesh.insert_edge(sphere_corner(i), sphere_corner(i + 1));
    if (!front_corners.empty()) front_corners[i] = mesh.corner(r.edge, 0);
    if (!back_corners.empty()) back_corners[i + 1] = sphere_corner(i + 1);
  }
  // Closing edge: splits the path face into the front face (the part of p_0) and the back face.
  InsertEdgeResult r = mesh.insert_edge(sphere_corner(n - 1), sphere_corner(0));
  if (!front_corners.empty()) front_corners[n - 1] = mesh.corner(r.edge, 0);
  if (!back_corners.empty()) back_corners[0] = mesh.corner(r.edge, 1);
  FaceManifold result;
  result.front = mesh.face(sphere_corner(0));
  result.back = mesh.face(sphere_corner(n - 1));
  return result;
}

}  // namespace dlfl
