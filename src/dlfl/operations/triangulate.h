#pragma once
// triangulate: faces cut into triangles by diagonals, ear by ear in the face's plane, so that a non-convex
// planar face is never folded over itself.

#include <span>
#include <vector>

#include <dlfl/mesh.h>
#include <dlfl/operations/transaction.h>

namespace dlfl {

/// What triangulate made.
struct TriangulateResult {
  /// The triangles of the faces that were cut, face after face (each face's own handle is one of them).
  std::vector<FaceId> faces;
};

/// Cuts each listed face of n > 3 sides into n - 2 triangles by n - 3 diagonals (insert_edge): E+(n-3),
/// F+(n-3) per face. Hole faces and faces of 3 or fewer sides are left alone. The diagonals come from ear
/// clipping in the face's plane (the plane through its first corner normal to its Newell vector): a corner is
/// cut off when it is convex there, its two neighbours are different vertices, and no other corner of the
/// face lies in the triangle. A planar simple polygon, convex or not, so becomes triangles that all face the
/// way it faces and whose areas sum to its area. A face with no such ear (not planar, self-overlapping in its
/// plane, degenerate) has its most convex corner cut off instead. A face that visits a vertex more than once
/// has the cuts that leave their neighbours cuttable made first; one left with corners that all have the same
/// vertex on both sides (a, b, a, b: no diagonal without a self-loop) keeps that remainder, and so may get
/// fewer than n - 3 diagonals (a, b, a, b, a, b has no triangulation at all). O(n^2) per face.
///
/// Throws ParameterError naming "faces" (mesh unchanged) for a removed face or a face listed twice.
TriangulateResult triangulate(Transaction& tx, std::span<const FaceId> faces);

/// triangulate on every face of the mesh (those alive when it starts).
TriangulateResult triangulate_all(Transaction& tx);

/// The refusals of triangulate, without changing anything. Throws ParameterError naming "faces".
void check_triangulate(const Mesh& mesh, std::span<const FaceId> faces);

}  // namespace dlfl
