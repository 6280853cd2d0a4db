#pragma once
// Internal to the schemes that make a face around every old vertex (dual, Doo-Sabin): the corners of those
// faces, in order.

#include <cstdint>
#include <span>

#include <dlfl/mesh.h>

namespace dlfl::detail {

/// Gives the corners around each vertex of dense `m` (a compacted copy of `input`, or `input` itself)
/// consecutive slots, vertex after vertex from `first`: `slot[c]` for corner c, counter-clockwise seen from
/// outside (along `prev_around_vertex`), so that a face through them is oriented like the input;
/// `offsets[v]` is the first slot of vertex v and `offsets[V]` the slot after the last. Throws TopologyError
/// for a point sphere ("SCHEME: v3 is a point sphere (no edge)") and, with `refuse_valence_one`, a vertex of
/// valence 1 ("SCHEME: v3 has valence 1 (its face would have a single corner)"), naming `input`'s handles.
void number_vertex_face_corners(const Mesh& m, const Mesh& input, const char* scheme, std::uint32_t first,
                                std::span<std::uint32_t> offsets, std::span<std::uint32_t> slot,
                                bool refuse_valence_one);

}  // namespace dlfl::detail
