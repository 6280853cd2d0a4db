#include <dlfl/schemes/loop.h>

#include <cmath>
#include <numbers>
#include <vector>

#include <dlfl/dense_mesh.h>
#include <dlfl/mesh_assembler.h>
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
Mesh loop(const Mesh& input, Origins* origins) {
  const detail::DenseTriangles dense(input, "loop", "Loop subdivision", detail::TriangleHoles::allowed);
  const Mesh& m = dense.mesh();
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
    const std::uint32_t m0 = edge_base + m.edge(c0).index();
    const std::uint32_t m1 = edge_base + m.edge(c1).index();
    const std::uint32_t m2 = edge_base + m.edge(c2).index();
    const std::uint32_t z = central_base + 3 * f;
    out.set_corner(z + 0, m0, 3 * k1 + 1);
    out.set_corner(z + 1, m1, 3 * k2 + 1);
    out.set_corner(z + 2, m2, 3 * k0 + 1);
    out.set_corner(3 * k0 + 1, m0, z + 2);
    out.set_corner(3 * k1 + 1, m1, z + 0);
    out.set_corner(3 * k2 + 1, m2, z + 1);
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
  for (std::uint32_t e = 0; e < ne; ++e) {
    const CornerId s0 = m.corner(EdgeId(e), 0), s1 = m.corner(EdgeId(e), 1);
    const std::uint32_t a = m.vertex(s0).index(), b = m.vertex(s1).index();
    const glm::dvec3& pa = m.position(VertexId(a));
    const glm::dvec3& pb = m.position(VertexId(b));
    // The third vertex of a triangle is at the corner before the edge's side corner.
    const glm::dvec3& pc = m.position(m.vertex(m.prev(s0)));
    const glm::dvec3& pd = m.position(m.vertex(m.prev(s1)));
    out.set_position(edge_base + e, 0.375 * (pa + pb) + 0.125 * (pc + pd));
    sum[a] += pb;
    sum[b] += pa;
    ++valence[a];
    ++valence[b];
    const std::uint32_t n0 = m.next(s0).index(), n1 = m.next(s1).index();
    out.set_corner(3 * s0.index() + 0, a, 3 * n1 + 2);
    out.set_corner(3 * n1 + 2, edge_base + e, 3 * s0.index() + 0);
    out.set_corner(3 * s1.index() + 0, b, 3 * n0 + 2);
    out.set_corner(3 * n0 + 2, edge_base + e, 3 * s1.index() + 0);
  }

  // Vertex points, with Loop's weight beta for valence n.
  const detail::ValenceWeights beta_of([](std::uint32_t n) {
    const double c = 3.0 / 8.0 + std::cos(2.0 * std::numbers::pi / n) / 4.0;
    return (5.0 / 8.0 - c * c) / n;
  });
  for (std::uint32_t v = 0; v < nv; ++v) {
    const std::uint32_t n = valence[v];  // >= 2: no point spheres, no self-loops
    const double beta = beta_of(n);
    out.set_position(v, (1.0 - n * beta) * m.position(VertexId(v)) + beta * sum[v]);
  }
  Mesh result = out.finish();
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
        CornerId c = m.first_corner(FaceId((k - central_base) / 3));
        for (std::uint32_t j = 0; j <= (k - central_base) % 3; ++j) c = m.next(c);
        return in.corner(c.index());
      }
      return detail::corner_polygon_side(m, in, CornerId(k / 3), k % 3, 3);
    });
  }
  return result;
}

namespace detail {

SchemeSpec loop_scheme() {
  return parameterless_scheme(
      loop, "loop", "Loop: every triangle into four, on triangle meshes",
      [](const MeshCounts& c) {  // V' = V + E, E' = 2E + 3F, F' = 4F
        return MeshCounts{c.vertices + c.edges, 2 * c.edges + 3 * c.faces, 4 * c.faces};
      });
}

}  // namespace detail
}  // namespace dlfl
