// collapse_edge with the Euler operators: each edge (v, w) at the removed end v, taken around v from the face
// of side 0, is redrawn as (u, w) in the face beside it (an insert_edge that splits off the triangle u v w),
// then deleted (the triangle merges into the face beyond). v is left with e alone; deleting e makes v a point
// sphere, which is deleted. Every step is O(1), so the whole is O(valence of v).

#include <dlfl/operations/collapse_edge.h>

#include <algorithm>
#include <string>
#include <vector>

#include <dlfl/operations/detail/operation_table.h>
#include <dlfl/operations/detail/refusal.h>
#include <dlfl/operations/detail/vertex_merge.h>

namespace dlfl {
namespace {

constexpr const char* op_name = "collapse_edge";

[[noreturn]] void refuse_non_manifold(const std::string& why) {
  detail::refuse(op_name, "edge", "the result would not be a manifold (" + why + ")");
}

// The third vertex of the face on `side` of e when that face is a triangle, else an invalid handle.
VertexId triangle_apex(const Mesh& m, EdgeId e, int side) {
  const CornerId c = m.corner(e, side);
  return m.size(m.face(c)) == 3 ? m.vertex(m.prev(c)) : VertexId();
}

bool is_surface_triangle(const Mesh& m, FaceId f) { return m.size(f) == 3 && !m.is_hole(f); }

// Deletes the edge of a 2-gon that is not `kept`'s (whose corner is in it), so that the face beyond absorbs
// the 2-gon, keeping that face's hole flag. False (and nothing done) if the face of `kept` is no longer a
// 2-gon of two different edges.
bool remove_two_gon(Transaction& tx, CornerId kept) {
  const Mesh& m = tx.mesh();
  const CornerId other = m.next(kept);
  if (m.size(m.face(kept)) != 2 || m.edge(other) == m.edge(kept)) return false;
  const bool beyond_is_hole = m.is_hole(m.face(m.opposite(other)));
  tx.delete_edge(m.edge(other));
  const FaceId merged = m.face(kept);
  if (m.is_hole(merged) != beyond_is_hole) tx.set_hole(merged, beyond_is_hole);
  return true;
}

CollapseEdgeOptions options_of(const Params& p) {
  CollapseEdgeOptions options;
  if (p.has("position")) options.position = p.point("position");
  options.cleanup = p.boolean("cleanup");
  return options;
}

}  // namespace

void check_collapse_edge(const Mesh& m, EdgeId e, const CollapseEdgeOptions& options) {
  detail::require_live(m, op_name, "edge", e);
  if (options.position) detail::require_finite(op_name, "position", *options.position);
  const CornerId s0 = m.corner(e, 0);
  const CornerId s1 = m.corner(e, 1);
  const VertexId u = m.vertex(s0);
  const VertexId v = m.vertex(s1);

  for (CornerId c : m.corners(v)) {
    if (m.edge(c) != e && m.vertex(m.next(c)) == u) {
      detail::refuse(op_name, "edge",
                     "the collapse would make a self-loop of " + to_string(m.edge(c)) +
                         ", which also joins " + to_string(u) + " and " + to_string(v));
    }
  }

  // Vertices: a common neighbour is allowed only as the apex of a triangle beside e, whose two edges to it
  // become the 2-gon's. (Such an apex is always a common neighbour.)
  const std::vector<VertexId> common = detail::common_neighbours(m, u, v);
  std::vector<VertexId> apexes;
  for (int side : {0, 1}) {
    const VertexId x = triangle_apex(m, e, side);
    if (x.valid() && std::find(apexes.begin(), apexes.end(), x) == apexes.end()) apexes.push_back(x);
  }
  const std::string doubled = detail::doubled_edges(common, apexes, "the end vertices");
  if (!doubled.empty()) refuse_non_manifold(doubled);

  // Faces: leaving out the two corner pairs along e (s0 with next(s0), s1 with next(s1)), no face may keep a
  // corner at u and one at v.
  std::vector<FaceId> at_u;
  for (CornerId c : m.corners(u)) {
    if (c != s0 && c != m.next(s1)) at_u.push_back(m.face(c));
  }
  std::sort(at_u.begin(), at_u.end());
  for (CornerId c : m.corners(v)) {
    if (c == s1 || c == m.next(s0) || !std::binary_search(at_u.begin(), at_u.end(), m.face(c))) continue;
    refuse_non_manifold(to_string(m.face(c)) + " visits both " + to_string(u) + " and " + to_string(v) +
                        " away from the edge; it would pass through the merged vertex twice");
  }

  // Boundary: the merged vertex's rotation is side 0's face, v's other corners, side 1's face, u's other
  // corners. More separate runs of holes there than at u or v (and more than one) pinch the boundary.
  std::vector<bool> merged{m.is_hole(m.face(s0))};
  detail::append_hole_flags(m, m.next_around_vertex(m.next(s0)), s1, merged);
  merged.push_back(m.is_hole(m.face(s1)));
  detail::append_hole_flags(m, m.next_around_vertex(m.next(s1)), s0, merged);
  const std::size_t runs = detail::hole_runs(merged);
  if (runs > std::max<std::size_t>({1, detail::hole_runs(m, u), detail::hole_runs(m, v)})) {
    refuse_non_manifold("the merged vertex would be on the boundary in " + std::to_string(runs) +
                        " separate places, a pinch");
  }
}

CollapseEdgeResult collapse_edge(Transaction& tx, EdgeId e, const CollapseEdgeOptions& options) {
  const Mesh& m = tx.mesh();
  check_collapse_edge(m, e, options);
  const CornerId s0 = m.corner(e, 0);  // at u; stays e's corner there until e goes
  const CornerId s1 = m.corner(e, 1);  // at v
  const VertexId u = m.vertex(s0);
  const VertexId v = m.vertex(s1);
  const glm::dvec3 position = options.position ? *options.position : 0.5 * (m.position(u) + m.position(v));
  // A surface triangle beside e becomes a 2-gon that keeps the triangle's edge at u; these are its corners.
  const CornerId two_gon0 = is_surface_triangle(m, m.face(s0)) ? m.prev(s0) : CornerId();
  const CornerId two_gon1 = is_surface_triangle(m, m.face(s1)) ? m.next(s1) : CornerId();

  while (m.next(s0) != s1) {
    const CornerId at_v = m.next(s0);  // its edge runs from v to w
    const EdgeId old_edge = m.edge(at_v);
    const bool beyond_is_hole = m.is_hole(m.face(m.opposite(at_v)));
    tx.insert_edge(m.next(at_v), s0);  // (w, u): the triangle (w, u, v) splits off, s0 in it
    tx.delete_edge(old_edge);          // it merges into the face beyond (v, w): next(s0) is v's next corner
    // The sliver carried its old face's flag; the merged face must keep the flag of the face beyond.
    if (m.is_hole(m.face(s0)) != beyond_is_hole) tx.set_hole(m.face(s0), beyond_is_hole);
  }
  tx.delete_edge(e);  // v hangs on e alone: it becomes a point sphere
  tx.delete_vertex(v);
  tx.set_position(u, position);

  CollapseEdgeResult result{u, 0};
  if (options.cleanup) {
    for (CornerId kept : {two_gon0, two_gon1}) {
      if (kept.valid() && remove_two_gon(tx, kept)) ++result.two_gons_removed;
    }
  }
  return result;
}

std::vector<OperationSpec> detail::collapse_edge_operation_specs() {
  return {edit_operation(
      "collapse_edge",
      "merges the two end vertices of an edge into one (from(e) stays); triangles beside it become 2-gons",
      {param("edge", ParamType::edge, "the edge to collapse"),
       param("position", ParamType::point, "where the merged vertex goes").optional("the edge midpoint"),
       param("cleanup", ParamType::boolean, false,
             "remove the 2-gons that triangles beside the edge become")},
      "V-1, E-1, F+0; cleanup with k triangles beside the edge: V-1, E-1-k, F-k",
      [](Transaction& tx, const Params& p) {
        const CollapseEdgeResult r = collapse_edge(tx, p.handle<EdgeId>("edge"), options_of(p));
        return Params{{"vertex", r.vertex}, {"two_gons_removed", r.two_gons_removed}};
      },
      [](const Mesh& m, Params& p) { check_collapse_edge(m, p.handle<EdgeId>("edge"), options_of(p)); })};
}
}  // namespace dlfl
