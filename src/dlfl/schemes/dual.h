#pragma once
// The dual of a polygon mesh, open or closed.

#include <dlfl/mesh.h>
#include <dlfl/schemes/boundary_rule.h>
#include <dlfl/schemes/origins.h>

namespace dlfl {

/// The dual mesh: a vertex at the centroid of every face (the average of its corners' positions, so a vertex
/// the face visits twice counts twice), a face around every vertex, and an edge across every edge. V' = F,
/// E' = E, F' = V; the face sizes of the dual are the valences of the input and its valences are the input's
/// face sizes, and the topology (genus of every component) is kept. A vertex of valence 2 gives a 2-gon
/// (legal in this kernel). The input is not modified.
///
/// Orientation: the face of vertex v lists the faces around v counter-clockwise seen from outside, which is
/// the `prev_around_vertex` order (`next_around_vertex` turns clockwise), so outward normals stay outward.
///
/// Handles (deterministic; tombstones of the input are ignored, elements count in live-handle order):
/// - output vertex f = the input's f-th live face; output face v = the input's v-th live vertex;
/// - the corners of output face v stand for the input corners at v, starting at corner(v) and following
///   prev_around_vertex; the corner for input corner c (at v, in face f) sits at output vertex f;
/// - edges are numbered by the assembler (in order of their smaller corner).
///
/// Open meshes (hole faces, one per boundary loop), by `boundary.rule`:
/// - `curve` (the default): the boundary of the dual is the dual of the boundary. A hole is no face, so it
///   gets no vertex; each boundary edge gets a boundary vertex at its midpoint, and each boundary vertex a
///   boundary edge, joining the midpoints of its two boundary edges: the face of a boundary vertex v of
///   valence n lists the centroids of its n - 1 faces and, where the hole is, the midpoint of the boundary
///   edge leaving v along the hole, then that of the one arriving (n + 1 corners; a corner with one face
///   gives a triangle, not a 2-gon). The boundary loops stay holes, each the polygon of its edges'
///   midpoints, which depends on the boundary polygon alone. A sharp boundary vertex (marked `sharp`, or
///   with exactly two edges when `sharp_corners`) also keeps itself: a vertex at its position between the
///   two midpoints (n + 2 corners), marked `sharp` in the result. Counts: with F_o the faces that are not
///   holes, h the holes, H the hole corners and S those at sharp vertices, V' = F_o + H + S, E' = E + H + S,
///   F' = V + h. Handles: the vertices of the faces that are not holes in face order, then for each hole
///   corner in corner order its midpoint and its kept vertex; faces: the vertex faces, then the holes in
///   face order. Since a boundary vertex of the dual stands for a boundary edge, the dual of the dual of an
///   open mesh is the mesh with a collar of quads along its boundary (one per boundary edge), not the mesh.
/// - `hole`: refused (the behaviour before boundary rules; treating the hole as a face would silently close
///   the surface).
///
/// Throws TopologyError, naming the element, when the dual is not a mesh of this kernel:
/// - a point sphere (a vertex without edges has no face around it);
/// - a hole face under `boundary = hole`;
/// - an edge with the same face on both sides (for example the edge of a valence-1 vertex): its dual would be
///   a self-loop.
/// O(size).
///
/// Origins (filled when `origins` is given; handles of `mesh` itself): output vertex <- the face it stands
/// for, output face <- the vertex, output edge <- the edge it crosses. Under `curve`: a boundary midpoint <-
/// its edge, a kept vertex <- its vertex, a hole face <- the input hole, a boundary edge <- the boundary
/// vertex it stands for. By kind: vertices F from faces, faces V from vertices, edges E from edges (and, on
/// the boundary, vertices from edges and vertices, edges from vertices). Costs nothing when not asked for.
Mesh dual(const Mesh& mesh, const BoundaryOptions& boundary, Origins* origins = nullptr);

/// The same with the default boundary options (`curve`, sharp corners kept).
Mesh dual(const Mesh& mesh, Origins* origins = nullptr);

}  // namespace dlfl
