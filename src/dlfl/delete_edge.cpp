// DELETEEDGE, the exact inverse of INSERTEDGE. See Mesh::delete_edge in mesh.h.

#include <dlfl/errors.h>
#include <dlfl/mesh.h>

namespace dlfl {

DeleteEdgeResult Mesh::delete_edge(EdgeId e, const detail::Reuse& reuse) {
  require(e, "delete_edge");
  if (reuse.face.valid() && (reuse.face.index() >= face_capacity() || is_alive(reuse.face))) {
    throw InvalidArgument("delete_edge: a handle to reuse is not a removed element");
  }
  const CornerId s0 = corner(e, 0);  // at u
  const CornerId s1 = corner(e, 1);  // at w
  const VertexId u = vertex(s0);
  const VertexId w = vertex(s1);
  const CornerId x0 = next(s0);  // at w: the corner that continues side 0 once the edge is gone
  const CornerId x1 = next(s1);  // at u
  const CornerId p0 = prev(s0);
  const CornerId p1 = prev(s1);
  const FaceId f0 = face(s0);
  const FaceId f1 = face(s1);

  DeleteEdgeResult result;
  Step& inverse = result.inverse;
  inverse.kind = Step::Kind::insert_edge;
  inverse.reuse.corners = {s0, s1};
  inverse.reuse.edge = e;
  inverse.reuse.face_anchors = {{{f0, first_corner(f0)}, {f1, first_corner(f1)}}};
  inverse.reuse.vertex_anchors = {{{u, corner(u)}, {w, corner(w)}}};

  if (f0 != f1) {
    // Merge (inverse of a split): the larger face survives, a tie goes to face(s1).
    const bool keep1 = size(f1) >= size(f0);
    const FaceId keep = keep1 ? f1 : f0;
    const FaceId gone = keep1 ? f0 : f1;
    // The loser's corners, minus its edge corner, move to the survivor.
    const CornerId start = keep1 ? x0 : x1;
    const CornerId stop = keep1 ? s0 : s1;
    for (CornerId c = start; c != stop; c = next(c)) corners_[c.index()].face = keep;
    faces_[keep.index()].size = size(f0) + size(f1) - 2;
    link(p0, x1);
    link(p1, x0);
    CornerId& anchor = faces_[keep.index()].corner;
    if (anchor == s0) anchor = x0;
    if (anchor == s1) anchor = x1;
    if (corner(u) == s0) vertex_corner_[u.index()] = x1;
    if (corner(w) == s1) vertex_corner_[w.index()] = x0;
    kill(s0);
    kill(s1);
    kill(e);
    kill(gone);
    result.removed_face = gone;
    inverse.reuse.face = gone;
    inverse.corner1 = x1;
    inverse.corner2 = x0;
    apply_anchors(reuse);
    return result;
  }

  // Split (inverse of a merge). Part U continues at u (x1 .. p0), part W at w (x0 .. p1). An end vertex with
  // no other edge (next(s1) == s0) becomes a point sphere that keeps its corner.
  const FaceId f = f0;
  const bool dangling_u = x1 == s0;
  const bool dangling_w = x0 == s1;
  std::uint32_t length_u = 1, length_w = 1;
  if (dangling_u && !dangling_w) {
    length_w = size(f) - 2;
  } else if (dangling_w && !dangling_u) {
    length_u = size(f) - 2;
  } else if (!dangling_u && !dangling_w) {
    const FirstArrival walk = first_arrival(x1, s0, x0, s1);
    length_u = walk.x_first ? walk.steps : size(f) - 2 - walk.steps;
    length_w = size(f) - 2 - length_u;
  }
  const CornerId start_u = dangling_u ? s0 : x1;
  const CornerId start_w = dangling_w ? s1 : x0;
  if (dangling_u) {
    link(s0, s0);
    corners_[s0.index()].edge = EdgeId();
  } else {
    link(p0, x1);
  }
  if (dangling_w) {
    link(s1, s1);
    corners_[s1.index()].edge = EdgeId();
  } else {
    link(p1, x0);
  }

  const bool keep_u = length_u >= length_w;
  // A new face copies f's hole flag; a revived one keeps its own.
  const FaceId g = new_face(reuse.face, faces_[f.index()].hole);
  const CornerId moved_start = keep_u ? start_w : start_u;
  const CornerId f_anchor = first_corner(f);
  const CornerId g_anchor = first_corner(g);  // meaningful only for a revived face
  const MovedCycle moved = move_cycle(moved_start, g, f_anchor, g_anchor);
  const bool f_anchor_moved = f_anchor == s0 || f_anchor == s1 || moved.passed_f_anchor;
  const bool g_anchor_inside = moved.passed_g_anchor;
  faces_[f.index()].size = keep_u ? length_u : length_w;
  faces_[g.index()].size = keep_u ? length_w : length_u;
  if (f_anchor_moved) faces_[f.index()].corner = keep_u ? start_u : start_w;
  if (!(reuse.face.valid() && g_anchor_inside)) faces_[g.index()].corner = moved_start;
  if (!dangling_u && corner(u) == s0) vertex_corner_[u.index()] = x1;
  if (!dangling_w && corner(w) == s1) vertex_corner_[w.index()] = x0;
  if (!dangling_u) kill(s0);
  if (!dangling_w) kill(s1);
  kill(e);
  result.created_face = g;
  // A corner kept for a point sphere is not created again by the inverse.
  if (dangling_u) inverse.reuse.corners[0] = CornerId();
  if (dangling_w) inverse.reuse.corners[1] = CornerId();
  inverse.corner1 = start_u;
  inverse.corner2 = start_w;
  apply_anchors(reuse);
  return result;
}

}  // namespace dlfl
