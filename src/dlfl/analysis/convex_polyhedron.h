#pragma once
// Convex polyhedra as the Meng-Prautzsch schemes need them: face planes, the centre, and the precondition
// check "closed, strictly convex, centre strictly inside" (paper, assumption 2.1). See
// docs/meng_prautzsch.md.

#include <glm/vec3.hpp>
#include <optional>
#include <string>
#include <vector>

#include <dlfl/mesh.h>

namespace dlfl {

/// The plane of a face: unit normal pointing outward (the face is counter-clockwise seen from outside) and
/// offset, so the plane is {x : dot(normal, x) == offset}. The normal is Newell's (exact for planar faces);
/// the offset is taken at the centroid of the face's vertices.
struct FacePlane {
  glm::dvec3 normal{0.0};
  double offset = 0.0;
  /// Signed distance of a point to the plane: positive outside.
  double distance(const glm::dvec3& p) const;
};

/// The plane of a face, as above. A degenerate face (zero area) gets a zero normal.
FacePlane face_plane(const Mesh& mesh, FaceId f);

/// The length of the diagonal of the bounding box of the live vertices (0 for an empty mesh): the mesh size
/// that relative tolerances scale with. O(vertices).
double bounding_box_diagonal(const Mesh& mesh);

/// The centroid of the live vertices: the default centre of the Meng-Prautzsch schemes. (0,0,0) for an empty
/// mesh.
glm::dvec3 vertex_centroid(const Mesh& mesh);

/// Tolerances of the convexity check. Lengths are relative to the diagonal of the mesh's bounding box.
struct ConvexityOptions {
  /// A vertex within this distance of a face plane counts as on it (planarity), and must be at least this far
  /// inside a plane it is not on (strict convexity); the centre must be this far inside every face plane.
  double relative_tolerance = 1e-9;
  /// Two adjacent faces whose normals are closer than this angle (radians) are coplanar.
  double angle_tolerance = 1e-9;
};

/// Why a mesh is not a strictly convex polyhedron around `centre`: the first violation found, or nothing.
/// `topological` tells a structural defect (hole, point sphere, face of fewer than 3 sides, not a single
/// sphere) from a geometric one.
struct ConvexityViolation {
  bool topological = false;
  std::string message;  ///< names the offending face, edge or vertex
};

/// Checks, in O(size), that the mesh is a closed, strictly convex polyhedron with `centre` strictly inside:
/// - no hole faces, no point spheres, every face has at least 3 sides;
/// - every face is planar (its vertices within the tolerance of its plane) and a strictly convex polygon
///   (every corner turns the same way as the face normal, and the boundary turns around once);
/// - every edge is convex and its two faces are not coplanar (exterior angle above the angle tolerance);
/// - the centre lies strictly inside every face plane, and the faces seen from the centre cover the sphere of
///   directions exactly once (their solid angles sum to 4 pi).
/// Together these make the surface the boundary of a convex body: seen from the centre it is a radial graph
/// (one sheet), and a radial graph that is convex at every edge bounds a convex set. Every vertex then lies
/// strictly inside every face plane not containing it.
std::optional<ConvexityViolation> convexity_violation(const Mesh& mesh, const glm::dvec3& centre,
                                                      const ConvexityOptions& options = {});

/// True if `convexity_violation` finds nothing.
bool is_convex_polyhedron(const Mesh& mesh, const glm::dvec3& centre, const ConvexityOptions& options = {});

/// Throws if `convexity_violation` finds something: TopologyError for a structural defect, InvalidArgument
/// for a geometric one, with `context` (e.g. the scheme's name) in front of the message.
void require_convex_polyhedron(const Mesh& mesh, const glm::dvec3& centre, const std::string& context,
                               const ConvexityOptions& options = {});

}  // namespace dlfl
