#pragma once
// remove_2gons: every 2-gon removed by deleting one of its two edges. See docs/modeling.md.

#include <cstddef>

#include <dlfl/mesh.h>
#include <dlfl/operations/transaction.h>

namespace dlfl {

/// Removes every surface 2-gon (a face of two corners and two different edges) by deleting one of its
/// edges, which merges it into the face across that edge: E-k, F-k, V+0 for k 2-gons removed. The face
/// across keeps its corners, its shape and (the merge being onto a surface face) its flag. The edge deleted
/// is the first one along the 2-gon, from its first corner, whose face across is a surface face. Left
/// alone: hole 2-gons (removing one would close its boundary loop), 2-gons with a hole face across both
/// edges, and 2-gons whose two edges have the same face across (that face would be left on both sides of
/// the other edge; e.g. the two 2-gons of a component that is only them). Refuses nothing. Returns k.
/// O(F).
std::size_t remove_2gons(Transaction& tx);

}  // namespace dlfl
