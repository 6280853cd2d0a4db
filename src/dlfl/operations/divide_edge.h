#pragma once
// divide_edge: an edge cut into equal segments by new vertices on it. See docs/modeling.md.

#include <cstdint>
#include <vector>

#include <dlfl/mesh.h>
#include <dlfl/operations/transaction.h>

namespace dlfl {

/// The most segments `divide_edge` makes of one edge: a guard against a mistyped count exhausting memory.
inline constexpr std::int64_t max_edge_segments = 1000000;

struct DivideEdgeResult {
  /// The new vertices, from from(e) towards to(e).
  std::vector<VertexId> vertices;
  /// The segments, from from(e) towards to(e); the first is e itself.
  std::vector<EdgeId> edges;
};

/// Throws ParameterError naming "edge" for a removed edge, or "segments" for a count outside [1,
/// max_edge_segments].
void check_divide_edge(const Mesh& mesh, EdgeId e, std::int64_t segments);

/// Puts segments - 1 new vertices on e, equally spaced on the segment between its end positions, so that e
/// becomes `segments` edges (subdivide_edge repeated on the far part). One segment changes nothing. Both
/// faces of e grow by segments - 1 corners.
///
/// Counts: V+(s-1), E+(s-1), F+0. O(s).
DivideEdgeResult divide_edge(Transaction& tx, EdgeId e, std::int64_t segments = 2);

}  // namespace dlfl
