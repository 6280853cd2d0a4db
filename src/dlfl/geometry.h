#pragma once
// Basic geometry of faces and vertices, from the vertex positions.

#include <glm/vec3.hpp>

#include <dlfl/mesh.h>

namespace dlfl {

/// Newell's vector of f: the sum over its edges (p_i, p_{i+1}) of p_i x p_{i+1}, computed in the stable
/// form of Newell's method. Its direction is the face's normal (outward for a face counter-clockwise seen
/// from outside), its length twice the area of the polygon (for a non-planar face: of its largest
/// projection). Zero for a point sphere's face and a 2-gon. O(size of f).
glm::dvec3 newell_vector(const Mesh& mesh, FaceId f);

/// The unit normal of f (Newell's vector normalised); the zero vector for a degenerate face (Newell's vector
/// zero: a point sphere, a 2-gon, collinear vertices). O(size of f).
glm::dvec3 face_normal(const Mesh& mesh, FaceId f);

/// The average of the positions of f's corners (a vertex visited twice counts twice). O(size of f).
glm::dvec3 face_centroid(const Mesh& mesh, FaceId f);

/// The area of f: half the length of Newell's vector. O(size of f).
double face_area(const Mesh& mesh, FaceId f);

/// The area-weighted average of the normals of the faces around v that are not holes, normalised (one term
/// per corner of v, so a face visiting v twice counts twice); the zero vector if that sum is zero (a point
/// sphere, or a vertex with only hole faces). O(sum of the sizes of the faces around v).
glm::dvec3 vertex_normal(const Mesh& mesh, VertexId v);

}  // namespace dlfl
