#pragma once
// Internal to the operations that take a mesh's edges out and put them back mirrored (reverse_orientation,
// the shells' inner copy): edge ends as numbers, and the corner of an edge at one of its ends.

#include <cstdint>
#include <limits>

#include <dlfl/mesh.h>

namespace dlfl::detail {

/// "No edge end".
inline constexpr std::uint32_t no_edge_end = std::numeric_limits<std::uint32_t>::max();

/// An edge end: edge e at the vertex of its side-s corner, numbered 2e + s.
inline std::uint32_t end_of(const Mesh& m, CornerId c) {
  const EdgeId e = m.edge(c);
  return 2 * e.index() + (m.corner(e, 0) == c ? 0 : 1);
}

/// The corner at vertex v that starts along edge e, one of whose ends is v (there are no self-loops).
inline CornerId corner_at(const Mesh& m, EdgeId e, VertexId v) {
  const CornerId c = m.corner(e, 0);
  return m.vertex(c) == v ? c : m.corner(e, 1);
}

}  // namespace dlfl::detail
