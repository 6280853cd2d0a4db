#pragma once
// MLCA (multi-linear subdivision followed by cell averaging, Bajaj, Schaefer, Warren, Xu) on DLFL polygon
// meshes: the d = 2 case of the scheme, for quad surfaces. Volumes and non-manifold complexes live in cells/.

#include <dlfl/mesh.h>
#include <dlfl/schemes/origins.h>

namespace dlfl {

/// Section 3.3 of the paper: every face n-gon becomes n quads (its vertex, the midpoints of its two edges
/// there, and the face centroid), positions linear, nothing smoothed. The connectivity is that of one
/// Catmull-Clark step (quad k comes from the input's k-th corner; vertices: old vertices, then edge
/// midpoints, then face centroids), so F' = corners, V' = V + E + F. Hole faces are split too and their quads
/// stay holes. Throws TopologyError for a point sphere. The input is not modified.
Mesh split_to_quads(const Mesh& mesh);

/// One MLCA step on a polygon mesh, returning a quad mesh:
/// - if a face that is not a hole has other than 4 corners, the mesh is first `split_to_quads`;
/// - then bilinear subdivision (each quad into 4, Catmull-Clark's connectivity and numbering), and every
///   vertex moves to the centroid of the centroids of the quads that contain it (formula (1)).
///
/// Composite rules on a quad mesh: a face point stays at its face's centroid; an edge point gets 3/8 of each
/// end and 1/16 of the other four vertices of its two quads; a vertex of valence n keeps 9/16 of itself and
/// gets 3/(8n) of each edge neighbour and 1/(16n) of each diagonal neighbour (formula (2)). On a closed quad
/// mesh whose vertices are all 4-valent this is Catmull-Clark.
///
/// Open meshes: boundary edges (a hole on exactly one side) are crease segments as in section 3.2 of the
/// paper, so the boundary follows the cubic B-spline rules: a boundary vertex with k boundary edges keeps 3/4
/// of itself plus 1/(4k) of each boundary neighbour, a boundary edge point stays at the midpoint. Hole faces
/// are split like faces and their quads stay holes; vertices that touch only holes keep their bilinear
/// positions. Point spheres are 0-cells, which cell averaging with creases leaves in place: they are copied
/// unchanged and come last in the output, after the vertices of the quad surface.
/// The input is not modified.
///
/// Origins (filled when `origins` is given; handles of `mesh` itself). On a quad mesh those of
/// `catmull_clark` (the same connectivity): vertex points <- vertices, edge points <- edges, face points <-
/// faces, quad k <- corner k, halves of old edges <- their edge, the edge from the edge point of edge(c) to
/// the face point of face(c) <- corner c. After a split, the rule is applied to the split quads and taken
/// back through the split, whose vertices come from vertices, edges and faces, whose edges come from edges
/// (halves) and corners (inner edges), and whose quads and their corners come from the corner each is made
/// for: so vertex points <- vertices, edges or faces, edge points <- edges or corners, face points and
/// quads <- corners, edges <- edges or corners. By kind, after a split: vertices V from vertices, 3E from
/// edges, F from faces, 2C from corners; faces 4C from corners; edges 4E from edges, 6C from corners. A
/// copied point sphere and its face <- its vertex. Costs nothing when not asked for.
Mesh mlca(const Mesh& mesh, Origins* origins = nullptr);

}  // namespace dlfl
