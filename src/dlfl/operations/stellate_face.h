#pragma once
// stellate_face: a new vertex above a face, joined to each of its corners, so that an n-gon becomes a fan of
// n triangles. Also the core that subdivide_face shares: a new vertex joined to chosen corners of one face.

#include <glm/vec3.hpp>
#include <span>
#include <vector>

#include <dlfl/mesh.h>
#include <dlfl/operations/transaction.h>

namespace dlfl {

struct StellateFaceOptions {
  /// How far the new vertex is moved from the face's centroid along the face's unit normal (Newell's,
  /// dlfl/geometry.h; outward for a positive height). A face whose normal is zero (collinear corners, a
  /// 2-gon) gets its vertex at the centroid whatever the height.
  double height = 0.0;
};

/// What a stellation made.
struct StellateFaceResult {
  /// The new vertex of each face, in the order the faces were given.
  std::vector<VertexId> vertices;
  /// The triangles, face after face, each face's in the order of its corners from its first corner (the
  /// i-th triangle has the i-th corner and the next one). The face's own handle is one of them.
  std::vector<FaceId> faces;
};

/// Stellates face f: a new vertex at its centroid moved `options.height` along its normal, joined by an edge
/// to every corner. An n-gon becomes n triangles: V+1, E+n, F+n-1. Triangles keep f's orientation and its
/// (surface) hole flag. O(n).
///
/// Throws ParameterError (mesh unchanged) naming "face" for a removed face, a hole face, a point sphere's
/// face or a new vertex that would not be at a finite position, and naming "height" for a non-finite height.
StellateFaceResult stellate_face(Transaction& tx, FaceId f, const StellateFaceOptions& options = {});

/// Stellates each face on its own, as stellate_face: V+k, E+sum n, F+sum (n-1) for k faces. O(sum n).
///
/// Throws ParameterError (mesh unchanged) naming "faces" for an empty list, a face listed twice, or any face
/// stellate_face would refuse ("height" for a non-finite height).
StellateFaceResult stellate_faces(Transaction& tx, std::span<const FaceId> faces,
                                  const StellateFaceOptions& options = {});

/// The refusals of stellate_faces (stellate_face with one face), without changing anything: `parameter` is
/// the name messages give the argument ("face" or "faces"). Throws ParameterError.
void check_stellate_faces(const Mesh& mesh, std::span<const FaceId> faces, double height,
                          const char* parameter);

/// The stellation step shared with subdivide_face: a new vertex at `position`, joined by one new edge to
/// each of `corners`, which must be distinct corners of one face listed in the order they come along it
/// (at least one). The face is cut into one face per corner: the i-th runs from the new vertex through
/// corners[i] up to corners[i+1]'s vertex. V+1, E+k, F+k-1 for k corners; each insert_edge relabels O(1)
/// corners plus the part cut off, so the whole is O(size of the face). Returns the new vertex, and the faces
/// in the order of the corners (the face of corners[i] after the cut).
StellateFaceResult join_corners_to_new_vertex(Transaction& tx, std::span<const CornerId> corners,
                                              const glm::dvec3& position);

}  // namespace dlfl
