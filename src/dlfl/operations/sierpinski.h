#pragma once
// sierpinski: TopMod's "multi-connect midpoints": every vertex keeps a corner piece, and the pieces of the
// two ends of every edge are joined by a thin strut across its middle (docs/modeling.md, "High genus").

#include <dlfl/mesh.h>
#include <dlfl/operations/transaction.h>

namespace dlfl {

struct SierpinskiOptions {
  /// Where each edge is cut, as a share of its length from each end: the size of the corner pieces. In
  /// (0, 0.5); the strut along an edge is (1 - 2 scale) of it long.
  double scale = 0.45;
  /// The width of a strut where it meets a piece, as a share of the cut edges of the piece on either side
  /// of it. In (0, 0.5).
  double neck = 0.1;
};

/// Cuts every edge in three (its ends' tips at `scale` from each end) and every corner of every face off
/// between the two tips next to it (the caps: a piece of the surface around each vertex); cuts each such
/// cut edge in three (its neck points at `neck` from each end); splits off, in each face, a quad along the
/// middle piece of each edge (a strut's side); and joins, at each end of each edge, the two neck points
/// beside the tip across the edge. What remained of each face turns into one face per vertex, closing its
/// piece (the vertex figure through the neck points), and one quad per edge, the strut's floor: every
/// piece is a corner pyramid, every strut a triangular prism from one piece to the next.
///
/// Counts, for V vertices and E edges (point spheres are left as they are and count in V): V' = V + 6E,
/// E' = 13E, F' = V + 5E, whatever the faces: 2E caps of 5 sides, 3E quads, and a face of 2k sides per
/// vertex of valence k. V' - E' + F' = 2V - 2E: a connected input gives one closed component of genus
/// E - V + 1 (tetrahedron 3, cube 5). Hole faces are cut like the others, and what is cut from a hole face
/// stays a hole; the faces that close the pieces and the struts' floors are surface faces.
///
/// Refuses (ParameterError, nothing changed): `scale` or `neck` not finite or outside (0, 0.5); a vertex of
/// valence 1, and positions that would not be finite (naming "scale"). O(size of the mesh).
void sierpinski(Transaction& tx, const SierpinskiOptions& options = {});

/// The checks of sierpinski, without changing anything.
void check_sierpinski(const Mesh& mesh, const SierpinskiOptions& options);

}  // namespace dlfl
