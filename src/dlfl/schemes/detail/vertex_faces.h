#pragma once
// Internal to the schemes that make a face around every old vertex (dual, Doo-Sabin): the corners of those
// faces, in order.

#include <cstdint>
#include <span>

#include <dlfl/mesh.h>

namespace dlfl::detail {

/// Throws the TopologyError of `number_vertex_face_corners` for dense vertex `v` (a point sphere, or of
/// valence 1), naming `input`'s handle. Out of line: it is the cold path.
[[noreturn]] void refuse_vertex_face(const Mesh& input, const char* scheme, std::uint32_t v,
                                     bool point_sphere);

/// Gives the corners around each vertex of dense `m` (a compacted copy of `input`, or `input` itself)
/// consecutive slots, vertex after vertex from `first`: `slot[c]` for corner c, counter-clockwise seen from
/// outside (along `prev_around_vertex`), so that a face through them is oriented like the input;
/// `offsets[v]` is the first slot of vertex v and `offsets[V]` the slot after the last. Throws TopologyError
/// for a point sphere ("SCHEME: v3 is a point sphere (no edge)") and, with `refuse_valence_one`, a vertex of
/// valence 1 ("SCHEME: v3 has valence 1 (its face would have a single corner)"), naming `input`'s handles.
///
/// The general form gives corner c `slots_of(c)` consecutive slots (0 or more; the boundary rules give a
/// hole's corner two), `slot[c]` being the first; the valence-one refusal counts corners, not slots.
///
/// Inline: it runs once per corner inside the scheme's own pass, and a call boundary costs the schemes a few
/// percent (the loop reloads the mesh's arrays after every store).
///
/// Orientation. Let c be a corner at v in face f, p = prev(c). Seen from outside f is counter-clockwise, so
/// at v its interior is the angle swept counter-clockwise from the direction of edge(c) (towards next(c)) to
/// that of edge(p) (towards vertex(p)). Turning further counter-clockwise crosses edge(p) into the face of
/// opposite(p), whose corner at v is opposite(p) itself (it starts where p's edge ends): that is
/// prev_around_vertex(c). So listing the corners around v along prev_around_vertex is counter-clockwise.
template <class SlotsOf>
inline void number_vertex_face_corners(const Mesh& m, const Mesh& input, const char* scheme,
                                       std::uint32_t first, std::span<std::uint32_t> offsets,
                                       std::span<std::uint32_t> slot, bool refuse_valence_one,
                                       const SlotsOf& slots_of) {
  const auto nv = static_cast<std::uint32_t>(m.num_vertices());
  std::uint32_t next_slot = first;
  for (std::uint32_t v = 0; v < nv; ++v) {
    offsets[v] = next_slot;
    const CornerId start = m.corner(VertexId(v));
    if (!m.edge(start).valid()) refuse_vertex_face(input, scheme, v, true);
    CornerId c = start;
    std::uint32_t corners = 0;
    do {
      slot[c.index()] = next_slot;
      next_slot += slots_of(c);
      ++corners;
      c = m.prev_around_vertex(c);
    } while (c != start);
    if (refuse_valence_one && corners == 1) refuse_vertex_face(input, scheme, v, false);
  }
  offsets[nv] = next_slot;
}

/// One slot per corner.
inline void number_vertex_face_corners(const Mesh& m, const Mesh& input, const char* scheme,
                                       std::uint32_t first, std::span<std::uint32_t> offsets,
                                       std::span<std::uint32_t> slot, bool refuse_valence_one) {
  number_vertex_face_corners(m, input, scheme, first, offsets, slot, refuse_valence_one,
                             [](CornerId) { return std::uint32_t{1}; });
}

}  // namespace dlfl::detail
