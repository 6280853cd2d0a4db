#pragma once
// chamfer_edge: an edge becomes a new face (docs/modeling.md, "Cutting"). For an edge whose ends have
// valences a and b: V+a+b-4, E+a+b-3, F+1 (on a cube, V+2, E+3, F+1); the Euler characteristic, the
// orientation and the hole faces elsewhere are kept.

#include <span>
#include <string_view>

#include <dlfl/mesh.h>
#include <dlfl/operations/cut_result.h>
#include <dlfl/operations/transaction.h>

namespace dlfl {

struct ChamferEdgeOptions {
  /// Where each other edge at the edge's two ends is cut, as a share of its length from that end, in
  /// (0, 0.5).
  double offset = 0.25;
};

/// Cuts `edge` off with its two end vertices: each of the a + b - 2 other edges at its ends gets a new
/// vertex at `offset` of its length from the end, the new vertices are joined across each face around the
/// edge, and the edge, its ends and the stubs are removed, leaving an (a + b - 2)-gon (a hole face if a hole
/// face was around: the cut widens the boundary). Refusals (ParameterError naming "edge" or "offset", before
/// any change): a removed edge, fewer than 2 other edges at its ends, another edge joining its ends, an
/// offset outside (0, 0.5), cut points that would not be finite. O(the faces around the edge's ends).
CutResult chamfer_edge(Transaction& tx, EdgeId edge, const ChamferEdgeOptions& options = {});

/// Chamfers every edge of the list as one operation; the counts add up. Two listed edges that share an end
/// are refused (their cuts would meet); an edge joining the ends of two listed edges gets two new vertices.
/// Refusals name "edges".
CutResult chamfer_edges(Transaction& tx, std::span<const EdgeId> edges,
                        const ChamferEdgeOptions& options = {});

/// The checks of chamfer_edges, refusals naming `parameter`.
void check_chamfer_edges(const Mesh& mesh, std::span<const EdgeId> edges, const ChamferEdgeOptions& options,
                         std::string_view parameter = "edges");

}  // namespace dlfl
