#include <dlfl/schemes/meng_prautzsch_pushing.h>

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <limits>
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

void check_mp_pushing_params(const MpPushingParams& p) {
  detail::check_mp_params("mp-pushing", p.tau, p.ratio, p.center, p.random);
}

Mesh mp_pushing(const Mesh& input, const MpPushingParams& params, Origins* origins) {
  return detail::mp_pushing(input, params, origins, nullptr);
}

SchemeSpec detail::mp_pushing_scheme() {
  return mp_step_scheme<MpPushingParams>(
      dlfl::mp_pushing, "mp-pushing",
      "Meng-Prautzsch corner pushing P: cut every corner off, push the old vertices towards the centre",
      "how far each old vertex moves towards the centre, as a fraction of the way to its extreme position",
      "where each edge's new point divides it: |from(e) m| : |m to(e)| = ratio : 1 (1: the midpoint)",
      mp_pushing_counts);
}

double pushing_extreme_fraction(const glm::dvec3& p, std::span<const glm::dvec3> ring,
                                const glm::dvec3& center) {
  const std::size_t ring_size = ring.size();
  double extreme = 1.0;
  const glm::dvec3 towards = center - p;
  for (std::size_t i = 0; i < ring_size; ++i) {
    const glm::dvec3& a = ring[(i + ring_size - 1) % ring_size];
    const glm::dvec3& b = ring[i];
    const glm::dvec3& c = ring[(i + 1) % ring_size];
    const glm::dvec3 normal = glm::cross(b - a, c - b);
    const double approach = glm::dot(normal, towards);
    if (approach == 0.0) continue;  // moving parallel to this plane: never reaches it
    const double s = glm::dot(normal, b - p) / approach;
    if (s > 0.0) extreme = std::min(extreme, s);
  }
  return extreme;
}

Mesh detail::mp_pushing(const Mesh& input, const MpPushingParams& params, Origins* origins,
                        std::vector<Origin>* corners) {
  // Per-edge split fractions along the edge, per-vertex taus (drawn from the seed when random).
  const MpStepInput step("mp-pushing", input, params, ElementKind::vertex);
  const Mesh& m = step.mesh();
  const glm::dvec3& center = step.center();
  const auto& [fraction, tau] = step.choices();
  const auto [nv, ne, nf, nc] = dense_counts(m);

  // Output faces: the central faces in input face order, then one triangle per input corner.
  const auto [offsets, position] = mp_face_layout(m, nc, 3);  // position: the central-face corner of corner c
  MeshAssembler out(std::size_t(nv) + ne, offsets);
  std::vector<glm::dvec3> point(ne);
  for (std::uint32_t e = 0; e < ne; ++e) {
    const glm::dvec3& a = m.position(m.from(EdgeId(e)));
    const glm::dvec3& b = m.position(m.to(EdgeId(e)));
    point[e] = a + fraction[e] * (b - a);
    out.set_position(nv + e, point[e]);
  }
  std::vector<glm::dvec3> ring;  // edge points around the current vertex, reused
  for (std::uint32_t v = 0; v < nv; ++v) {
    const glm::dvec3& p = m.position(VertexId(v));
    ring.clear();
    for (CornerId c : m.corners(VertexId(v))) ring.push_back(point[m.edge(c).index()]);
    const double s = pushing_extreme_fraction(p, ring, center);
    out.set_position(v, p + tau[v] * s * (center - p));
  }

  // Connectivity. The triangle of corner c runs vertex(c), m(edge c), m(edge prev c): its first edge is half
  // of the old edge(c), whose other half ends the triangle of the corner across; its second faces the central
  // face; its third is half of edge(prev c), which the triangle of the corner across starts with.
  // nc is copied in: clang before 16 cannot capture a structured binding.
  const auto triangle = [nc = nc](CornerId x) { return nc + 3 * x.index(); };
  for (std::uint32_t i = 0; i < nc; ++i) {
    const CornerId c(i);
    out.set_corner(position[i], nv + m.edge(c).index(), triangle(m.next(c)) + 1);
    out.set_corner(triangle(c) + 0, m.vertex(c).index(), triangle(m.next(m.opposite(c))) + 2);
    out.set_corner(triangle(c) + 1, nv + m.edge(c).index(), position[m.prev(c).index()]);
    out.set_corner(triangle(c) + 2, nv + m.edge(m.prev(c)).index(), triangle(m.opposite(m.prev(c))) + 0);
  }
  Mesh result = detail::require_convex_result(out.finish(), center, "mp-pushing", params.tau, params.ratio);
  if (!origins && !corners) return result;
  const detail::InputHandles in(input);
  if (corners) {
    corners->assign(result.corner_capacity(), Origin{});
    for (std::uint32_t i = 0; i < nc; ++i) {
      (*corners)[position[i]] = in.corner(i);
      for (std::uint32_t j = 0; j < 3; ++j) (*corners)[triangle(CornerId(i)) + j] = in.corner(i);
    }
  }
  if (origins) {
    detail::reset_origins(*origins, result);
    in.fill(origins->vertices, {Origin::Kind::vertex, Origin::Kind::edge});
    in.fill(origins->faces, {Origin::Kind::face, Origin::Kind::corner});
    // The central corner of c runs to the point of edge(next c), cutting off next(c); the triangle of c runs
    // along edge(c), across to the central face (cutting off c), and along edge(prev c).
    std::vector<Origin> edge_of(result.corner_capacity());
    for (std::uint32_t i = 0; i < nc; ++i) {
      const CornerId c(i);
      edge_of[position[i]] = in.corner(m.next(c).index());
      for (std::uint32_t j = 0; j < 3; ++j) {
        edge_of[triangle(c) + j] = detail::corner_polygon_side(m, in, c, j, 3);
      }
    }
    detail::set_edge_origins(*origins, result, edge_of);
  }
  return result;
}

}  // namespace dlfl
