#pragma once
// The dual of a closed polygon mesh.

#include <dlfl/mesh.h>
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
/// Throws TopologyError, naming the element, when the dual is not a mesh of this kernel:
/// - a point sphere (a vertex without edges has no face around it);
/// - a hole face: the dual of an open mesh is not defined (the boundary would need a vertex that does not
///   stand for a face), and treating the hole as a face would silently close the surface;
/// - an edge with the same face on both sides (for example the edge of a valence-1 vertex): its dual would be
///   a self-loop.
/// O(size).
///
/// Origins (filled when `origins` is given; handles of `mesh` itself): output vertex <- the face it stands
/// for, output face <- the vertex, output edge <- the edge it crosses. By kind: vertices F from faces, faces
/// V from vertices, edges E from edges. Costs nothing when not asked for.
Mesh dual(const Mesh& mesh, Origins* origins = nullptr);

}  // namespace dlfl
