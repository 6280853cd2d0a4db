// dissolve_coplanar: see dissolve_coplanar.h.

#include <dlfl/operations/dissolve_coplanar.h>

#include <cmath>
#include <glm/geometric.hpp>
#include <numbers>
#include <vector>

#include <dlfl/format.h>
#include <dlfl/geometry.h>
#include <dlfl/navigation.h>
#include <dlfl/operations/detail/operation_table.h>
#include <dlfl/operations/detail/refusal.h>
#include <dlfl/operations/detail/valence2_join.h>

namespace dlfl {
namespace {

// The angle between two non-zero vectors, in degrees, robust near 0 and 180.
double degrees_between(const glm::dvec3& a, const glm::dvec3& b) {
  return std::atan2(glm::length(glm::cross(a, b)), glm::dot(a, b)) * (180.0 / std::numbers::pi);
}

// True if merging faces f and g (different, beside edge e) keeps the result simple: walking the smaller
// one, the corners whose edge has the other face across form one run of k < size corners, and exactly the
// k + 1 vertices of that run are on the other face.
bool meet_along_one_chain(const Mesh& m, FaceId f, FaceId g) {
  const FaceId small = m.size(f) <= m.size(g) ? f : g;
  const FaceId large = small == f ? g : f;
  std::size_t shared = 0, runs = 0, common = 0;
  const CornerId first = m.first_corner(small);
  CornerId c = first;
  do {
    const bool here = m.face(m.opposite(c)) == large;
    const bool before = m.face(m.opposite(m.prev(c))) == large;
    shared += here;
    runs += here && !before;
    common += corner_in_face(m, m.vertex(c), large).valid();
    c = m.next(c);
  } while (c != first);
  return runs == 1 && shared < m.size(small) && common == shared + 1;
}

class Dissolve {
 public:
  Dissolve(Transaction& tx, const DissolveCoplanarOptions& o)
      : tx_(tx), m_(tx.mesh()), angle_(o.angle_degrees), newell_(m_.face_capacity()) {
    for (FaceId f : m_.faces()) newell_[f.index()] = newell_vector(m_, f);
  }

  DissolveCoplanarResult run() {
    const std::uint32_t edges = m_.edge_capacity();
    for (bool merged = true; merged;) {
      merged = false;
      for (std::uint32_t i = 0; i < edges; ++i) {
        const EdgeId e(i);
        if (m_.is_alive(e) && dissolvable(e)) {
          merge(e);
          merged = true;
        }
      }
    }
    result_.vertices_joined = detail::join_valence2_vertices(tx_, touched_);
    return result_;
  }

 private:
  glm::dvec3 normal(FaceId f) const {
    return f.index() < newell_.size() ? newell_[f.index()] : glm::dvec3(0.0);
  }

  bool dissolvable(EdgeId e) const {
    const FaceId f = m_.face(e, 0), g = m_.face(e, 1);
    if (f == g || m_.is_hole(f) || m_.is_hole(g)) return false;
    const glm::dvec3 nf = normal(f), ng = normal(g);
    if (nf == glm::dvec3(0.0) || ng == glm::dvec3(0.0)) return false;
    return degrees_between(nf, ng) < angle_ && meet_along_one_chain(m_, f, g);
  }

  void merge(EdgeId e) {
    const FaceId f = m_.face(e, 0), g = m_.face(e, 1);
    const VertexId ends[2] = {m_.from(e), m_.to(e)};
    const glm::dvec3 sum = normal(f) + normal(g);
    const FaceId gone = tx_.delete_edge(e).removed_face;
    newell_[(gone == f ? g : f).index()] = sum;
    ++result_.edges_merged;
    for (VertexId v : ends) peel(v);
  }

  // Deletes the chain of edges left dangling from v (the rest of the chain two faces met along), with its
  // free ends; the vertex it ends at is remembered for the joins.
  void peel(VertexId v) {
    if (!m_.is_alive(v)) return;  // peeled from the edge's other end
    while (m_.valence(v) == 1) {
      const CornerId c = m_.corner(v);
      const VertexId next = m_.vertex(m_.next(c));
      tx_.delete_edge(m_.edge(c));  // v becomes a point sphere
      tx_.delete_vertex(v);
      ++result_.edges_peeled;
      v = next;
    }
    touched_.push_back(v);
  }

  Transaction& tx_;
  const Mesh& m_;
  double angle_;
  std::vector<glm::dvec3> newell_;
  std::vector<VertexId> touched_;
  DissolveCoplanarResult result_;
};

}  // namespace

void check_dissolve_coplanar(const DissolveCoplanarOptions& o) {
  const double a = o.angle_degrees;
  if (!std::isfinite(a)) detail::refuse_worded("dissolve_coplanar", "angle_degrees", " is not finite");
  if (!(a > 0.0 && a <= 180.0)) {
    detail::refuse_worded("dissolve_coplanar", "angle_degrees",
                          " = " + format_number(a) + " is outside (0, 180]");
  }
}

DissolveCoplanarResult dissolve_coplanar(Transaction& tx, const DissolveCoplanarOptions& options) {
  check_dissolve_coplanar(options);
  return Dissolve(tx, options).run();
}

std::vector<OperationSpec> detail::dissolve_coplanar_operation_specs() {
  return {edit_operation(
      "dissolve_coplanar",
      "deletes the edges between faces whose normals differ by less than the angle, where the merged face "
      "stays simple, then the vertices of valence 2 this leaves",
      {param("angle_degrees", ParamType::number, 0.01, "faces whose normals differ by less are coplanar")
           .range(0, 180, true, false)},
      "V-(d+j), E-(k+d+j), F-k: k merges, d dangling edges peeled, j vertices joined",
      [](Transaction& tx, const Params& p) {
        const DissolveCoplanarResult r = dissolve_coplanar(tx, {p.number("angle_degrees")});
        return Params{{"edges_merged", r.edges_merged},
                      {"edges_peeled", r.edges_peeled},
                      {"vertices_joined", r.vertices_joined}};
      },
      [](const Mesh&, Params& p) { check_dissolve_coplanar({p.number("angle_degrees")}); })};
}
}  // namespace dlfl
