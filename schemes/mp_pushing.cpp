#include "schemes/mp_pushing.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <vector>

#include "dlfl/build_mesh.h"
#include "dlfl/errors.h"
#include "dlfl/mesh_assembler.h"
#include "dlfl/polygon_soup.h"
#include "schemes/convex_polyhedron.h"

namespace dlfl {

void check_mp_pushing_params(const MpPushingParams& p) {
  detail::check_mp_params("mp-pushing", p.tau, p.ratio, p.center, p.random);
}

double pushing_extreme_fraction(const glm::dvec3& p, const glm::dvec3* ring, std::size_t ring_size,
                                const glm::dvec3& center) {
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

Mesh mp_pushing(const Mesh& input, const MpPushingParams& params) {
  check_mp_pushing_params(params);
  std::optional<Mesh> storage;
  const Mesh& m = dense_mesh(input, storage);  // handles 0 .. count-1
  const glm::dvec3 center = params.center.value_or(vertex_centroid(m));
  require_convex_polyhedron(m, center, "mp-pushing");
  const auto nv = static_cast<std::uint32_t>(m.num_vertices());
  const auto ne = static_cast<std::uint32_t>(m.num_edges());
  const auto nf = static_cast<std::uint32_t>(m.num_faces());
  const auto nc = static_cast<std::uint32_t>(m.num_corners());

  // Per-edge split fractions, per-vertex taus: edges first, then vertices, in handle order.
  std::vector<double> fraction(ne, params.ratio / (1.0 + params.ratio));
  std::vector<double> tau(nv, params.tau);
  if (params.random.enabled) {
    MpRandom rng(params.random.seed);
    const double lo = params.random.epsilon, hi = 1.0 - params.random.epsilon;
    for (double& s : fraction) s = rng.uniform(lo, hi);
    for (double& t : tau) t = rng.uniform(lo, hi);
  }

  PolygonSoup soup;
  soup.positions.resize(std::size_t(nv) + ne);
  for (std::uint32_t e = 0; e < ne; ++e) {
    const glm::dvec3& a = m.position(m.from(EdgeId(e)));
    const glm::dvec3& b = m.position(m.to(EdgeId(e)));
    soup.positions[nv + e] = a + fraction[e] * (b - a);
  }
  std::vector<glm::dvec3> ring;  // edge points around the current vertex, reused
  for (std::uint32_t v = 0; v < nv; ++v) {
    const glm::dvec3& p = m.position(VertexId(v));
    ring.clear();
    for (CornerId c : m.corners(VertexId(v))) ring.push_back(soup.positions[nv + m.edge(c).index()]);
    const double s = pushing_extreme_fraction(p, ring.data(), ring.size(), center);
    soup.positions[v] = p + tau[v] * s * (center - p);
  }

  soup.indices.reserve(std::size_t(nc) * 4);
  soup.offsets.reserve(std::size_t(nf) + nc + 1);
  std::vector<std::uint32_t> polygon;
  for (std::uint32_t f = 0; f < nf; ++f) {
    polygon.clear();
    for (CornerId c : m.corners(FaceId(f))) polygon.push_back(nv + m.edge(c).index());
    soup.add_face(polygon);
  }
  for (std::uint32_t k = 0; k < nc; ++k) {
    const CornerId c(k);
    soup.add_face({m.vertex(c).index(), nv + m.edge(c).index(), nv + m.edge(m.prev(c)).index()});
  }
  return build_mesh(soup);
}

}  // namespace dlfl
