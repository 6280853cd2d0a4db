// sierpinski: corner pieces joined by struts, from the shared cuts of detail/fractal_cuts.h, then one
// INSERTEDGE per strut side and two per edge for the necks.

#include <dlfl/operations/sierpinski.h>

#include <algorithm>
#include <array>
#include <limits>
#include <vector>

#include <dlfl/operations/detail/fractal_cuts.h>
#include <dlfl/operations/detail/operation_table.h>
#include <dlfl/operations/detail/shell_copy.h>

namespace dlfl {
namespace {

constexpr std::string_view op_name = "sierpinski";

// Everything sierpinski builds, decided on the unchanged mesh.
struct Plan {
  // The tips, at `scale` from each end of each edge.
  detail::EdgeCuts tips;
  std::vector<CornerId> corners;
  // Per corner index: on the corner's cut edge, which runs from the tip after the corner (on its edge) to
  // the tip before it, the neck points at `neck` from each end.
  std::vector<std::array<glm::dvec3, 2>> necks;
};

// The tip of vertex(c)'s piece on edge e, an edge at vertex(c).
const glm::dvec3& tip_at(const Mesh& m, const Plan& plan, EdgeId e, CornerId c) {
  return plan.tips.at[e.index()][m.from(e) == m.vertex(c) ? 0 : 1];
}

Plan planned(const Mesh& m, const SierpinskiOptions& o) {
  detail::require_share(
      op_name, "scale", o.scale, 0.5,
      "it is where each edge is cut, from each end, and the pieces of its ends must not meet");
  detail::require_share(
      op_name, "neck", o.neck, 0.5,
      "it is a share of the cut edges from each end, and the two necks on one must not meet");
  detail::refuse_dangling_edges(m, op_name, "scale");
  Plan plan;
  std::vector<glm::dvec3> all;
  plan.tips = detail::plan_edge_cuts(m, o.scale, all);
  plan.necks.resize(m.corner_capacity());
  plan.corners = detail::corners_with_edges(m);
  for (CornerId c : plan.corners) {
    const glm::dvec3& after = tip_at(m, plan, m.edge(c), c);
    const glm::dvec3& before = tip_at(m, plan, m.edge(m.prev(c)), c);
    plan.necks[c.index()] = detail::points_in_from_ends(after, before, o.neck);
    all.insert(all.end(), plan.necks[c.index()].begin(), plan.necks[c.index()].end());
  }
  detail::require_finite_positions(op_name, "scale", all, "tips and neck points");
  return plan;
}

}  // namespace

void sierpinski(Transaction& tx, const SierpinskiOptions& options) {
  const Mesh& m = tx.mesh();
  const Plan plan = planned(m, options);
  const bool holes = m.num_hole_faces() > 0;
  const std::size_t corner_capacity = m.corner_capacity();
  // Taken before anything changes: each corner's successor among the old corners, each edge's sides.
  std::vector<CornerId> next_old(corner_capacity);
  for (CornerId c : plan.corners) next_old[c.index()] = m.next(c);
  std::vector<std::array<CornerId, 2>> sides(m.edge_capacity());
  for (EdgeId e : plan.tips.edges) sides[e.index()] = {m.corner(e, 0), m.corner(e, 1)};
  std::vector<EdgeId> neck_order = detail::edge_build_order(m);
  std::reverse(neck_order.begin(), neck_order.end());
  std::vector<std::uint32_t> necks_left(m.vertex_capacity(), 0);
  for (VertexId v : m.vertices()) necks_left[v.index()] = m.valence(v);

  detail::cut_edges(tx, plan.tips);

  // The caps. next(c), at the tip after c, stays in the rest of the face, leaving along the edge's middle.
  std::vector<CornerId> after_tip(corner_capacity);
  std::vector<EdgeId> cuts(corner_capacity);
  for (CornerId c : plan.corners) {
    after_tip[c.index()] = m.next(c);
    cuts[c.index()] = detail::cut_corner(tx, c);
  }
  // The neck points. The rest of each face now runs ..., the tip before c, beta (the neck point near it),
  // alpha (the one near the tip after c), the tip after c, ...
  std::vector<CornerId> alpha(corner_capacity), beta(corner_capacity);
  for (CornerId c : plan.corners) {
    const auto& at = plan.necks[c.index()];
    detail::divide_in_three(tx, cuts[c.index()], at[0], at[1]);
    alpha[c.index()] = m.prev(after_tip[c.index()]);
    beta[c.index()] = m.prev(alpha[c.index()]);
  }
  // The struts' sides: from beta of the next old corner to alpha of c cuts off the quad (alpha, tip after c,
  // tip before the next corner, its beta). beta keeps its place in the rest (the window); at alpha the
  // window goes on from the new edge's side 1.
  std::vector<CornerId> window_alpha(corner_capacity);
  for (CornerId c : plan.corners) {
    const EdgeId side = tx.insert_edge(beta[next_old[c.index()].index()], alpha[c.index()]).edge;
    window_alpha[c.index()] = m.corner(side, 1);
  }
  // The necks: at each end of each edge, the neck points beside its tip in the two faces of the edge. The
  // windows become the pieces' inner faces and the struts' floors. The order is the mirrored copy's build
  // order reversed (see there), so that each INSERTEDGE costs what it touches: first the edges of a
  // spanning tree of the faces, root first (each merges a window not yet reached into the rest, and then
  // splits off the strut's floor); the 2g edges that close the handles; then the edges of a spanning tree
  // of the vertices, leaves first, the end where the piece's last neck goes first (it splits off the
  // piece's inner face, then the floor).
  std::vector<EdgeId> necks;
  necks.reserve(2 * plan.tips.edges.size());
  auto neck_at = [&](CornerId from, CornerId across) {
    necks_left[m.vertex(from).index()] -= 1;
    necks.push_back(tx.insert_edge(window_alpha[from.index()], beta[next_old[across.index()].index()]).edge);
  };
  for (EdgeId e : neck_order) {
    const auto [s0, s1] = sides[e.index()];
    const bool to_first = necks_left[m.vertex(s1).index()] == 1;
    neck_at(to_first ? s1 : s0, to_first ? s0 : s1);
    neck_at(to_first ? s0 : s1, to_first ? s1 : s0);
  }
  if (holes) {
    // Merging a hole's window can leave a hole flag on the faces that close the pieces; they are surface.
    for (EdgeId e : necks) {
      for (int side = 0; side < 2; ++side) {
        if (m.is_hole(m.face(e, side))) tx.set_hole(m.face(e, side), false);
      }
    }
  }
}

void check_sierpinski(const Mesh& mesh, const SierpinskiOptions& options) { planned(mesh, options); }

std::vector<OperationSpec> detail::sierpinski_operation_specs() {
  return {edit_operation(
      "sierpinski",
      "TopMod's multi-connect midpoints: a corner piece at every vertex, a strut along every edge "
      "(genus E - V + 1)",
      {param("scale", ParamType::number, 0.45,
             "where each edge is cut, from each end: the size of the pieces")
           .in_open(0.0, 0.5),
       param("neck", ParamType::number, 0.1, "the struts' width, as a share of the pieces' cut edges")
           .in_open(0.0, 0.5)},
      "V'=V+6E, E'=13E, F'=V+5E (Euler characteristic 2V-2E)",
      [](Transaction& tx, const Params& p) {
        sierpinski(tx, {p.number("scale"), p.number("neck")});
        return Params{};
      },
      [](const Mesh& mesh, Params& p) {
        planned(mesh, {p.number("scale"), p.number("neck")});
      })};
}
}  // namespace dlfl
