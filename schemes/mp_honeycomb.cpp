#include "schemes/mp_honeycomb.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <limits>
#include <vector>

#include "dlfl/build_mesh.h"
#include "dlfl/errors.h"
#include "dlfl/mesh_assembler.h"
#include "dlfl/polygon_soup.h"
#include "schemes/convex_polyhedron.h"

namespace dlfl {
namespace {

// The unit vector at fraction s of the great-circle arc from a to b (a, b unit, not parallel).
glm::dvec3 slerp(const glm::dvec3& a, const glm::dvec3& b, double s) {
  const double theta = std::atan2(glm::length(glm::cross(a, b)), glm::dot(a, b));
  const glm::dvec3 n = (std::sin((1.0 - s) * theta) * a + std::sin(s * theta) * b) / std::sin(theta);
  return glm::normalize(n);
}

}  // namespace

void check_mp_honeycomb_params(const MpHoneycombParams& p) {
  detail::check_mp_params("mp-honeycomb", p.tau, p.ratio, p.center, p.random);
}

Mesh mp_honeycomb(const Mesh& input, const MpHoneycombParams& params) {
  check_mp_honeycomb_params(params);
  std::optional<Mesh> storage;
  const Mesh& m = dense_mesh(input, storage);  // handles 0 .. count-1
  require_convex_polyhedron(m, params.center.value_or(vertex_centroid(m)), "mp-honeycomb");
  const auto nv = static_cast<std::uint32_t>(m.num_vertices());
  const auto ne = static_cast<std::uint32_t>(m.num_edges());
  const auto nf = static_cast<std::uint32_t>(m.num_faces());
  const auto nc = static_cast<std::uint32_t>(m.num_corners());

  // Per-edge split fractions of the exterior angle, per-face taus: edges first, then faces, in handle order.
  std::vector<double> fraction(ne, params.ratio / (1.0 + params.ratio));
  std::vector<double> tau(nf, params.tau);
  if (params.random.enabled) {
    MpRandom rng(params.random.seed);
    const double lo = params.random.epsilon, hi = 1.0 - params.random.epsilon;
    for (double& s : fraction) s = rng.uniform(lo, hi);
    for (double& t : tau) t = rng.uniform(lo, hi);
  }

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

  // f-face vertices. Corner j of face F (at old vertex p_j) slides up the line where the planes of the two
  // edges at p_j meet: q_j(t) = p_j + t w_j at height t above F (dot(n_F, w_j) = 1). The cross-section's
  // edge j keeps the direction of F's edge j and its length changes linearly; the first to vanish marks v_F.
  PolygonSoup soup;
  soup.positions.resize(std::size_t(nv) + nc);
  for (std::uint32_t v = 0; v < nv; ++v) soup.positions[v] = m.position(VertexId(v));
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
      soup.positions[nv + c.index()] = m.position(m.vertex(c)) + tau[f] * height * slide[j++];
    }
  }

  soup.indices.reserve(std::size_t(nc) + 6 * std::size_t(ne));
  soup.offsets.reserve(std::size_t(nf) + ne + 1);
  std::vector<std::uint32_t> polygon;
  for (std::uint32_t f = 0; f < nf; ++f) {
    polygon.clear();
    for (CornerId c : m.corners(FaceId(f))) polygon.push_back(nv + c.index());
    soup.add_face(polygon);
  }
  for (std::uint32_t e = 0; e < ne; ++e) {
    const CornerId c0 = m.corner(EdgeId(e), 0), c1 = m.corner(EdgeId(e), 1);
    soup.add_face({m.vertex(c0).index(), nv + m.next(c1).index(), nv + c1.index(), m.vertex(c1).index(),
                   nv + m.next(c0).index(), nv + c0.index()});
  }
  return build_mesh(soup);
}

}  // namespace dlfl
