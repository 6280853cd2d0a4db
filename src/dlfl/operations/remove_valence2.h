#pragma once
// remove_valence2: every vertex of valence 2 taken out by joining its two edges into one (unsubdivide_edge).
// See docs/modeling.md.

#include <cstddef>

#include <dlfl/mesh.h>
#include <dlfl/operations/transaction.h>

namespace dlfl {

/// Joins the two edges of every vertex of valence 2 into one edge, removing the vertex: V-k, E-k, F+0 for k
/// vertices joined (each face beside such a vertex loses a corner). Refuses nothing; a vertex is left when
/// its two neighbours are one vertex (the joined edge would be a self-loop), when its neighbours are already
/// joined by an edge that is not the third side of a triangle beside it (the joined edge would double that
/// edge with no face between them), or when both its edges run the same way and it has one face on both
/// sides (on a dangling chain or a bridge, where no re-drawn edge can turn them). A vertex whose neighbour
/// is joined is looked at again. Boundary vertices are joined like any other (an open grid's corners go).
/// Returns k. O(V) plus the valences of the neighbours and, where an edge must be turned round, the size of
/// the smaller face beside it.
std::size_t remove_valence2(Transaction& tx);

}  // namespace dlfl
