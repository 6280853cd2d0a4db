#pragma once
// The honeycomb's `planarize` rule (docs/lateral_artifacts.md), shared by honeycomb and honeycomb-zw: a
// non-stationary planarization against the bricklayers' problem of Akleman and Srinivasan, "Honeycomb
// subdivision", section 5. A step planarizes the new faces when its input has a flat region (two faces that
// share an edge and lie in one plane), where the hexagons that straddle a straight crease bend; a step from
// an input without one is the plain step, bit for bit. The rule moves vertices only: the counts, the
// 3-valence and the topology are those of the plain step.

#include <dlfl/mesh.h>

namespace dlfl::detail {

/// Rounds of the `planarize` operation's moves (operations/detail/planarize_moves.h) that one step makes.
inline constexpr int lateral_planarize_rounds = 50;

/// True when two distinct surface faces that share an edge lie in one plane: unit normals within 1e-9 of
/// each other and each centroid within 1e-9 of the bounding-box diagonal of the other's plane. O(size).
bool has_flat_region(const Mesh& mesh);

/// `lateral_planarize_rounds` rounds of planarizing moves on `result`, except that a vertex on a hole face
/// never moves (so the boundary rule's curve stays exactly as it is). O(size) per round.
void planarize_new_faces(Mesh& result);

}  // namespace dlfl::detail
