#include <dlfl/schemes/doo_sabin.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <optional>
#include <vector>

#include <dlfl/dense_mesh.h>
#include <dlfl/errors.h>
#include <dlfl/mesh_assembler.h>
#include <dlfl/schemes/detail/boundary_points.h>
#include <dlfl/schemes/detail/scheme_origins.h>
#include <dlfl/schemes/detail/scheme_table.h>
#include <dlfl/schemes/detail/vertex_faces.h>

namespace dlfl {
namespace {

// Faces up to this size use a tabulated weight row (O(n^2) per face); larger ones the closed form (O(n)).
constexpr std::uint32_t max_tabulated = 64;

// Weight rows alpha_0 .. alpha_{n-1}, computed once per face size. cos is evaluated at min(k, n-k) so that
// alpha_k == alpha_{n-k} exactly.
class WeightTable {
 public:
  const double* row(std::uint32_t n) {
    auto& r = rows_[n];
    if (r.empty()) {
      r.resize(n);
      const double inv = 1.0 / (4.0 * n);
      for (std::uint32_t k = 0; k < n; ++k) {
        const std::uint32_t j = std::min(k, n - k);
        r[k] = (3.0 + 2.0 * std::cos(2.0 * std::numbers::pi * j / n)) * inv;
      }
      r[0] = 0.25 + 5.0 * inv;
    }
    return r.data();
  }

