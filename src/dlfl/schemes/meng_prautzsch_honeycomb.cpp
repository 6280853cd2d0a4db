#include <dlfl/schemes/meng_prautzsch_honeycomb.h>

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <limits>
#include <span>
#include <vector>

#include <dlfl/analysis/convex_polyhedron.h>
#include <dlfl/dense_mesh.h>
#include <dlfl/errors.h>
#include <dlfl/mesh_assembler.h>
#include <dlfl/schemes/detail/corner_origins.h>
#include <dlfl/schemes/detail/meng_prautzsch_params.h>
#include <dlfl/schemes/detail/scheme_origins.h>
#include <dlfl/schemes/detail/scheme_table.h>

namespace dlfl {
namespace {

// The unit vector at fraction s of the great-circle arc from a to b (a, b unit, not parallel).
glm::dvec3 slerp(const glm::dvec3& a, const glm::dvec3& b, double s) {
  const double theta = std::atan2(glm::length(glm::cross(a, b)), glm::dot(a, b));
  const glm::dvec3 n = (std::sin((1.0 - s) * theta) * a + std::sin(s * theta) * b) / std::sin(theta);
  return glm::normalize(n);
}

// The origins of a step's output and of its corners (see detail::mp_honeycomb), either may be null. Out of
// line so that the step's own loops are compiled as they are without it.
[[gnu::noinline]] void honeycomb_origins(const Mesh& input, const Mesh& m, const Mesh& result,
                                         std::span<const std::uint32_t> position, Origins* origins,
                                         std::vector<Origin>* corners) {
  const auto [nv, ne, nf, nc] = dense_counts(m);
  // Per output corner: the origin of the corner and of its outgoing edge. In hexagon e (corners as
  // detail::mp_honeycomb sets them) the corners at f-face vertices stem from those vertices' corners, the
  // ones at old vertices from the side corner of e leaving them; its sides are verticals (old vertex to
  // f-face vertex of corner x
  // <- x) and f-face sides (of corner c <- c).
  const detail::InputHandles in(input);
  std::vector<Origin> corner_of(result.corner_capacity()), edge_of(result.corner_capacity());
  for (std::uint32_t i = 0; i < nc; ++i) corner_of[position[i]] = edge_of[position[i]] = in.corner(i);
  for (std::uint32_t e = 0; e < ne; ++e) {
    const CornerId c0 = m.corner(EdgeId(e), 0), c1 = m.corner(EdgeId(e), 1);
    const Origin o0 = in.corner(c0.index()), o1 = in.corner(c1.index());
    const Origin n0 = in.corner(m.next(c0).index()), n1 = in.corner(m.next(c1).index());
    const std::uint32_t base = nc + 6 * e;
    const Origin corner_origins[6] = {o0, n1, o1, o1, n0, o0};
    const Origin edge_origins[6] = {n1, o1, o1, n0, o0, o0};
    for (int j = 0; j < 6; ++j) {
      corner_of[base + j] = corner_origins[j];
      edge_of[base + j] = edge_origins[j];
    }
  }
  if (origins) {
    detail::reset_origins(*origins, result);
    in.fill(origins->vertices, {Origin::Kind::vertex, Origin::Kind::corner});
    in.fill(origins->faces, {Origin::Kind::face, Origin::Kind::edge});
    detail::set_edge_origins(*origins, result, edge_of);
  }
  if (corners) *corners = std::move(corner_of);
}

}  // namespace

void check_mp_honeycomb_params(const MpHoneycombParams& p) {
  detail::check_mp_params("mp-honeycomb", p.tau, p.ratio, p.center, p.random);
}

Mesh mp_honeycomb(const Mesh& input, const MpHoneycombParams& params, Origins* origins) {
  return detail::mp_honeycomb(input, params, origins, nullptr);
}

Mesh detail::mp_honeycomb(const Mesh& input, const MpHoneycombParams& params, Origins* origins,
                          std::vector<Origin>* corners) {
  // Per-edge split fractions of the exterior angle, per-face taus (drawn from the seed when random).
  const MpStepInput step("mp-honeycomb", input, params, ElementKind::face);
  const Mesh& m = step.mesh();
  const auto& [fraction, tau] = step.choices();
  const auto [nv, ne, nf, nc] = dense_counts(m);

  std::vector<glm::dvec3> face_normal(nf);
  for (std::uint32_t f = 0; f < nf; ++f) face_normal[f] = face_plane(m, FaceId(f)).normal;
  // Edge planes pass through their edge; only their normals are needed, as every plane below is met at a
  // point known to lie on it (an old vertex).
  std::vector<glm::dvec3> edge_normal(ne);
  for (std::uint32_t e = 0; e < ne; ++e) {
    const EdgeId id(e);
    edge_normal[e] =
        slerp(face_normal[m.face(id, 0).index()], face_normal[m.face(id, 1).index()], fraction[e]);
  }

  // Output faces: the f-faces in input face order, then one hexagon per input edge (6 corners each).
  const auto [offsets, position] = mp_face_layout(m, ne, 6);  // position: the f-face corner of input corner c
  MeshAssembler out(std::size_t(nv) + nc, offsets);
  for (std::uint32_t v = 0; v < nv; ++v) out.set_position(v, m.position(VertexId(v)));

  // f-face vertices. Corner j of face F (at old vertex p_j) slides up the line where the planes of the two
  // edges at p_j meet: q_j(t) = p_j + t w_j at height t above F (dot(n_F, w_j) = 1). The cross-section's
  // edge j keeps the direction of F's edge j and its length changes linearly; the first to vanish marks v_F.
  std::vector<glm::dvec3> slide;  // w_j of the current face, reused
  for (std::uint32_t f = 0; f < nf; ++f) {
    const FaceId face(f);
    const glm::dvec3& n = face_normal[f];
    slide.clear();
    for (CornerId c : m.corners(face)) {
      const glm::dvec3 line =
          glm::cross(edge_normal[m.edge(m.prev(c)).index()], edge_normal[m.edge(c).index()]);
      const double rise = glm::dot(n, line);
      if (!(std::abs(rise) > 1e-12 * glm::length(line))) {
        throw InvalidArgument("mp-honeycomb: the edge planes at " + to_string(m.vertex(c)) + " of " +
                              to_string(face) + " meet in a line parallel to the face");
      }
      slide.push_back(line / rise);
    }
    double height = std::numeric_limits<double>::infinity();
    std::uint32_t j = 0;
    for (CornerId c : m.corners(face)) {
      const glm::dvec3 along = m.position(m.vertex(m.next(c))) - m.position(m.vertex(c));
      const double length = glm::length(along);
      const double rate = glm::dot(slide[(j + 1) % slide.size()] - slide[j], along / length);
      if (rate < 0.0) height = std::min(height, length / -rate);
      ++j;
    }
    if (!std::isfinite(height)) {
      throw InvalidArgument("mp-honeycomb: the region Delta over " + to_string(face) +
                            " is unbounded (its edge planes open outwards); use ratios closer to 1");
    }
    j = 0;
    for (CornerId c : m.corners(face)) {
      out.set_position(nv + c.index(), m.position(m.vertex(c)) + tau[f] * height * slide[j++]);
    }
  }

  // Connectivity. The hexagon of edge e runs from(e), Q(next c1), Q(c1), to(e), Q(next c0), Q(c0), with
  // c0, c1 its side corners and Q(x) the f-face vertex of corner x. Seen from an input corner x, its edge's
  // hexagon holds three of x's half-edges: "down" Q(x) -> vertex(x), "across" Q(next x) -> Q(x) (the twin of
  // the f-face edge) and "up" vertex(next x) -> Q(next x).
  // nc is copied in: clang before 16 cannot capture a structured binding.
  const auto hexagon = [&m, nc = nc](CornerId x) { return nc + 6 * m.edge(x).index(); };
  const auto on_side_1 = [&](CornerId x) { return m.corner(m.edge(x), 1) == x; };
  const auto down = [&](CornerId x) { return hexagon(x) + (on_side_1(x) ? 2 : 5); };
  const auto across = [&](CornerId x) { return hexagon(x) + (on_side_1(x) ? 1 : 4); };
  const auto up = [&](CornerId x) { return hexagon(x) + (on_side_1(x) ? 0 : 3); };
  for (std::uint32_t i = 0; i < nc; ++i) out.set_corner(position[i], nv + i, across(CornerId(i)));
  for (std::uint32_t e = 0; e < ne; ++e) {
    const CornerId c0 = m.corner(EdgeId(e), 0), c1 = m.corner(EdgeId(e), 1);
    const std::uint32_t base = nc + 6 * e;
    out.set_corner(base + 0, m.vertex(c0).index(), down(m.next(c1)));
    out.set_corner(base + 1, nv + m.next(c1).index(), position[c1.index()]);
    out.set_corner(base + 2, nv + c1.index(), up(m.prev(c1)));
    out.set_corner(base + 3, m.vertex(c1).index(), down(m.next(c0)));
    out.set_corner(base + 4, nv + m.next(c0).index(), position[c0.index()]);
    out.set_corner(base + 5, nv + c0.index(), up(m.prev(c0)));
  }
  Mesh result =
      detail::require_convex_result(out.finish(), step.center(), "mp-honeycomb", params.tau, params.ratio);
  if (!origins && !corners) return result;
  honeycomb_origins(input, m, result, position, origins, corners);
  return result;
}

namespace detail {

SchemeSpec mp_honeycomb_scheme() {
  return mp_step_scheme<MpHoneycombParams>(
      dlfl::mp_honeycomb, "mp-honeycomb",
      "Meng-Prautzsch honeycomb H: convexity-preserving refinement of convex polyhedra by cutting planes",
      "where each f-face lies between its old face (0) and the vertex v_F of the region over it (1)",
      "how each edge plane divides the edge's exterior angle, ratio : 1 (1 bisects)", mp_honeycomb_counts);
}

}  // namespace detail
}  // namespace dlfl
