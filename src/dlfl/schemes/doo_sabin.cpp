#include <dlfl/schemes/doo_sabin.h>

#include <array>
#include <cmath>
#include <numbers>
#include <optional>
#include <vector>

#include <dlfl/dense_mesh.h>
#include <dlfl/errors.h>
#include <dlfl/mesh_assembler.h>
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

Mesh doo_sabin(const Mesh& input, Origins* origins) {
  std::optional<Mesh> storage;
  const Mesh& m = dense_mesh(input, storage);  // handles 0 .. count-1
  const auto [nv, ne, nf, nc] = dense_counts(m);

  // Output corners: F-faces take 0 .. nc-1 (face by face), E-face e takes e_base + 4e .. + 3, V-faces take
  // v_base .. (vertex by vertex). slot[c] / vslot[c] is the output corner for input corner c in its F-face /
  // V-face.
  const std::uint32_t e_base = nc, v_base = nc + 4 * ne;
  std::vector<std::uint32_t> offsets(std::size_t(nf) + ne + nv + 1);
  std::vector<std::uint32_t> slot(nc), vslot(nc);
  std::uint32_t next_slot = 0;
  for (std::uint32_t f = 0; f < nf; ++f) {
    offsets[f] = next_slot;
    for (CornerId c : m.corners(FaceId(f))) slot[c.index()] = next_slot++;
  }
  for (std::uint32_t e = 0; e < ne; ++e) offsets[nf + e] = e_base + 4 * e;
  // V-faces counter-clockwise around v, oriented like the input; they end at 2 nc + 4 ne = 4 nc.
  detail::number_vertex_face_corners(m, input, "doo-sabin", v_base, std::span(offsets).subspan(nf + ne),
                                     vslot, true);

  MeshAssembler out(nc, offsets);

  // Points: output vertex k is the point of input corner k, computed in its face.
  {
    WeightTable table;
    std::vector<glm::dvec3> v, p;
    std::vector<double> trig;
    for (std::uint32_t f = 0; f < nf; ++f) {
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
  for (std::uint32_t k = 0; k < nc; ++k) {
    const CornerId c(k);
    const EdgeId e = m.edge(c);
    out.set_corner(slot[k], k, e_base + 4 * e.index() + (m.corner(e, 0) == c ? 3 : 1));
    const CornerId p = m.prev(c);
    const EdgeId g = m.edge(p);
    out.set_corner(vslot[k], k, e_base + 4 * g.index() + (m.corner(g, 0) == p ? 2 : 0));
  }
  for (std::uint32_t e = 0; e < ne; ++e) {
    const CornerId c0 = m.corner(EdgeId(e), 0), c1 = m.corner(EdgeId(e), 1);
    const CornerId n0 = m.next(c0), n1 = m.next(c1);
    const std::uint32_t q = e_base + 4 * e;
    out.set_corner(q + 0, c0.index(), vslot[n1.index()]);
    out.set_corner(q + 1, n1.index(), slot[c1.index()]);
    out.set_corner(q + 2, c1.index(), vslot[n0.index()]);
    out.set_corner(q + 3, n0.index(), slot[c0.index()]);
  }
  for (std::uint32_t f = 0; f < nf; ++f) {
    if (m.is_hole(FaceId(f))) out.set_hole(f, true);
  }
  Mesh result = out.finish();
  if (origins) {
    const detail::InputHandles in(input);
    detail::reset_origins(*origins, result);
    for (std::uint32_t k = 0; k < nc; ++k) origins->vertices[k] = in.corner(k);
    for (std::uint32_t f = 0; f < nf; ++f) origins->faces[f] = in.face(f);
    for (std::uint32_t e = 0; e < ne; ++e) origins->faces[nf + e] = in.edge(e);
    for (std::uint32_t v = 0; v < nv; ++v) origins->faces[nf + ne + v] = in.vertex(v);
    // The edge leaving each output corner: along an F-face, the side of its corner; around a V-face, the old
    // edge it crosses (see the twins above: E0 and E2 pair with V-faces, E1 and E3 with F-faces).
    std::vector<Origin> edge_of(4 * std::size_t(nc));
    for (std::uint32_t k = 0; k < nc; ++k) {
      edge_of[slot[k]] = in.corner(k);
      edge_of[vslot[k]] = in.edge(m.edge(m.prev(CornerId(k))).index());
    }
    for (std::uint32_t e = 0; e < ne; ++e) {
      const std::uint32_t q = e_base + 4 * e;
      edge_of[q + 0] = edge_of[q + 2] = in.edge(e);
      edge_of[q + 1] = in.corner(m.corner(EdgeId(e), 1).index());
      edge_of[q + 3] = in.corner(m.corner(EdgeId(e), 0).index());
    }
    detail::set_edge_origins(*origins, result, edge_of);
  }
  return result;
}

namespace detail {

SchemeSpec doo_sabin_scheme() {
  return parameterless_scheme(
      doo_sabin, "doo-sabin",
      "Doo-Sabin: a point per corner; faces for every face, edge and vertex; every new vertex 4-valent",
      [](const MeshCounts& c) {  // V' = C = 2E, E' = 2C = 4E, F' = V + E + F
        return MeshCounts{2 * c.edges, 4 * c.edges, c.vertices + c.edges + c.faces};
      });
}

}  // namespace detail
}  // namespace dlfl
