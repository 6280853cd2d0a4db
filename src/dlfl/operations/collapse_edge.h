#pragma once
// collapse_edge: the two end vertices of an edge become one (an edge contraction), through the Euler
// operators alone, so that the transaction's record undoes it exactly. See docs/modeling.md.

#include <glm/vec3.hpp>
#include <optional>

#include <dlfl/mesh.h>
#include <dlfl/operations/transaction.h>

namespace dlfl {

struct CollapseEdgeOptions {
  /// Where the merged vertex goes; the edge's midpoint when not given.
  std::optional<glm::dvec3> position;
  /// Removes each 2-gon that a surface triangle beside the edge becomes, by deleting its edge that came from
  /// the removed vertex.
  bool cleanup = false;
};

struct CollapseEdgeResult {
  /// The merged vertex: from(e), which keeps its handle; to(e) is removed.
  VertexId vertex;
  /// The 2-gons that cleanup removed (k).
  int two_gons_removed = 0;
};

/// Throws ParameterError, naming "edge" (or "position"), if `collapse_edge(tx, e, options)` would refuse: a
/// removed edge; another edge between the same two vertices (it would become a self-loop); or the link
/// condition fails, that is the result would not be a manifold polygon mesh:
/// - the end vertices have a common neighbour that is not the third vertex of a triangle beside e (the two
///   edges to it would double up);
/// - a face visits both end vertices other than along e (it would pass through the merged vertex twice);
/// - the merged vertex would lie on the boundary (next to hole faces) in more separate places than either
///   end does, and in more than one (a pinched boundary).
/// O(valence of from(e) + valence of to(e)), up to a logarithm.
void check_collapse_edge(const Mesh& mesh, EdgeId e, const CollapseEdgeOptions& options = {});

/// Merges to(e) into from(e), which moves to `options.position`. Every edge (to(e), w) other than e is
/// replaced by an edge (from(e), w) in the same place; faces keep their sides and hole flags, a triangle
/// beside e becomes a 2-gon (removed with `cleanup`). Face handles around to(e) may change (the kernel's
/// larger-part-keeps rule); edges at to(e) are new edges.
///
/// Counts: V-1, E-1, F+0. With cleanup and k surface triangles beside e: V-1, E-1-k, F-k; except when the two
/// triangles share all three edges (their component is that pillow alone), where one 2-gon is left to remove
/// and k = 1.
///
/// Validates with `check_collapse_edge` before it changes anything. O(valence of to(e) + valence of from(e)).
CollapseEdgeResult collapse_edge(Transaction& tx, EdgeId e, const CollapseEdgeOptions& options = {});

}  // namespace dlfl
