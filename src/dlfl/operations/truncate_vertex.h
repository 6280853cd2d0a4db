#pragma once
// truncate_vertex: cuts a corner off (docs/modeling.md, "Cutting"). A vertex of valence k becomes a k-gon:
// V+k-1, E+k, F+1; the Euler characteristic, the orientation and the hole faces elsewhere are kept.

#include <span>
#include <string_view>

#include <dlfl/mesh.h>
#include <dlfl/operations/cut_result.h>
#include <dlfl/operations/transaction.h>

namespace dlfl {

struct TruncateVertexOptions {
  /// Where each edge at the vertex is cut, as a share of its length from the vertex, in (0, 0.5): below 0.5
  /// the cuts of two truncated neighbours never meet.
  double offset = 0.25;
};

/// Cuts `vertex` off: each of its k edges gets a new vertex at `offset` of its length from it, the new
/// vertices are joined across each face around it, and the vertex with its stubs is removed, leaving a
/// k-gon (a hole face if a hole face was around the vertex: the cut then widens the boundary). V+k-1, E+k,
/// F+1. Refusals (ParameterError naming "vertex" or "offset", before any change): a removed vertex, a vertex
/// with fewer than 2 edges, an offset outside (0, 0.5) or not finite, cut points that would not be finite.
/// O(the faces around the vertex).
CutResult truncate_vertex(Transaction& tx, VertexId vertex, const TruncateVertexOptions& options = {});

/// Truncates every vertex of the list as one operation; the counts add up (a vertex listed twice is
/// refused; an edge joining two listed vertices gets two new vertices). Refusals name "vertices".
CutResult truncate_vertices(Transaction& tx, std::span<const VertexId> vertices,
                            const TruncateVertexOptions& options = {});

/// The checks of truncate_vertices, refusals naming `parameter`.
void check_truncate_vertices(const Mesh& mesh, std::span<const VertexId> vertices,
                             const TruncateVertexOptions& options, std::string_view parameter = "vertices");

}  // namespace dlfl
