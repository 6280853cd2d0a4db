#pragma once
// planarize: vertices moved so that the faces approach their best-fit planes. See docs/modeling.md.

#include <dlfl/mesh.h>
#include <dlfl/operations/transaction.h>

namespace dlfl {

struct PlanarizeOptions {
  /// Rounds of moves, in [0, 10000]; 0 only measures.
  int iterations = 10;
};

struct PlanarizeResult {
  /// `nonplanarity` of the mesh before the first round and after the last.
  double nonplanarity_before = 0.0;
  double nonplanarity_after = 0.0;
  /// Rounds that moved a vertex (a round that moves none ends the run).
  int iterations_run = 0;
};

/// The largest non-planarity of a surface face of 4 or more corners (hole faces, triangles, 2-gons and
/// point spheres are planar or do not count): the largest distance of a corner from the face's
/// least-squares plane, divided by the face's mean edge length. 0 for a mesh of planar faces. O(size).
double nonplanarity(const Mesh& mesh);

/// Throws ParameterError naming "iterations" unless it is in [0, 10000].
void check_planarize(const PlanarizeOptions& options);

/// Each round fits the least-squares plane to every surface face of 4 or more corners and moves every
/// vertex of such faces to the mean of its projections onto the planes of its faces (one per corner; a
/// face already planar to 1e-12 of its mean edge length counts as the vertex where it is), all from the
/// positions the round started with. That is the local-global alternation of Bouaziz, Deuss, Schwartzburg,
/// Weise and Pauly, *Shape-Up*: neither step increases the sum of the squared distances of the corners from
/// their planes. A vertex that would not move, or would go to a non-finite position, is not written, so a
/// planar mesh stays exactly as it is. Counts: V+0, E+0, F+0. O(size) per round.
PlanarizeResult planarize(Transaction& tx, const PlanarizeOptions& options = {});

}  // namespace dlfl
