#pragma once
// smooth: Laplacian smoothing. See docs/modeling.md.

#include <dlfl/mesh.h>
#include <dlfl/operations/transaction.h>

namespace dlfl {

struct SmoothOptions {
  /// Rounds, in [0, 10000]; 0 changes nothing.
  int iterations = 1;
  /// The share of the way to the neighbours' mean that a vertex moves per round, in (0, 1].
  double lambda = 0.5;
  /// Leaves the vertices next to a hole face (boundaries of an open mesh) where they are.
  bool keep_boundary = true;
};

/// Throws ParameterError naming "iterations" or "lambda" for a value outside its range (or not finite).
void check_smooth(const SmoothOptions& options);

/// Each round moves every vertex p with edges to p + lambda (q - p), q the mean of its neighbours (the far
/// end of each of its edges, so a neighbour joined by two edges counts twice), all from the positions the
/// round started with (Jacobi). Point spheres stay; with `keep_boundary`, so do the vertices next to a hole
/// face. A vertex that would not move is not written. Counts: V+0, E+0, F+0. O(size) per round.
void smooth(Transaction& tx, const SmoothOptions& options = {});

}  // namespace dlfl
