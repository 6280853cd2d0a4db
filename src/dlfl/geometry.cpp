#include <dlfl/geometry.h>

#include <glm/geometric.hpp>

namespace dlfl {

glm::dvec3 newell_vector(const Mesh& mesh, FaceId f) {
  glm::dvec3 n(0.0);
  for (CornerId c : mesh.corners(f)) {
    const glm::dvec3& p = mesh.position(mesh.vertex(c));
    const glm::dvec3& q = mesh.position(mesh.vertex(mesh.next(c)));
    // Newell's form of (p x q): summed over the cycle it is the same, but its differences stay accurate far
    // from the origin.
    n.x += (p.y - q.y) * (p.z + q.z);
    n.y += (p.z - q.z) * (p.x + q.x);
    n.z += (p.x - q.x) * (p.y + q.y);
  }
  return n;
}

glm::dvec3 face_normal(const Mesh& mesh, FaceId f) {
  const glm::dvec3 n = newell_vector(mesh, f);
  const double length = glm::length(n);
  return length > 0.0 ? n / length : glm::dvec3(0.0);
}

glm::dvec3 face_centroid(const Mesh& mesh, FaceId f) {
  glm::dvec3 sum(0.0);
  for (CornerId c : mesh.corners(f)) sum += mesh.position(mesh.vertex(c));
  return sum / double(mesh.size(f));
}

double face_area(const Mesh& mesh, FaceId f) { return 0.5 * glm::length(newell_vector(mesh, f)); }

glm::dvec3 vertex_normal(const Mesh& mesh, VertexId v) {
  // Newell's vector is the unit normal times twice the area: summing them weights each normal by its area.
  glm::dvec3 sum(0.0);
  for (CornerId c : mesh.corners(v)) {
    if (!mesh.is_hole(mesh.face(c))) sum += newell_vector(mesh, mesh.face(c));
  }
  const double length = glm::length(sum);
  return length > 0.0 ? sum / length : glm::dvec3(0.0);
}

}  // namespace dlfl
