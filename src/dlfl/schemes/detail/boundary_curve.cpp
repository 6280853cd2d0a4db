#include <dlfl/schemes/detail/boundary_curve.h>

#include <dlfl/dense_mesh.h>

namespace dlfl::detail {

BoundaryVertices::BoundaryVertices(const Mesh& m, const BoundaryOptions& options,
                                   const std::optional<ConstAttribute<VertexId, bool>>& marks) {
  const auto [nv, ne, nf, nc] = dense_counts(m);
  std::vector<std::uint32_t> hole_corners(nv, 0), valence(nv, 0);
  for (std::uint32_t k = 0; k < nc; ++k) {
    const std::uint32_t v = m.vertex(CornerId(k)).index();
    ++valence[v];  // each edge at v leaves v at exactly one corner
    hole_corners[v] += m.is_hole(m.face(CornerId(k)));
  }
  kinds_.assign(nv, Kind::interior);
  for (std::uint32_t v = 0; v < nv; ++v) {
    if (hole_corners[v] == 0) continue;
    const bool sharp =
        hole_corners[v] > 1 || (marks && (*marks)[VertexId(v)]) || (options.sharp_corners && valence[v] == 2);
    kinds_[v] = sharp ? Kind::sharp : Kind::smooth;
  }
}

glm::dvec3 BoundaryVertices::before(const Mesh& m, CornerId c) const {
  const glm::dvec3& p = m.position(m.vertex(c));
  return is_sharp(m.vertex(c).index()) ? 2.0 * p - m.position(m.vertex(m.next(c)))
                                       : m.position(m.vertex(m.prev(c)));
}

glm::dvec3 BoundaryVertices::after(const Mesh& m, CornerId c) const {
  const glm::dvec3& p = m.position(m.vertex(c));
  return is_sharp(m.vertex(c).index()) ? 2.0 * p - m.position(m.vertex(m.prev(c)))
                                       : m.position(m.vertex(m.next(c)));
}

void BoundaryVertices::set_binary_vertex_points(const Mesh& m, MeshAssembler& out) const {
  for (FaceId h : m.faces()) {
    if (!m.is_hole(h)) continue;
    for (CornerId c : m.corners(h)) {
      const std::uint32_t v = m.vertex(c).index();
      const glm::dvec3& p = m.position(VertexId(v));
      out.set_position(v, is_sharp(v) ? p : (before(m, c) + 6.0 * p + after(m, c)) / 8.0);
    }
  }
}

void carry_sharp_marks(const std::optional<ConstAttribute<VertexId, bool>>& marks, Mesh& result,
                       std::uint32_t num_vertices, const BoundaryVertices* boundary) {
  if (!marks && !boundary) return;  // nothing to carry (a closed mesh without marks)
  std::optional<VertexAttribute<bool>> out;
  if (marks) out = result.add_vertex_attribute<bool>(sharp_vertex_attribute, false);
  for (std::uint32_t v = 0; v < num_vertices; ++v) {
    const bool marked = (marks && (*marks)[VertexId(v)]) || (boundary && boundary->is_sharp(v));
    if (!marked) continue;
    if (!out) out = result.add_vertex_attribute<bool>(sharp_vertex_attribute, false);
    (*out)[VertexId(v)] = true;
  }
}

OpenLayout::OpenLayout(const Mesh& m, std::uint32_t corner_sides, std::uint32_t face_sides,
                       const std::function<std::uint32_t(FaceId)>& hole_sides)
    : corner_sides_(corner_sides), face_sides_(face_sides) {
  const auto [nv, ne, nf, nc] = dense_counts(m);
  first_.resize(nc);
  rank_.resize(nf);
  offsets_.push_back(0);
  std::uint32_t next = 0;  // the next output corner
  for (std::uint32_t k = 0; k < nc; ++k) {
    if (m.is_hole(m.face(CornerId(k)))) continue;
    first_[k] = next;
    next += corner_sides;
    offsets_.push_back(next);
  }
  face_polygons_ = next;
  for (std::uint32_t f = 0; f < nf; ++f) {
    if (m.is_hole(FaceId(f))) continue;
    rank_[f] = surface_faces_++;
    if (face_sides == 0) continue;
    next += face_sides;
    offsets_.push_back(next);
  }
  first_hole_face_ = static_cast<std::uint32_t>(offsets_.size() - 1);
  std::uint32_t holes = 0;
  for (std::uint32_t f = 0; f < nf; ++f) {
    if (!m.is_hole(FaceId(f))) continue;
    rank_[f] = holes++;
    const std::uint32_t sides = hole_sides(FaceId(f));
    hole_sides_.push_back(sides);
    for (CornerId c : m.corners(FaceId(f))) {
      first_[c.index()] = next;
      next += sides;
    }
    offsets_.push_back(next);
  }
}

// Per edge with sides s0 (a -> b) and s1 (b -> a): the half at a runs a -> m from leaving(s0) and m -> a
// from arriving(next s1); the half at b likewise. A hole side's run is leaving(s), then arriving(next s).
void OpenLayout::set_half_edge_corners(const Mesh& m, std::uint32_t edge_base, MeshAssembler& out) const {
  const auto ne = static_cast<std::uint32_t>(m.num_edges());
  for (std::uint32_t e = 0; e < ne; ++e) {
    const CornerId s0 = m.corner(EdgeId(e), 0), s1 = m.corner(EdgeId(e), 1);
    const std::uint32_t in0 = arriving(m, m.next(s0)), in1 = arriving(m, m.next(s1));
    out.set_corner(leaving(s0), m.vertex(s0).index(), in1);
    out.set_corner(in1, edge_base + e, leaving(s0));
    out.set_corner(leaving(s1), m.vertex(s1).index(), in0);
    out.set_corner(in0, edge_base + e, leaving(s1));
  }
}

void OpenLayout::set_hole_flags(MeshAssembler& out) const {
  for (auto f = first_hole_face_; f + 1 < offsets_.size(); ++f) out.set_hole(f, true);
}

void OpenLayout::face_origins(const Mesh& m, const InputHandles& in, Origins& origins) const {
  const auto [nv, ne, nf, nc] = dense_counts(m);
  std::uint32_t polygon = 0;
  for (std::uint32_t k = 0; k < nc; ++k) {
    if (!m.is_hole(m.face(CornerId(k)))) origins.faces[polygon++] = in.corner(k);
  }
  for (std::uint32_t f = 0; f < nf; ++f) {
    if (m.is_hole(FaceId(f))) {
      origins.faces[hole_face(FaceId(f))] = in.face(f);
    } else if (face_sides_ > 0) {
      origins.faces[polygon + rank_[f]] = in.face(f);
    }
  }
}

std::vector<Origin> OpenLayout::edge_origins(
    const Mesh& m, const InputHandles& in, const std::function<Origin(CornerId, std::uint32_t)>& of_surface,
    const std::function<Origin(FaceId, std::uint32_t)>& of_face) const {
  const auto [nv, ne, nf, nc] = dense_counts(m);
  std::vector<Origin> edge_of(offsets_.back());
  for (std::uint32_t k = 0; k < nc; ++k) {
    const CornerId c(k);
    const bool hole = m.is_hole(m.face(c));
    const std::uint32_t end = first_[k] + (hole ? hole_sides_[rank_[m.face(c).index()]] : corner_sides_);
    for (std::uint32_t i = first_[k]; i < end; ++i) {
      edge_of[i] = hole ? in.edge(m.edge(c).index()) : of_surface(c, i - first_[k]);
    }
  }
  if (face_sides_ > 0) {
    for (std::uint32_t f = 0; f < nf; ++f) {
      if (m.is_hole(FaceId(f))) continue;
      for (std::uint32_t i = 0; i < face_sides_; ++i)
        edge_of[face_polygon(FaceId(f)) + i] = of_face(FaceId(f), i);
    }
  }
  return edge_of;
}

}  // namespace dlfl::detail
