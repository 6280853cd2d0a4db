#pragma once
// Internal to collapse_edge and splice_corners: the parts of the link condition that both check for the two
// vertices they merge into one (docs/modeling.md, "collapse_edge"). Each is O(the valences involved).

#include <cstddef>
#include <string>
#include <vector>

#include <dlfl/mesh.h>

namespace dlfl::detail {

/// The distinct vertices joined by an edge to both u and v, u and v themselves left out, sorted.
std::vector<VertexId> common_neighbours(const Mesh& mesh, VertexId u, VertexId v);

/// Why the merge would double up an edge, or empty if it would not: the common neighbours of u and v (as
/// `common_neighbours` gives them) may only be `apexes`, the third vertices of the triangles beside the edge
/// that joins (or will join) u and v, whose two edges to the apex become a 2-gon. `ends` names u and v in
/// the message ("the end vertices").
std::string doubled_edges(const std::vector<VertexId>& common, const std::vector<VertexId>& apexes,
                          const char* ends);

/// The hole flags of the faces of the corners around a vertex, from `first` (included) along
/// `next_around_vertex` up to `stop` (excluded), appended to `flags`. `stop` must be on that rotation.
void append_hole_flags(const Mesh& mesh, CornerId first, CornerId stop, std::vector<bool>& flags);

/// How many separate runs of hole faces a cyclic sequence of face flags has: the number of times a boundary
/// passes through the vertex whose corners they are. 0 when all or none are holes.
std::size_t hole_runs(const std::vector<bool>& cyclic_flags);

/// The hole runs around v (see above); 1 for an ordinary boundary vertex.
std::size_t hole_runs(const Mesh& mesh, VertexId v);

}  // namespace dlfl::detail
