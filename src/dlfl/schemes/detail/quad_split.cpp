#include <dlfl/schemes/detail/quad_split.h>

namespace dlfl::detail {

// Twins follow from the corners around the quad's corner: across the outgoing edge lies the quad of the next
// corner around the vertex, across the edge into the face point the quad of the next corner of the face, and
// so on.
void assemble_quad_split(const Mesh& m, MeshAssembler& out) {
  const auto nv = static_cast<std::uint32_t>(m.num_vertices());
  const auto ne = static_cast<std::uint32_t>(m.num_edges());
  const auto nc = static_cast<std::uint32_t>(m.num_corners());
  const std::uint32_t edge_base = nv, face_base = nv + ne;
  for (std::uint32_t k = 0; k < nc; ++k) {
    const CornerId c(k);
    const CornerId p = m.prev(c);
    const std::uint32_t q = 4 * k;
    out.set_corner(q + 0, m.vertex(c).index(), 4 * m.next(m.opposite(c)).index() + 3);
    out.set_corner(q + 1, edge_base + m.edge(c).index(), 4 * m.next(c).index() + 2);
    out.set_corner(q + 2, face_base + m.face(c).index(), 4 * p.index() + 1);
    out.set_corner(q + 3, edge_base + m.edge(p).index(), 4 * m.opposite(p).index() + 0);
  }
  for (std::uint32_t k = 0; k < nc; ++k) {
    if (m.is_hole(m.face(CornerId(k)))) out.set_hole(k, true);
  }
}

}  // namespace dlfl::detail
