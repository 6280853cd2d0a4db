#include "schemes/polyhedron_angles.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <vector>

#include "schemes/convex_polyhedron.h"

namespace dlfl {
namespace {

// Accurate for small and large angles alike (acos loses half the digits near 0).
double angle_between(const glm::dvec3& a, const glm::dvec3& b) {
  return std::atan2(glm::length(glm::cross(a, b)), glm::dot(a, b));
}

// The largest angle between two of the unit vectors. The pair is chosen by chord length |a - b|, which grows
// with the angle over [0, pi] and is exact for small angles, and is cheap: one atan2 per call, not per pair.
double diameter(const std::vector<glm::dvec3>& normals) {
  double widest = -1.0;
  std::size_t best_i = 0, best_j = 0;
  for (std::size_t i = 0; i < normals.size(); ++i) {
    for (std::size_t j = i + 1; j < normals.size(); ++j) {
      const glm::dvec3 d = normals[i] - normals[j];
      const double chord = glm::dot(d, d);
      if (chord > widest) widest = chord, best_i = i, best_j = j;
    }
  }
  return widest < 0.0 ? 0.0 : angle_between(normals[best_i], normals[best_j]);
}

// The normals of the non-hole faces around v, appended to `out`.
template <class Normal>
void gather_vertex_normals(const Mesh& mesh, VertexId v, const Normal& normal, std::vector<glm::dvec3>& out) {
  if (mesh.is_point_sphere(v)) return;
  for (CornerId c : mesh.corners(v)) {
    const FaceId f = mesh.face(c);
    if (!mesh.is_hole(f)) out.push_back(normal(f));
  }
}

template <class Normal>
double vertex_angle_with(const Mesh& mesh, VertexId v, const Normal& normal,
                         std::vector<glm::dvec3>& buffer) {
  buffer.clear();
  gather_vertex_normals(mesh, v, normal, buffer);
  return diameter(buffer);
}

template <class Normal>
double face_angle_with(const Mesh& mesh, FaceId f, const Normal& normal, std::vector<glm::dvec3>& buffer) {
  buffer.clear();
  for (CornerId c : mesh.corners(f)) gather_vertex_normals(mesh, mesh.vertex(c), normal, buffer);
  return diameter(buffer);
}

template <class Normal>
double edge_angle_with(const Mesh& mesh, EdgeId e, const Normal& normal) {
  return angle_between(normal(mesh.face(e, 0)), normal(mesh.face(e, 1)));
}

auto normal_on_demand(const Mesh& mesh) {
  return [&mesh](FaceId f) { return face_plane(mesh, f).normal; };
}

void add(AngleSummary& s, double angle) {
  s.max = std::max(s.max, angle);
  s.mean += angle;  // the sum until `finish`
  ++s.count;
}

void finish(AngleSummary& s) { s.mean = s.count ? s.mean / double(s.count) : 0.0; }

}  // namespace

double edge_angle(const Mesh& mesh, EdgeId e) { return edge_angle_with(mesh, e, normal_on_demand(mesh)); }

double vertex_angle(const Mesh& mesh, VertexId v) {
  std::vector<glm::dvec3> buffer;
  return vertex_angle_with(mesh, v, normal_on_demand(mesh), buffer);
}

double face_angle(const Mesh& mesh, FaceId f) {
  std::vector<glm::dvec3> buffer;
  return face_angle_with(mesh, f, normal_on_demand(mesh), buffer);
}

PolyhedronAngles polyhedron_angles(const Mesh& mesh) {
  std::vector<glm::dvec3> normals(mesh.face_capacity());
  for (FaceId f : mesh.faces()) normals[f.index()] = face_plane(mesh, f).normal;
  const auto normal = [&normals](FaceId f) { return normals[f.index()]; };
  std::vector<glm::dvec3> buffer;  // reused: no allocation per element
  PolyhedronAngles a;
  for (EdgeId e : mesh.edges()) {
    if (!mesh.is_hole(mesh.face(e, 0)) && !mesh.is_hole(mesh.face(e, 1))) {
      add(a.edge, edge_angle_with(mesh, e, normal));
    }
  }
  for (VertexId v : mesh.vertices()) {
    if (!mesh.is_point_sphere(v)) add(a.vertex, vertex_angle_with(mesh, v, normal, buffer));
  }
  for (FaceId f : mesh.faces()) {
    if (!mesh.is_hole(f) && mesh.size(f) > 1) add(a.face, face_angle_with(mesh, f, normal, buffer));
  }
  finish(a.edge);
  finish(a.vertex);
  finish(a.face);
  return a;
}

}  // namespace dlfl
