#pragma once
// The honeycomb's `planarize` rule (docs/lateral_artifacts.md), shared by honeycomb and honeycomb-zw: a
// non-stationary planarization against the bricklayers' problem of Akleman and Srinivasan, "Honeycomb
// subdivision", section 5. The step from a control mesh (not yet 3-valent) with a flat region (two faces
// that share an edge and lie in one plane), where the faces that straddle a straight crease bend, planarizes
// its new faces, and keeps that only if it bends no more than the plain step (no more concave edges, no
// larger mean dihedral angle); every other step is the plain step, bit for bit. The rule moves vertices
// only: the counts, the 3-valence and the topology are those of the plain step.

#include <dlfl/mesh.h>

namespace dlfl::detail {

/// Rounds of the `planarize` operation's moves (analysis/detail/planarize_moves.h) that one step makes.
inline constexpr int lateral_planarize_rounds = 50;

/// True when two distinct surface faces that share an edge lie in one plane: unit normals within 1e-9 of
/// each other and each centroid within 1e-9 of the bounding-box diagonal of the other's plane. O(size).
bool has_flat_region(const Mesh& mesh);

/// Whether a step from `mesh` runs the rule: `mesh` is a control mesh (an inner vertex, not on a hole, whose
/// valence is not 3; after one honeycomb step every inner vertex is 3-valent, so the rule acts on the first
/// step only) and has a flat region. O(size).
bool lateral_rule_applies(const Mesh& mesh);

/// `lateral_planarize_rounds` rounds of planarizing moves on `result` (a step's plain result), except that a
/// vertex on a hole face never moves (so the boundary rule's curve stays exactly as it is); kept only if they
/// make neither more concave edges nor a larger mean dihedral angle (analysis/concave_edges.h) than the plain
/// result, which is otherwise restored bit for bit. True when kept. O(size) per round.
bool planarize_new_faces(Mesh& result);

}  // namespace dlfl::detail
