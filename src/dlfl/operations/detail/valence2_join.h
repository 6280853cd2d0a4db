#pragma once
// Internal to remove_valence2 and dissolve_coplanar: joining the two edges of a vertex of valence 2 into one
// edge (unsubdivide_edge), and the rules for when that is left undone.

#include <cstddef>
#include <span>

#include <dlfl/mesh.h>
#include <dlfl/operations/transaction.h>

namespace dlfl::detail {

/// True if v has valence 2 and its two edges can be joined into one: its two neighbours are different
/// vertices (else the joined edge would be a self-loop), and every edge already between them is the third
/// side of a triangle beside v (which the join turns into a 2-gon); any other such edge would be doubled by
/// the joined edge with no face between them. When the two edges do not continue each other (both start or
/// both end at v on side 0), the faces on the two sides of v must differ (see `join_edges_at`). O(valence
/// of a neighbour).
bool joinable(const Mesh& mesh, VertexId v);

/// Joins the two edges of a `joinable` vertex v: V-1, E-1, F+0. unsubdivide_edge needs one edge arriving
/// at v and one leaving it (on side 0); when both start or both end there, one of them is first deleted and
/// inserted again the other way round (a merge of the two faces beside v and the split that restores them;
/// the faces keep their hole flags, though the smaller may get a new handle). O(size of the smaller face
/// beside v).
void join_edges_at(Transaction& tx, VertexId v);

/// Joins every joinable vertex among `candidates` (in that order), and again any candidate that becomes
/// joinable when a neighbour is joined. Returns the number of vertices joined (removed).
std::size_t join_valence2_vertices(Transaction& tx, std::span<const VertexId> candidates);

}  // namespace dlfl::detail
