#pragma once
// Internal to planarize: the least-squares plane of a face's corners, and how far the corners are from it.

#include <glm/vec3.hpp>

#include <dlfl/mesh.h>

namespace dlfl::detail {

/// The plane through `point` with unit `normal` that minimises the sum of the squared distances of the
/// face's corners (the centroid, and the eigenvector of the smallest eigenvalue of the corners' covariance).
/// Any normal of the line or point when the corners are collinear or coincide.
struct Plane {
  glm::dvec3 point{0.0};
  glm::dvec3 normal{0, 0, 1};
};

Plane best_fit_plane(const Mesh& mesh, FaceId f);

/// The largest distance of a corner of f from its best-fit plane, divided by the mean length of f's edges
/// (0 when those are all zero). Scale-free: 0 for a planar face.
double face_nonplanarity(const Mesh& mesh, FaceId f, const Plane& plane);

}  // namespace dlfl::detail
