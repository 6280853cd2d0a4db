#pragma once
// subdivide_face: one face cut into quads around a new vertex at its centroid, through new midpoints of its
// edges (or, in the triangles style, stellated).

#include <cstdint>
#include <vector>

#include <dlfl/mesh.h>
#include <dlfl/operations/transaction.h>

namespace dlfl {

enum class SubdivideFaceStyle : std::uint8_t {
  quads,      ///< the face vertex joined to new edge midpoints: n quads
  triangles,  ///< the face vertex joined to the corners: stellate_face with height 0, n triangles
};

struct SubdivideFaceOptions {
  SubdivideFaceStyle style = SubdivideFaceStyle::quads;
};

/// What subdivide_face made.
struct SubdivideFaceResult {
  /// The face vertex, at the face's centroid.
  VertexId center;
  /// The edge midpoints in the order of the face's edges from its first corner (quads only).
  std::vector<VertexId> midpoints;
  /// The new faces in the order of the face's corners from its first corner; the face's own handle is one of
  /// them. Quads: the i-th has the i-th corner between the midpoints of the edges before and after it.
  std::vector<FaceId> faces;
};

/// Subdivides face f (n corners). Quads: every edge of f gets a vertex at its midpoint, and a new vertex at
/// the centroid of f is joined to each midpoint: V+n+1, E+2n, F+n-1. Each neighbouring face across an edge of
/// f gains the midpoint as a corner (it grows by one side), hole faces included. An edge with f on both sides
/// gets one midpoint, which the face vertex is joined to twice: then V+m+1, E+m+n, F+n-1 for m distinct
/// edges. Triangles: as stellate_face with height 0: V+1, E+n, F+n-1. The new faces keep f's orientation and
/// hole flag (a surface face). O(n).
///
/// Throws ParameterError naming "face" (mesh unchanged) for a removed face, a hole face or a point sphere's
/// face.
SubdivideFaceResult subdivide_face(Transaction& tx, FaceId f, const SubdivideFaceOptions& options = {});

/// The refusals of subdivide_face, without changing anything. Throws ParameterError naming "face".
void check_subdivide_face(const Mesh& mesh, FaceId f);

}  // namespace dlfl