 private:
  std::array<std::vector<double>, max_tabulated + 1> rows_;
};

// New points of one face, with p[i] the point of its i-th corner and v its vertex positions.
//
// Closed form for large faces: alpha_k = 3/(4n) + cos(theta k)/(2n) + [k = 0]/4 with theta = 2 pi / n, and
// cos(theta (j - i)) = cos(theta j) cos(theta i) + sin(theta j) sin(theta i), so
//   p_i = v_i / 4 + 3/(4n) S + (cos(theta i) C + sin(theta i) D) / (2n),
// with S = sum v_j, C = sum cos(theta j) v_j, D = sum sin(theta j) v_j.
void face_points(const glm::dvec3* v, glm::dvec3* p, std::uint32_t n, WeightTable& table,
                 std::vector<double>& trig) {
  if (n <= max_tabulated) {
    const double* alpha = table.row(n);
    for (std::uint32_t i = 0; i < n; ++i) {
      glm::dvec3 sum = alpha[0] * v[i];
      std::uint32_t j = i + 1 == n ? 0 : i + 1;
      for (std::uint32_t k = 1; k < n; ++k) {
        sum += alpha[k] * v[j];
        j = j + 1 == n ? 0 : j + 1;
      }
      p[i] = sum;
    }
    return;
  }
  trig.resize(2 * std::size_t(n));
  glm::dvec3 s(0.0), c(0.0), d(0.0);
  for (std::uint32_t j = 0; j < n; ++j) {
    const double angle = 2.0 * std::numbers::pi * j / n;
    trig[2 * j] = std::cos(angle);
    trig[2 * j + 1] = std::sin(angle);
    s += v[j];
    c += trig[2 * j] * v[j];
    d += trig[2 * j + 1] * v[j];
  }
  const double w_sum = 3.0 / (4.0 * n), w_trig = 1.0 / (2.0 * n);
  for (std::uint32_t i = 0; i < n; ++i) {
    p[i] = 0.25 * v[i] + w_sum * s + w_trig * (trig[2 * i] * c + trig[2 * i + 1] * d);
  }
}

}  // namespace

Mesh doo_sabin(const Mesh& input, Origins* origins) { return doo_sabin(input, BoundaryOptions{}, origins); }

Mesh doo_sabin(const Mesh& input, const BoundaryOptions& boundary, Origins* origins) {
  std::optional<Mesh> storage;
  const Mesh& m = dense_mesh(input, storage);  // handles 0 .. count-1
  const auto [nv, ne, nf, nc] = dense_counts(m);

  // The boundary rule (curve, on a mesh with holes): a hole corner h gets two points, out(h) on its own edge
  // and in(h) on edge(prev(h)), both near vertex(h); at a sharp vertex they are one point, the vertex itself.
  // `in_point[c]` is the output vertex of the point of c that edge(prev(c)) leads to: c itself, but for a
  // split hole corner, whose in-point is numbered after the nc corner points.
  const bool curve = boundary.rule == BoundaryRule::curve && detail::has_hole(m);
  std::vector<bool> sharp, hole_corner, dissolved;
  std::vector<std::uint32_t> in_point;
  std::uint32_t nvert = nc;
  if (curve) {
    sharp = detail::sharp_boundary_vertices(m, boundary, "doo-sabin");
    hole_corner.assign(nc, false);
    dissolved.assign(nv, false);
    in_point.resize(nc);
    for (std::uint32_t k = 0; k < nc; ++k) {
      hole_corner[k] = m.is_hole(m.face(CornerId(k)));
      const bool split = hole_corner[k] && !sharp[m.vertex(CornerId(k)).index()];
      in_point[k] = split ? nvert++ : k;
    }
    // A sharp corner with one face: its V-face would be the 2-gon of its face's point and the kept vertex,
    // so it is left out and the two E-faces beside it share that edge.
    for (std::uint32_t v = 0; v < nv; ++v) {
      const CornerId c = m.corner(VertexId(v));
      const CornerId d = m.prev_around_vertex(c);
      dissolved[v] = sharp[v] && m.prev_around_vertex(d) == c && c != d &&
                     hole_corner[c.index()] != hole_corner[d.index()];
    }
  }
  const auto split = [&](std::uint32_t k) {
    return curve && hole_corner[k] && !sharp[m.vertex(CornerId(k)).index()];
  };
  const auto in_of = [&](std::uint32_t k) { return curve ? in_point[k] : k; };

  // Output corners: F-faces first (face by face; a split hole corner takes two, in(h) then out(h)), then
  // E-face e at e_base + 4e .. + 3, then V-faces (vertex by vertex; a split hole corner takes two, out(h)
  // then in(h)). slot[c] is the F-face corner leaving the point of c along edge(c); in_slot[c] that of in(c).
  // vslot[c] is c's first V-face corner; the one leaving towards the next corner around the vertex, across
  // edge(prev(c)), is vslot[c] + 1 for a split hole corner and vslot[c] otherwise.
  std::vector<std::uint32_t> offsets(std::size_t(nf) + ne + nv + 1);
  std::vector<std::uint32_t> slot(nc), vslot(nc), in_slot(curve ? nc : 0);
  std::uint32_t next_slot = 0;
  for (std::uint32_t f = 0; f < nf; ++f) {
    offsets[f] = next_slot;
    for (CornerId c : m.corners(FaceId(f))) {
      if (split(c.index())) in_slot[c.index()] = next_slot++;
      slot[c.index()] = next_slot++;
    }
  }
  const std::uint32_t e_base = next_slot, v_base = e_base + 4 * ne;
  for (std::uint32_t e = 0; e < ne; ++e) offsets[nf + e] = e_base + 4 * e;
  // V-faces counter-clockwise around v, oriented like the input.
  detail::number_vertex_face_corners(m, input, "doo-sabin", v_base, std::span(offsets).subspan(nf + ne),
                                     vslot, true, [&](CornerId c) -> std::uint32_t {
                                       if (!curve) return 1;
                                       if (dissolved[m.vertex(c).index()]) return 0;
                                       return split(c.index()) ? 2 : 1;
                                     });
  const auto vin = [&](std::uint32_t k) { return vslot[k] + (split(k) ? 1 : 0); };

  // Faces of dissolved V-faces are left out of the offsets (they would be empty).
  std::vector<std::uint32_t> face_of_vertex;  // output face of each V-face, when some are dissolved
  if (curve && std::find(dissolved.begin(), dissolved.end(), true) != dissolved.end()) {
    face_of_vertex.resize(nv);
    std::uint32_t w = nf + ne;
    for (std::uint32_t v = 0; v < nv; ++v) {
      face_of_vertex[v] = dissolved[v] ? ~0u : w;
      if (!dissolved[v]) offsets[w++] = offsets[nf + ne + v];
    }
    offsets[w] = offsets[nf + ne + nv];
    offsets.resize(std::size_t(w) + 1);
  }

  MeshAssembler out(nvert, offsets);

  // Points: output vertex k is the point of input corner k, computed in its face (for a hole under the
  // boundary rule: out(k)); the in-points of split hole corners follow.
  {
    WeightTable table;
    std::vector<glm::dvec3> v, p;
    std::vector<double> trig;
    for (std::uint32_t f = 0; f < nf; ++f) {
      if (curve && m.is_hole(FaceId(f))) continue;
      const std::uint32_t n = m.size(FaceId(f));
      v.resize(n);
      p.resize(n);
      std::uint32_t i = 0;
      for (CornerId c : m.corners(FaceId(f))) v[i++] = m.position(m.vertex(c));
      face_points(v.data(), p.data(), n, table, trig);
      i = 0;
      for (CornerId c : m.corners(FaceId(f))) out.set_position(c.index(), p[i++]);
    }
  }
  std::vector<std::uint32_t> kept;  // output vertices at sharp vertices, marked in the result
  if (curve) {
    // Chaikin along the boundary (clamped at sharp vertices): only the boundary polygon is read.
    for (std::uint32_t k = 0; k < nc; ++k) {
      if (!hole_corner[k]) continue;
      const CornerId h(k);
      const VertexId a = m.vertex(h), b = m.vertex(m.next(h)), z = m.vertex(m.prev(h));
      const glm::dvec3 pa = m.position(a);
      out.set_position(k, detail::chaikin_point(pa, m.position(b), sharp[a.index()], sharp[b.index()]));
      if (in_point[k] != k) {
        out.set_position(in_point[k], detail::chaikin_point(pa, m.position(z), false, sharp[z.index()]));
      } else {
        kept.push_back(k);
      }
    }
  }

  // Twins. Take an edge e from A to B; c0 = corner(e,0) (A to B, in face f0) and c1 = corner(e,1) (B to A,
  // in face f1). Seen from outside with A on the left and B on the right, f0 lies above the edge (a face is
  // counter-clockwise, so its interior is on the left of A -> B) and f1 below. The four points are
  // P(c0) near A above, P(next(c0)) near B above, P(c1) near B below, P(next(c1)) near A below; the E-face
  // runs counter-clockwise through them:
  //   E0 = P(c0) -> P(next(c1))   crosses to the V-face of A,
  //   E1 = P(next(c1)) -> P(c1)   crosses to the F-face of f1, whose corner c1 runs P(c1) -> P(next(c1)),
  //   E2 = P(c1) -> P(next(c0))   crosses to the V-face of B,
  //   E3 = P(next(c0)) -> P(c0)   crosses to the F-face of f0, whose corner c0 runs P(c0) -> P(next(c0)).
  // So the F-face corner of c is the twin of E3 (c on side 0 of its edge) or E1 (side 1).
  //
  // V-face of v: its corners follow prev_around_vertex, so the corner of c runs P(c) -> P(d) with
  // d = opposite(prev(c)): it crosses the edge g = edge(prev(c)), which arrives at v. If prev(c) is g's
  // side-0 corner, it is g's c0, B = v and c = next(c0), d = c1: the E-face side P(c1) -> P(next(c0)) is E2.
  // If prev(c) is the side-1 corner, it is c1, A = v, c = next(c1), d = c0: the side P(c0) -> P(next(c1)) is
  // E0. Conversely E0 pairs with the V-face corner of next(c1), and E2 with that of next(c0).
  //
  // Boundary rule: on a hole's side the points near A and B on e are in(next(c1)) and out(c1) (c1 the hole
  // corner), so the E-face reads P(next(c)) as the in-point of next(c). A split hole corner h adds the side
  // in(h) -> out(h) to its F-face and out(h) -> in(h) to the V-face (twins). A dissolved V-face's two
  // neighbouring E-face sides become twins of each other.
  const auto e_side_of_vin = [&](CornerId c) {  // the E-face side that c's V-face corner pairs with
    const CornerId p = m.prev(c);
    const EdgeId g = m.edge(p);
    return e_base + 4 * g.index() + (m.corner(g, 0) == p ? 2 : 0);
  };
  const auto v_twin = [&](CornerId n) {  // the twin of the E-face side that crosses to n's V-face corner
    if (curve && dissolved[m.vertex(n).index()]) return e_side_of_vin(m.prev_around_vertex(n));
    return vin(n.index());
  };
  for (std::uint32_t k = 0; k < nc; ++k) {
    const CornerId c(k);
    const EdgeId e = m.edge(c);
    out.set_corner(slot[k], k, e_base + 4 * e.index() + (m.corner(e, 0) == c ? 3 : 1));
    if (split(k)) {
      out.set_corner(in_slot[k], in_point[k], vslot[k]);
      out.set_corner(vslot[k], k, in_slot[k]);
    }
    if (!curve || !dissolved[m.vertex(c).index()]) out.set_corner(vin(k), in_of(k), e_side_of_vin(c));
  }
  for (std::uint32_t e = 0; e < ne; ++e) {
    const CornerId c0 = m.corner(EdgeId(e), 0), c1 = m.corner(EdgeId(e), 1);
    const CornerId n0 = m.next(c0), n1 = m.next(c1);
    const std::uint32_t q = e_base + 4 * e;
    out.set_corner(q + 0, c0.index(), v_twin(n1));
    out.set_corner(q + 1, in_of(n1.index()), slot[c1.index()]);
    out.set_corner(q + 2, c1.index(), v_twin(n0));
    out.set_corner(q + 3, in_of(n0.index()), slot[c0.index()]);
  }
  for (std::uint32_t f = 0; f < nf; ++f) {
    if (m.is_hole(FaceId(f))) out.set_hole(f, true);
  }
  Mesh result = out.finish();
  detail::mark_sharp(result, kept);
  if (origins) {
    const detail::InputHandles in(input);
    detail::reset_origins(*origins, result);
    for (std::uint32_t k = 0; k < nc; ++k) {
      origins->vertices[k] = in.corner(k);
      if (in_of(k) != k) origins->vertices[in_of(k)] = in.corner(k);
    }
    for (std::uint32_t f = 0; f < nf; ++f) origins->faces[f] = in.face(f);
    for (std::uint32_t e = 0; e < ne; ++e) origins->faces[nf + e] = in.edge(e);
    for (std::uint32_t v = 0; v < nv; ++v) {
      const std::uint32_t face = face_of_vertex.empty() ? nf + ne + v : face_of_vertex[v];
      if (face != ~0u) origins->faces[face] = in.vertex(v);
    }
    // The edge leaving each output corner: along an F-face, the side of its corner; around a V-face, the old
    // edge it crosses (see the twins above: E0 and E2 pair with V-faces, E1 and E3 with F-faces). The side
    // in(h) -> out(h) cutting off a hole's corner stems from that corner; the edge a dissolved V-face leaves
    // between its face's point and the kept vertex stems from its face's corner.
    std::vector<Origin> edge_of(result.num_corners());
    for (std::uint32_t e = 0; e < ne; ++e) {
      const std::uint32_t q = e_base + 4 * e;
      edge_of[q + 0] = edge_of[q + 2] = in.edge(e);
      edge_of[q + 1] = in.corner(m.corner(EdgeId(e), 1).index());
      edge_of[q + 3] = in.corner(m.corner(EdgeId(e), 0).index());
    }
    for (std::uint32_t k = 0; k < nc; ++k) {
      const CornerId c(k);
      edge_of[slot[k]] = in.corner(k);
      if (split(k)) edge_of[in_slot[k]] = edge_of[vslot[k]] = in.corner(k);
      if (!curve || !dissolved[m.vertex(c).index()]) {
        edge_of[vin(k)] = in.edge(m.edge(m.prev(c)).index());
      } else if (!hole_corner[k]) {
        edge_of[e_side_of_vin(c)] = edge_of[e_side_of_vin(m.prev_around_vertex(c))] = in.corner(k);
      }
    }
    detail::set_edge_origins(*origins, result, edge_of);
  }
  return result;
}

namespace detail {

SchemeSpec doo_sabin_scheme() {
  return boundary_scheme(
      doo_sabin, "doo-sabin",
      "Doo-Sabin: a point per corner; faces for every face, edge and vertex; every new vertex 4-valent",
      [](const MeshCounts& c) {  // V' = C = 2E, E' = 2C = 4E, F' = V + E + F (closed, or boundary=hole)
        return MeshCounts{2 * c.edges, 4 * c.edges, c.vertices + c.edges + c.faces};
      });
}

}  // namespace detail
}  // namespace dlfl
