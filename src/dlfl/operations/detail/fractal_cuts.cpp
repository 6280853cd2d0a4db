#include <dlfl/operations/detail/fractal_cuts.h>

#include <cmath>
#include <string>

#include <dlfl/format.h>
#include <dlfl/operations/detail/refusal.h>

namespace dlfl::detail {

std::array<glm::dvec3, 2> points_in_from_ends(const glm::dvec3& a, const glm::dvec3& b, double t) {
  return {a + t * (b - a), b + t * (a - b)};
}

std::array<VertexId, 2> divide_in_three(Transaction& tx, EdgeId e, const glm::dvec3& near_from,
                                        const glm::dvec3& near_to) {
  const Mesh& m = tx.mesh();
  const VertexId first = tx.subdivide_edge(e, near_from);
  // e now ends at `first`; the new edge, from `first` to the old to(e), follows it on side 0.
  const EdgeId rest = m.edge(m.next(m.corner(e, 0)));
  return {first, tx.subdivide_edge(rest, near_to)};
}

EdgeCuts plan_edge_cuts(const Mesh& mesh, double t, std::vector<glm::dvec3>& positions) {
  EdgeCuts cuts;
  cuts.at.resize(mesh.edge_capacity());
  for (EdgeId e : mesh.edges()) {
    cuts.edges.push_back(e);
    const auto& at = cuts.at[e.index()] =
        points_in_from_ends(mesh.position(mesh.from(e)), mesh.position(mesh.to(e)), t);
    positions.insert(positions.end(), at.begin(), at.end());
  }
  return cuts;
}

void cut_edges(Transaction& tx, const EdgeCuts& cuts) {
  for (EdgeId e : cuts.edges) divide_in_three(tx, e, cuts.at[e.index()][0], cuts.at[e.index()][1]);
}

EdgeId cut_corner(Transaction& tx, CornerId c) {
  const Mesh& m = tx.mesh();
  // insert_edge(c1, c2) leaves c2 ... (before c1) plus a new corner at vertex(c1) as one part: here the
  // triangle prev(c), c and the new corner at next(c)'s vertex, which is the edge's side 0.
  return tx.insert_edge(m.next(c), m.prev(c)).edge;
}

std::vector<CornerId> corners_with_edges(const Mesh& mesh) {
  std::vector<CornerId> out;
  out.reserve(mesh.num_corners());
  for (CornerId c : mesh.corners()) {
    if (mesh.edge(c).valid()) out.push_back(c);
  }
  return out;
}

void require_share(std::string_view op, std::string_view param, double share, double hi,
                   std::string_view why) {
  if (!std::isfinite(share) || !(share > 0.0 && share < hi)) {
    refuse_worded(
        op, param,
        " = " + format_number(share) + " is outside (0, " + format_number(hi) + "): " + std::string(why));
  }
}

void refuse_dangling_edges(const Mesh& mesh, std::string_view op, std::string_view param) {
  for (CornerId c : mesh.corners()) {
    const EdgeId e = mesh.edge(c);
    if (e.valid() && e == mesh.edge(mesh.prev(c))) {
      refuse(op, param,
             to_string(mesh.vertex(c)) + " has valence 1 (the end of " + to_string(e) +
                 "): cutting its corner would join a point to itself");
    }
  }
}

void require_finite_positions(std::string_view op, std::string_view param, const std::vector<glm::dvec3>& ps,
                              std::string_view what) {
  for (const glm::dvec3& p : ps) {
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) {
      refuse(op, param, "the " + std::string(what) + " would not all have finite positions");
    }
  }
}

}  // namespace dlfl::detail
