#include <dlfl/schemes/loop.h>

#include <cmath>
#include <numbers>
#include <optional>
#include <span>
#include <vector>

#include <dlfl/dense_mesh.h>
#include <dlfl/mesh_assembler.h>
#include <dlfl/schemes/detail/boundary_curve.h>
#include <dlfl/schemes/detail/require_triangles.h>
#include <dlfl/schemes/detail/scheme_origins.h>
#include <dlfl/schemes/detail/scheme_table.h>
#include <dlfl/schemes/detail/valence_weights.h>

namespace dlfl {

// Connectivity, in closed form from the input's navigation.
//
// Notation: input triangle f has corners c0, c1, c2 (c0 = first_corner(f), c1 = next(c0), c2 = next(c1)) at
// vertices a, b, x, counter-clockwise; m(e) is the edge point of edge e, so m(edge(c0)) = m_ab,
// m(edge(c1)) = m_bx, m(edge(c2)) = m_xa. Output corner 3t + i is corner i of output triangle t.
//
//   corner triangle T(c) = triangle c:      (a, m_ab, m_xa) for c = c0, i.e.
//     3c + 0 at vertex(c),               edge vertex(c) -> m(edge(c))         (half of the old edge(c))
//     3c + 1 at m(edge(c)),              edge m(edge(c)) -> m(edge(prev(c)))  (inner edge)
//     3c + 2 at m(edge(prev(c))),        edge m(edge(prev(c))) -> vertex(c)   (half of the old edge(prev(c)))
//   central triangle Z(f) = triangle C + f: (m_ab, m_bx, m_xa), i.e.
//     3(C + f) + j at m(edge(cj)),       edge m(edge(cj)) -> m(edge(c(j+1)))
//
// Both turn the way abx does: (a, m_ab, m_xa) is abx scaled by 1/2 about a, and (m_ab, m_bx, m_xa) is
// (x, a, b) scaled by -1/2 about the centroid (a half turn in the plane of abx, which keeps the turning
// sense). So the orientation is the input's.
//
// Twins (the corner across each output edge, running the other way):
// - 3c + 1, m(edge(c)) -> m(edge(prev c)), inner edge of f: the central corner that runs
//   m(edge(prev c)) -> m(edge(c)) is the one at the edge point of prev(c), slot j - 1 of Z(f) when c = cj.
//   Conversely 3(C + f) + j has twin 3 c(j+1) + 1, since prev(c(j+1)) = cj.
// - 3c + 0, a -> m(edge(c)): let o = opposite(c), the corner at b in the triangle across edge(c), whose edge
//   runs b -> a. next(o) is the corner at a there, and prev(next(o)) = o, so T(next(o)) = (a, ...,
//   m(edge(o))) with m(edge(o)) = m(edge(c)); its corner 2 runs m(edge(c)) -> a. Twin: 3 next(opposite(c))
//   + 2.
// - 3c + 2, m(edge(prev c)) -> a: the triangle across edge(prev(c)) has q = opposite(prev(c)) at a, with
//   edge(q) = edge(prev(c)); T(q)'s corner 0 runs a -> m(edge(q)). Twin: 3 opposite(prev(c)) + 0.
//   The two rules are inverse: for r = next(opposite(c)), opposite(prev(r)) = opposite(opposite(c)) = c.
//
// Per input edge e with side corners s0 = corner(e,0) (a -> b) and s1 = corner(e,1) (b -> a), these give:
//   3 s0 + 0 at a with twin 3 next(s1) + 2;     3 next(s1) + 2 at m(e) with twin 3 s0 + 0;
//   3 s1 + 0 at b with twin 3 next(s0) + 2;     3 next(s0) + 2 at m(e) with twin 3 s1 + 0,
// since prev(next(s)) = s, so edge(prev(next(s))) = e. So one pass over the faces fills the inner corners
// (3c + 1 and the central triangles) and one pass over the edges fills the rest, with the edge points.
namespace {

// Loop's weight beta for valence n (Loop's original weights).
const auto& loop_beta() {
  static const detail::ValenceWeights beta([](std::uint32_t n) {
    const double c = 3.0 / 8.0 + std::cos(2.0 * std::numbers::pi / n) / 4.0;
    return (5.0 / 8.0 - c * c) / n;
  });
  return beta;
}

// The edge point of an inner edge a b whose triangles have the third vertices c and d.
glm::dvec3 edge_point(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c, const glm::dvec3& d) {
  return 0.375 * (a + b) + 0.125 * (c + d);
}

// The third vertex of the triangle of side corner s (at the corner before it).
const glm::dvec3& third(const Mesh& m, CornerId s) { return m.position(m.vertex(m.prev(s))); }

// One pass over the edges: the edge points (under the curve rule, `open`, a boundary edge's at its midpoint),
// the neighbour sums and valences of the vertex rule, and `per_edge(e, s0, s1)` for whatever else a step
// builds per edge.
template <bool open, class PerEdge>
void edge_pass(const Mesh& m, std::uint32_t edge_base, MeshAssembler& out, std::span<glm::dvec3> sum,
               std::span<std::uint32_t> valence, const PerEdge& per_edge) {
  const auto ne = static_cast<std::uint32_t>(m.num_edges());
  for (std::uint32_t e = 0; e < ne; ++e) {
    const CornerId s0 = m.corner(EdgeId(e), 0), s1 = m.corner(EdgeId(e), 1);
    const std::uint32_t a = m.vertex(s0).index(), b = m.vertex(s1).index();
    const glm::dvec3& pa = m.position(VertexId(a));
    const glm::dvec3& pb = m.position(VertexId(b));
    const bool boundary_edge = open && (m.is_hole(m.face(s0)) || m.is_hole(m.face(s1)));
    out.set_position(edge_base + e,
                     boundary_edge ? 0.5 * (pa + pb) : edge_point(pa, pb, third(m, s0), third(m, s1)));
    sum[a] += pb;
    sum[b] += pa;
    ++valence[a];
    ++valence[b];
    per_edge(e, s0, s1);
  }
}

// The vertex points 0 .. V-1 from the sums of each vertex's neighbours and its valence.
void set_vertex_points(const Mesh& m, std::span<const glm::dvec3> sum, std::span<const std::uint32_t> valence,
                       MeshAssembler& out) {
  const auto& beta_of = loop_beta();
  for (std::uint32_t v = 0; v < sum.size(); ++v) {
    const std::uint32_t n = valence[v];  // >= 2: no point spheres, no self-loops
    const double beta = beta_of(n);
    out.set_position(v, (1.0 - n * beta) * m.position(VertexId(v)) + beta * sum[v]);
  }
}

// The central triangle of a face (first corner z, at the edge points m0, m1, m2 of its corners' edges) and
// the inner corners (k + 1) of its corner triangles, whose first corners are k0, k1, k2. Inlined: it runs for
// every face of the hot loop.
[[gnu::always_inline]] inline void set_central_triangle(MeshAssembler& out, std::uint32_t z, std::uint32_t k0,
                                                        std::uint32_t k1, std::uint32_t k2, std::uint32_t m0,
                                                        std::uint32_t m1, std::uint32_t m2) {
  out.set_corner(z + 0, m0, k1 + 1);
  out.set_corner(z + 1, m1, k2 + 1);
  out.set_corner(z + 2, m2, k0 + 1);
  out.set_corner(k0 + 1, m0, z + 2);
  out.set_corner(k1 + 1, m1, z + 0);
  out.set_corner(k2 + 1, m2, z + 1);
}

// The origin of the edge leaving corner i of the central triangle of face f (its twin is the inner corner
// of the corner triangle of c(i+1), whose corner it names).
Origin central_edge_origin(const Mesh& m, const detail::InputHandles& in, FaceId f, std::uint32_t i) {
  CornerId c = m.first_corner(f);
  for (std::uint32_t j = 0; j <= i; ++j) c = m.next(c);
  return in.corner(c.index());
}

// The curve rule on an open mesh (boundary_curve.h): hole faces of any size stay whole, their sides halved;
// the corner triangles and central triangles of the surface faces are numbered by an OpenLayout.
Mesh loop_open(const Mesh& input, const Mesh& m, const BoundaryOptions& boundary,
               const std::optional<ConstAttribute<VertexId, bool>>& marks, Origins* origins) {
  const auto [nv, ne, nf, nc] = dense_counts(m);
  const detail::BoundaryVertices open(m, boundary, marks);
  const detail::OpenLayout layout(m, 3, 3, [](FaceId) { return 2u; });
  const std::uint32_t edge_base = nv;
  MeshAssembler out(std::size_t(nv) + ne, layout.offsets());
  for (std::uint32_t f = 0; f < nf; ++f) {
    if (m.is_hole(FaceId(f))) continue;
    const CornerId c0 = m.first_corner(FaceId(f));
    const CornerId c1 = m.next(c0);
    const CornerId c2 = m.next(c1);
    set_central_triangle(out, layout.face_polygon(FaceId(f)), layout.corner(c0), layout.corner(c1),
                         layout.corner(c2), edge_base + m.edge(c0).index(), edge_base + m.edge(c1).index(),
                         edge_base + m.edge(c2).index());
  }
  layout.set_half_edge_corners(m, edge_base, out);
  layout.set_hole_flags(out);

  // Edge points (a boundary edge's is its midpoint) and the neighbour sums of the interior vertex rule.
  std::vector<glm::dvec3> sum(nv, glm::dvec3(0.0));
  std::vector<std::uint32_t> valence(nv, 0);
  edge_pass<true>(m, edge_base, out, sum, valence, [](std::uint32_t, CornerId, CornerId) {});
  set_vertex_points(m, sum, valence, out);
  open.set_binary_vertex_points(m, out);
  Mesh result = out.finish();
  detail::carry_sharp_marks(marks, result, nv);
  if (origins) {
    const detail::InputHandles in(input);
    detail::reset_origins(*origins, result);
    in.fill(origins->vertices, {Origin::Kind::vertex, Origin::Kind::edge});
    layout.face_origins(m, in, *origins);
    detail::set_edge_origins(
        *origins, result,
        layout.edge_origins(
            m, in, [&](CornerId c, std::uint32_t i) { return detail::corner_polygon_side(m, in, c, i, 3); },
            [&](FaceId f, std::uint32_t i) { return central_edge_origin(m, in, f, i); }));
  }
  return result;
}

}  // namespace

Mesh loop(const Mesh& input, Origins* origins) { return loop(input, BoundaryOptions{}, origins); }

Mesh loop(const Mesh& input, const BoundaryOptions& boundary, Origins* origins) {
  const bool curve = boundary.rule == BoundaryRule::curve;
  const detail::DenseTriangles dense(input, "loop", "Loop subdivision",
                                     curve ? detail::TriangleHoles::any : detail::TriangleHoles::triangles);
  const Mesh& m = dense.mesh();
  const auto marks = curve ? detail::sharp_marks(m, "loop") : std::nullopt;
  if (curve && m.num_hole_faces() > 0) return loop_open(input, m, boundary, marks, origins);
  const auto [nv, ne, nf, nc] = dense_counts(m);  // nc = 3 nf
  const std::uint32_t central_base = 3 * nc;      // first corner of the central triangles
  const std::uint32_t edge_base = nv;             // vertex of the edge point of edge e
  MeshAssembler out(std::size_t(nv) + ne, std::size_t(nc) + nf, 3);

  // Faces: inner corners of the corner triangles, and the central triangles.
  for (std::uint32_t f = 0; f < nf; ++f) {
    const CornerId c0 = m.first_corner(FaceId(f));
    const CornerId c1 = m.next(c0);
    const CornerId c2 = m.next(c1);
    const std::uint32_t k0 = c0.index(), k1 = c1.index(), k2 = c2.index();
    set_central_triangle(out, central_base + 3 * f, 3 * k0, 3 * k1, 3 * k2, edge_base + m.edge(c0).index(),
                         edge_base + m.edge(c1).index(), edge_base + m.edge(c2).index());
    if (m.is_hole(FaceId(f))) [[unlikely]] {
      out.set_hole(k0, true);
      out.set_hole(k1, true);
      out.set_hole(k2, true);
      out.set_hole(nc + f, true);
    }
  }

  // Edges: edge points, the outer corners, and the neighbour sums of the vertex rule.
  std::vector<glm::dvec3> sum(nv, glm::dvec3(0.0));
  std::vector<std::uint32_t> valence(nv, 0);
  edge_pass<false>(m, edge_base, out, sum, valence, [&](std::uint32_t e, CornerId s0, CornerId s1) {
    const std::uint32_t n0 = m.next(s0).index(), n1 = m.next(s1).index();
    out.set_corner(3 * s0.index() + 0, m.vertex(s0).index(), 3 * n1 + 2);
    out.set_corner(3 * n1 + 2, edge_base + e, 3 * s0.index() + 0);
    out.set_corner(3 * s1.index() + 0, m.vertex(s1).index(), 3 * n0 + 2);
    out.set_corner(3 * n0 + 2, edge_base + e, 3 * s1.index() + 0);
  });
  set_vertex_points(m, sum, valence, out);
  Mesh result = out.finish();
  if (curve) detail::carry_sharp_marks(marks, result, nv);
  if (origins) {
    const detail::InputHandles in(input);
    detail::reset_origins(*origins, result);
    in.fill(origins->vertices, {Origin::Kind::vertex, Origin::Kind::edge});
    in.fill(origins->faces, {Origin::Kind::corner, Origin::Kind::face});
    // Corner 3c + i of a corner triangle: i = 0 runs along edge(c), 1 is the inner edge, 2 runs along
    // edge(prev c). A central corner is never an edge's side 0 (its twin 3c + 1 is smaller), but would name
    // its twin's corner c(j+1).
    detail::set_edge_origins(*origins, result, [&](std::uint32_t k) {
      if (k >= central_base) {
        return central_edge_origin(m, in, FaceId((k - central_base) / 3), (k - central_base) % 3);
      }
      return detail::corner_polygon_side(m, in, CornerId(k / 3), k % 3, 3);
    });
  }
  return result;
}

namespace detail {

SchemeSpec loop_scheme() {
  // V' = V + E, E' = 2E + 3F, F' = 4F (upper bounds under the curve rule: see the header)
  return boundary_scheme(loop, "loop", "Loop: every triangle into four, on triangle meshes",
                         [](const MeshCounts& c) {
                           return MeshCounts{c.vertices + c.edges, 2 * c.edges + 3 * c.faces, 4 * c.faces};
                         });
}

}  // namespace detail
}  // namespace dlfl
