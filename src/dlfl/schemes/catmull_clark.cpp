#include <dlfl/schemes/catmull_clark.h>

#include <optional>
#include <vector>

#include <dlfl/dense_mesh.h>
#include <dlfl/errors.h>
#include <dlfl/mesh_assembler.h>
#include <dlfl/schemes/detail/boundary_curve.h>
#include <dlfl/schemes/detail/quad_split.h>
#include <dlfl/schemes/detail/scheme_table.h>

namespace dlfl {

namespace {

// The curve rule's connectivity (boundary_curve.h): the quad of surface corner c is (vertex point, edge point
// of edge(c), face point, edge point of edge(prev c)) as in assemble_quad_split, but numbered by `layout`,
// and each hole face stays one hole face whose sides are the halves of its edges.
void assemble_open_quads(const Mesh& m, const detail::OpenLayout& layout, std::uint32_t edge_base,
                         std::uint32_t face_base, MeshAssembler& out) {
  layout.set_half_edge_corners(m, edge_base, out);
  // The inner corners of each quad: at the edge point of edge(c) and at the face point.
  const auto nc = static_cast<std::uint32_t>(m.num_corners());
  for (std::uint32_t k = 0; k < nc; ++k) {
    const CornerId c(k);
    if (m.is_hole(m.face(c))) continue;
    const std::uint32_t q = layout.corner(c);
    out.set_corner(q + 1, edge_base + m.edge(c).index(), layout.corner(m.next(c)) + 2);
    out.set_corner(q + 2, face_base + layout.rank(m.face(c)), layout.corner(m.prev(c)) + 1);
  }
  layout.set_hole_flags(out);
}

// The curve rule's origins: those of the split of every face (quad_split_origins), without the face points
// and quads of hole faces, and with each hole face from itself.
void open_quad_origins(const Mesh& m, const Mesh& result, const detail::OpenLayout& layout,
                       const detail::InputHandles& in, Origins& origins) {
  const auto [nv, ne, nf, nc] = dense_counts(m);
  detail::reset_origins(origins, result);
  in.fill(origins.vertices, {Origin::Kind::vertex, Origin::Kind::edge});
  for (std::uint32_t f = 0; f < nf; ++f) {
    if (!m.is_hole(FaceId(f))) origins.vertices[nv + ne + layout.rank(FaceId(f))] = in.face(f);
  }
  layout.face_origins(m, in, origins);
  const auto edge_of = layout.edge_origins(
      m, in, [&](CornerId c, std::uint32_t side) { return detail::corner_polygon_side(m, in, c, side, 4); },
      {});
  detail::set_edge_origins(origins, result, edge_of);
}

}  // namespace

Mesh catmull_clark(const Mesh& input, Origins* origins) {
  return catmull_clark(input, BoundaryOptions{}, origins);
}

Mesh catmull_clark(const Mesh& input, const BoundaryOptions& boundary, Origins* origins) {
  std::optional<Mesh> storage;
  const Mesh& m = dense_mesh(input, storage);  // handles 0 .. count-1
  const auto [nv, ne, nf, nc] = dense_counts(m);
  for (std::uint32_t v = 0; v < nv; ++v) {
    if (m.is_point_sphere(VertexId(v))) {
      throw TopologyError("catmull-clark: " + to_string(VertexId(v)) + " is a point sphere (no edge)");
    }
  }
  const bool curve = boundary.rule == BoundaryRule::curve;
  const auto marks = curve ? detail::sharp_marks(m, "catmull-clark") : std::nullopt;
  // The curve rule on an open mesh: hole faces get no face point and stay whole.
  std::optional<detail::BoundaryVertices> open;
  std::optional<detail::OpenLayout> layout;
  if (curve && m.num_hole_faces() > 0) {
    open.emplace(m, boundary, marks);
    layout.emplace(m, 4, 0, [](FaceId) { return 2u; });
  }
  // A face without a face point. (A plain bool, so that the loops need not read the optional again after
  // every store.)
  const bool holes_kept = open.has_value();
  auto is_hole = [&](FaceId f) { return holes_kept && m.is_hole(f); };
  const std::uint32_t edge_base = nv, face_base = nv + ne;
  const std::uint32_t face_points = layout ? layout->num_surface_faces() : nf;
  MeshAssembler out = layout ? MeshAssembler(std::size_t(nv) + ne + face_points, layout->offsets())
                             : MeshAssembler(std::size_t(nv) + ne + nf, nc, 4);

  // Face points.
  detail::LargeVector<glm::dvec3> face_point(nf);
  for (std::uint32_t f = 0; f < nf; ++f) {
    if (is_hole(FaceId(f))) {
      face_point[f] = glm::dvec3(0.0);  // summed into boundary vertices, whose sums are not used
      continue;
    }
    glm::dvec3 sum(0.0);
    for (CornerId c : m.corners(FaceId(f))) sum += m.position(m.vertex(c));
    face_point[f] = sum / double(m.size(FaceId(f)));
    out.set_position(face_base + (holes_kept ? layout->rank(FaceId(f)) : f), face_point[f]);
  }
  // Edge points; under the curve rule, a boundary edge's is its midpoint (cubic B-spline rule).
  for (std::uint32_t e = 0; e < ne; ++e) {
    const EdgeId id(e);
    const FaceId f0 = m.face(id, 0), f1 = m.face(id, 1);
    const glm::dvec3 ends = m.position(m.from(id)) + m.position(m.to(id));
    out.set_position(edge_base + e, is_hole(f0) || is_hole(f1)
                                        ? ends / 2.0
                                        : (ends + face_point[f0.index()] + face_point[f1.index()]) / 4.0);
  }
  // Vertex points: (Q + 2R + (n-3) S) / n = (sum of face points + 2 sum of midpoints) / n^2 + (n-3) S / n.
  // Each corner at v contributes its face's point and the midpoint of its outgoing edge (each edge at v
  // leaves v at exactly one corner). Under the curve rule, boundary vertices have their own rule.
  detail::LargeVector<glm::dvec3> sums(nv, glm::dvec3(0.0));
  detail::LargeVector<std::uint32_t> valence(nv, 0);
  for (std::uint32_t k = 0; k < nc; ++k) {
    const CornerId c(k);
    const std::uint32_t v = m.vertex(c).index();
    const glm::dvec3 mid = 0.5 * (m.position(VertexId(v)) + m.position(m.vertex(m.next(c))));
    sums[v] += face_point[m.face(c).index()] + 2.0 * mid;
    ++valence[v];
  }
  for (std::uint32_t v = 0; v < nv; ++v) {
    const double n = valence[v];
    out.set_position(v, sums[v] / (n * n) + (n - 3.0) / n * m.position(VertexId(v)));
  }
  if (open) open->set_binary_vertex_points(m, out);

  // Quad k for corner k: (vertex point, edge point out, face point, edge point in).
  if (layout) {
    assemble_open_quads(m, *layout, edge_base, face_base, out);
  } else {
    detail::assemble_quad_split(m, out);
  }
  Mesh result = out.finish();
  if (curve) detail::carry_sharp_marks(marks, result, nv);
  if (origins && layout) {
    open_quad_origins(m, result, *layout, detail::InputHandles(input), *origins);
  } else if (origins) {
    detail::quad_split_origins(m, result, detail::InputHandles(input), *origins);
  }
  return result;
}

namespace detail {

SchemeSpec catmull_clark_scheme() {
  return boundary_scheme(
      catmull_clark, "catmull-clark",
      "Catmull-Clark: a quad per corner; smooth (C2 away from extraordinary points) on any polygon mesh",
      // V' = V + E + F, E' = 2E + C = 4E, F' = C = 2E (upper bounds under the curve rule: see the header)
      [](const MeshCounts& c) {
        return MeshCounts{c.vertices + c.edges + c.faces, 4 * c.edges, 2 * c.edges};
      });
}

}  // namespace detail
}  // namespace dlfl
