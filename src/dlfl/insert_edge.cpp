// INSERTEDGE: the one operator that both splits faces and changes topology. See Mesh::insert_edge in mesh.h
// for the conventions (which corners stay, which face keeps its handle).

#include <dlfl/errors.h>
#include <dlfl/mesh.h>

namespace dlfl {
namespace {
template <class H>
bool reusable(const Mesh& m, H h, std::uint32_t capacity) {
  return !h.valid() || (h.index() < capacity && !m.is_alive(h));
}
}  // namespace

InsertEdgeResult Mesh::insert_edge(CornerId c1, CornerId c2, const detail::Reuse& reuse) {
  require(c1, "insert_edge");
  require(c2, "insert_edge");
  const VertexId u = vertex(c1);
  const VertexId w = vertex(c2);
  if (u == w) {
    throw TopologyError("insert_edge: " + to_string(c1) + " and " + to_string(c2) + " are both at " +
                        to_string(u) + "; the edge would be a self-loop");
  }
  const FaceId f1 = face(c1);
  const FaceId f2 = face(c2);
  const bool sphere1 = !edge(c1).valid();  // a point sphere's corner becomes the new edge's corner itself
  const bool sphere2 = !edge(c2).valid();
  // Only the handles this call will create are checked (a point sphere's corner is not created).
  const CornerId reuse1 = sphere1 ? CornerId() : reuse.corners[0];
  const CornerId reuse2 = sphere2 ? CornerId() : reuse.corners[1];
  if (!reusable(*this, reuse1, corner_capacity()) || !reusable(*this, reuse2, corner_capacity()) ||
      !reusable(*this, reuse.edge, edge_capacity()) ||
      (f1 == f2 && !reusable(*this, reuse.face, face_capacity())) || (reuse1.valid() && reuse1 == reuse2)) {
    throw InvalidArgument("insert_edge: a handle to reuse is not a removed element");
  }
  const CornerId a = prev(c1);
  const CornerId b = prev(c2);

  InsertEdgeResult result;
  Step& inverse = result.inverse;
  inverse.kind = Step::Kind::delete_edge;
  // Anchors: insert_edge never moves a vertex's representative (no corner goes away), and a face's first
  // corner only when a split carries it to the other part; that one case is recorded below.

  // In a split, measure the two parts before relinking: part A = c2 .. a, part B = c1 .. b (original
  // corners).
  std::uint32_t length_a = 0, length_b = 0;
  if (f1 == f2) {
    const FirstArrival walk = first_arrival(c1, c2, c2, c1);
    length_b = walk.x_first ? walk.steps : size(f1) - walk.steps;
    length_a = size(f1) - length_b;
  }

  const CornerId n1 = sphere1 ? c1 : new_corner(reuse1);
  const CornerId n2 = sphere2 ? c2 : new_corner(reuse2);
  const EdgeId e = new_edge(reuse.edge);
  corners_[n1.index()].vertex = u;
  corners_[n1.index()].edge = e;
  corners_[n2.index()].vertex = w;
  corners_[n2.index()].edge = e;
  edges_[e.index()].corner = {n1, n2};
  // The new face walk: n1, (c2 .. b), n2, (c1 .. a), with a point sphere's empty chain left out.
  link(n1, c2);
  link(n2, c1);
  if (!sphere1) link(a, n1);
  if (!sphere2) link(b, n2);

  result.edge = e;
  inverse.edge = e;

  if (f1 != f2) {
    // Merge: the larger face absorbs the other; relabel only the smaller one.
    const bool keep1 = size(f1) >= size(f2);
    const FaceId keep = keep1 ? f1 : f2;
    const FaceId gone = keep1 ? f2 : f1;
    if (keep1) {
      for (CornerId c = c2; c != n2; c = next(c)) corners_[c.index()].face = keep;
    } else {
      for (CornerId c = c1; c != n1; c = next(c)) corners_[c.index()].face = keep;
    }
    corners_[n1.index()].face = keep;
    corners_[n2.index()].face = keep;
    faces_[keep.index()].size = size(f1) + size(f2) + (sphere1 ? 0 : 1) + (sphere2 ? 0 : 1);
    kill(gone);
    result.removed_face = gone;
    inverse.reuse.face = gone;
    apply_anchors(reuse);
    return result;
  }

  // Split: the larger part keeps the handle (a tie goes to the part of c1, part B).
  const FaceId f = f1;
  const bool keep_b = length_b >= length_a;
  // A new face copies f's hole flag; a revived one keeps its own.
  const FaceId g = new_face(reuse.face, faces_[f.index()].hole);
  const CornerId moved_start = keep_b ? n1 : n2;  // the part that goes to g
  const CornerId kept_corner = keep_b ? c1 : c2;  // an original corner in the part that stays in f
  const CornerId moved_corner = keep_b ? c2 : c1;
  const CornerId f_anchor = first_corner(f);
  const CornerId g_anchor = first_corner(g);  // meaningful only for a revived face
  const MovedCycle moved = move_cycle(moved_start, g, f_anchor, g_anchor);
  const bool f_anchor_moved = moved.passed_f_anchor;
  const bool g_anchor_inside = moved.passed_g_anchor;
  corners_[(keep_b ? n2 : n1).index()].face = f;
  faces_[f.index()].size = (keep_b ? length_b : length_a) + 1;
  faces_[g.index()].size = (keep_b ? length_a : length_b) + 1;
  if (f_anchor_moved) {
    faces_[f.index()].corner = kept_corner;
    inverse.reuse.face_anchors[0] = {f, f_anchor};
  }
  if (!(reuse.face.valid() && g_anchor_inside)) faces_[g.index()].corner = moved_corner;
  result.created_face = g;
  apply_anchors(reuse);
  return result;
}

}  // namespace dlfl
