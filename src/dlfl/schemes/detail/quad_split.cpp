#include <dlfl/schemes/detail/quad_split.h>

#include <dlfl/dense_mesh.h>
#include <dlfl/detail/parallel_for.h>

namespace dlfl::detail {

// Twins follow from the corners around the quad's corner: across the outgoing edge lies the quad of the next
// corner around the vertex, across the edge into the face point the quad of the next corner of the face, and
// so on.
void assemble_quad_split(const Mesh& m, MeshAssembler& out) {
  const auto [nv, ne, nf, nc] = dense_counts(m);
  const std::uint32_t edge_base = nv, face_base = nv + ne;
  parallel_for(nc, [&](std::size_t i) {
    const auto k = static_cast<std::uint32_t>(i);
    const CornerId c(k);
    const CornerId p = m.prev(c);
    const std::uint32_t q = 4 * k;
    out.set_corner(q + 0, m.vertex(c).index(), 4 * m.next(m.opposite(c)).index() + 3);
    out.set_corner(q + 1, edge_base + m.edge(c).index(), 4 * m.next(c).index() + 2);
    out.set_corner(q + 2, face_base + m.face(c).index(), 4 * p.index() + 1);
    out.set_corner(q + 3, edge_base + m.edge(p).index(), 4 * m.opposite(p).index() + 0);
  });
  for (std::uint32_t k = 0; k < nc; ++k) {
    if (m.is_hole(m.face(CornerId(k)))) out.set_hole(k, true);
  }
}

void quad_split_origins(const Mesh& m, const Mesh& out, const InputHandles& in, Origins& origins) {
  reset_origins(origins, out);
  in.fill(origins.vertices, {Origin::Kind::vertex, Origin::Kind::edge, Origin::Kind::face});
  in.fill(origins.faces, {Origin::Kind::corner});
  // Quad k's corners, in order: at the vertex point (edge along edge(k)), at the edge point of edge(k) (edge
  // into the face point), at the face point (edge out to the edge point of edge(prev k), corner prev(k)'s
  // inner edge), at the edge point of edge(prev k) (edge along edge(prev k)).
  set_edge_origins(origins, out, [&](std::uint32_t corner) {
    return corner_polygon_side(m, in, CornerId(corner / 4), corner % 4, 4);
  });
}

std::vector<Origin> quad_split_corner_origins(const Mesh& m, const InputHandles& in) {
  const auto nc = static_cast<std::uint32_t>(m.num_corners());
  std::vector<Origin> corners(4 * std::size_t(nc));
  for (std::uint32_t k = 0; k < 4 * nc; ++k) corners[k] = in.corner(k / 4);
  return corners;
}

}  // namespace dlfl::detail
