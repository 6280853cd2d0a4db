#include <dlfl/schemes/sqrt3.h>

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
#include <dlfl/schemes/detail/sqrt3_steps.h>
#include <dlfl/schemes/detail/valence_weights.h>

namespace dlfl {

namespace {

// The origins of the output (see the header). Out of line so that the step's hot loops are compiled as they
// are without it (inlined, this block costs the edge pass an instruction per edge even when not asked for).
[[gnu::noinline]] void sqrt3_origins(const Mesh& input, const Mesh& m, const Mesh& result, Origins& origins) {
  const detail::InputHandles in(input);
  detail::reset_origins(origins, result);
  in.fill(origins.vertices, {Origin::Kind::vertex, Origin::Kind::face});
  in.fill(origins.faces, {Origin::Kind::corner});
  // Corner 3c + i of T(c) = (x, G, F): i = 0 runs x -> G, the edge from x to the face point of the face
  // across edge(c), whose corner at x is next(opposite(c)); 1 is the flipped edge(c); 2 runs F -> x.
  detail::set_edge_origins(origins, result, [&](std::uint32_t k) {
    const CornerId c(k / 3);
    switch (k % 3) {
      case 0:
        return in.corner(m.next(m.opposite(c)).index());
      case 1:
        return in.edge(m.edge(c).index());
      default:
        return in.corner(c.index());
    }
  });
}

}  // namespace

// Connectivity, in closed form from the input's navigation.
//
// Take an input edge with side corners s (at a, running a -> b, in triangle F = (a, b, x)) and o =
// opposite(s) (at b, running b -> a, in triangle G = (b, a, y)); write F and G also for their face points.
// Putting the face points in splits F into (a, b, F), (b, x, F), (x, a, F) and G likewise; both triangles on
// the edge keep the input's orientation. Together (a, b, F) and (b, a, G) bound the quadrilateral
// a -> G -> b -> F -> a (their union's boundary: a -> G, G -> b from the second, b -> F, F -> a from the
// first). Flipping the edge ab to the diagonal F G cuts that quadrilateral into (a, G, F) and (b, F, G),
// each still turning the same way. So every input corner c gives exactly one triangle,
//   T(c) = (vertex(c), G, F) with F = face point of face(c), G = face point of face(opposite(c)),
// and T(s), T(o) are the two triangles on the flipped edge. Output triangle c is T(c), corners 3c + i:
//   3c + 0 at vertex(c),               edge vertex(c) -> G
//   3c + 1 at G = V + face(opposite(c)), edge G -> F          (the flipped edge)
//   3c + 2 at F = V + face(c),            edge F -> vertex(c)
// For instance, unfolded into a plane with a = (0,0), b = (1,0), F = (1/2, h) above ab (inside the
// counter-clockwise triangle abx) and G = (1/2, -h) below it, (a, G, F) has signed area h / 2 > 0.
//
// Twins:
// - 3c + 1, G -> F: T(opposite(c)) = (b, F, G) has its corner 1 at F, running F -> G. Twin 3 opposite(c) + 1.
// - 3c + 2, F -> a: the other output edge between a and F lies in the triangle of the corner q at a across
//   the edge before c: q = opposite(prev(c)), whose edge(q) = edge(prev(c)) separates face(q) from F, so
//   T(q) = (a, F, face(q)) and its corner 0 runs a -> F. Twin 3 opposite(prev(c)) + 0.
// - 3c + 0, a -> G: the inverse of the previous rule. With r = next(opposite(c)) (the corner at a in G),
//   opposite(prev(r)) = opposite(opposite(c)) = c, so T(r)'s corner 2 runs G -> a. Twin 3 next(opposite(c))
//   + 2.
//
// Per input edge with side corners s0, s1 (s1 = opposite(s0)) these are, using prev(next(s)) = s:
//   3 s0 + 0 at vertex(s0), twin 3 next(s1) + 2;   3 next(s1) + 2 at V + face(s1), twin 3 s0 + 0;
//   3 s1 + 0 at vertex(s1), twin 3 next(s0) + 2;   3 next(s0) + 2 at V + face(s0), twin 3 s1 + 0;
//   3 s0 + 1 at V + face(s1), twin 3 s1 + 1;        3 s1 + 1 at V + face(s0), twin 3 s0 + 1.
// Every output corner is set exactly once (corner 0 and 1 of T(s) for the edge leaving s, corner 2 of T(r)
// for the edge leaving prev(r)), so one pass over the edges builds the whole connectivity.
Mesh sqrt3(const Mesh& input, Origins* origins) { return sqrt3(input, BoundaryOptions{}, origins); }

Mesh sqrt3(const Mesh& input, const BoundaryOptions& boundary, Origins* origins) {
  const bool curve = boundary.rule == BoundaryRule::curve;
  const detail::DenseTriangles dense(input, "sqrt3", "sqrt(3) subdivision",
                                     curve ? detail::TriangleHoles::any : detail::TriangleHoles::refused);
  const Mesh& m = dense.mesh();
  const auto marks = curve ? detail::sharp_marks(m, "sqrt3") : std::nullopt;
  if (curve && m.num_hole_faces() > 0) return detail::sqrt3_open(input, m, boundary, marks, origins);
  const auto [nv, ne, nf, nc] = dense_counts(m);  // nc = 3 nf
  const std::uint32_t face_base = nv;             // vertex of the face point of face f
  MeshAssembler out(std::size_t(nv) + nf, nc, 3);

  // Face points.
  for (std::uint32_t f = 0; f < nf; ++f) {
    const CornerId c0 = m.first_corner(FaceId(f));
    const CornerId c1 = m.next(c0);
    const CornerId c2 = m.next(c1);
    out.set_position(face_base + f,
                     (m.position(m.vertex(c0)) + m.position(m.vertex(c1)) + m.position(m.vertex(c2))) / 3.0);
  }

  // Edges: the whole connectivity, and the neighbour sums of the vertex rule.
  std::vector<glm::dvec3> sum(nv, glm::dvec3(0.0));
  std::vector<std::uint32_t> valence(nv, 0);
  for (std::uint32_t e = 0; e < ne; ++e) {
    const CornerId s0 = m.corner(EdgeId(e), 0), s1 = m.corner(EdgeId(e), 1);
    const std::uint32_t k0 = s0.index(), k1 = s1.index();
    const std::uint32_t a = m.vertex(s0).index(), b = m.vertex(s1).index();
    const std::uint32_t f0 = face_base + m.face(s0).index(), f1 = face_base + m.face(s1).index();
    const std::uint32_t n0 = m.next(s0).index(), n1 = m.next(s1).index();
    sum[a] += m.position(VertexId(b));
    sum[b] += m.position(VertexId(a));
    ++valence[a];
    ++valence[b];
    out.set_corner(3 * k0 + 0, a, 3 * n1 + 2);
    out.set_corner(3 * n1 + 2, f1, 3 * k0 + 0);
    out.set_corner(3 * k1 + 0, b, 3 * n0 + 2);
    out.set_corner(3 * n0 + 2, f0, 3 * k1 + 0);
    out.set_corner(3 * k0 + 1, f1, 3 * k1 + 1);
    out.set_corner(3 * k1 + 1, f0, 3 * k0 + 1);
  }

  detail::set_sqrt3_vertex_points(m, sum, valence, out);
  Mesh result = out.finish();
  if (curve) detail::carry_sharp_marks(marks, result, nv);
  if (origins) sqrt3_origins(input, m, result, *origins);
  return result;
}

namespace detail {

void set_sqrt3_vertex_points(const Mesh& m, std::span<const glm::dvec3> sum,
                             std::span<const std::uint32_t> valence, MeshAssembler& out) {
  // Kobbelt's weight a_n for valence n.
  static const ValenceWeights alpha_of(
      [](std::uint32_t n) { return (4.0 - 2.0 * std::cos(2.0 * std::numbers::pi / n)) / 9.0; });
  for (std::uint32_t v = 0; v < sum.size(); ++v) {
    const std::uint32_t n = valence[v];  // >= 2: no point spheres, no self-loops
    const double alpha = alpha_of(n);
    out.set_position(v, (1.0 - alpha) * m.position(VertexId(v)) + (alpha / n) * sum[v]);
  }
}

SchemeSpec sqrt3_scheme() {
  return boundary_scheme(
      sqrt3, "sqrt3",
      "Kobbelt's sqrt(3): a point per triangle and every old edge flipped, on triangle meshes",
      // V' = V + F, E' = 3E, F' = 3F (on open meshes under the curve rule, see the header)
      [](const MeshCounts& c) {
        return MeshCounts{c.vertices + c.faces, 3 * c.edges, 3 * c.faces};
      });
}

}  // namespace detail
}  // namespace dlfl
