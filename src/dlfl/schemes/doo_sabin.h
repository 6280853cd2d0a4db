#pragma once
// Doo-Sabin subdivision on any polygon mesh.

#include <dlfl/mesh.h>
#include <dlfl/schemes/origins.h>

namespace dlfl {

/// One Doo-Sabin step. The input is not modified.
///
/// Points: every corner of the input gets one new point, computed in its face. For a face with vertices
/// v_0 .. v_{n-1} (in order from any corner: the rule is invariant under rotation), the point of corner i is
///   p_i = sum_k alpha_k v_{i+k mod n},  alpha_0 = 1/4 + 5/(4n),  alpha_k = (3 + 2 cos(2 pi k / n)) / (4n),
/// weights that sum to 1 (affine invariant). A face visiting a vertex twice gives that vertex both weights.
///
/// Faces, all oriented like the input (counter-clockwise seen from outside):
/// - an F-face per input face: its n new points, in the face's order;
/// - an E-face (quad) per input edge: the four points of the edge's two ends in its two faces;
/// - a V-face per input vertex: the points of its corners, one per corner (size = valence).
/// So V' = number of corners, E' = 2 x corners, F' = V + E + F; every new vertex is 4-valent, and the
/// topology (Euler characteristic and genus of every component) is kept.
///
/// Handles (deterministic, a function of the input's live-handle order; tombstones of the input are ignored):
/// - output vertex k = the k-th live corner of the input;
/// - faces: F-faces first in input face order, then E-faces in edge order, then V-faces in vertex order;
/// - corners: the F-face of face f starts at the point of first_corner(f); the E-face of edge e runs
///   (c0, next(c1), c1, next(c0)) with c0, c1 its side-0 and side-1 corners; the V-face of v starts at the
///   point of corner(v) and continues along prev_around_vertex (counter-clockwise).
///
/// 2-gons are fine (n = 2: alpha = 7/8, 1/8), and so are vertices of valence 2 (their V-faces are 2-gons).
///
/// Hole faces (boundary loops of an open mesh) are treated as faces: the boundary is smoothed as if the hole
/// were capped by a face, so its new points are pulled towards the hole's centroid. The F-face of a hole is
/// flagged as a hole again; its E-faces and V-faces are ordinary faces. The result is an open mesh with as
/// many boundary loops as the input, each with as many corners as before.
///
/// Throws TopologyError, naming the vertex, for a point sphere (a vertex with no edge has no face to put a
/// point in) and for a vertex of valence 1 (its V-face would have one corner and an edge from a point to
/// itself). O(size) plus O(n) per face of more than 64 sides (its sums are evaluated in closed form).
///
/// Origins (filled when `origins` is given; handles of `mesh` itself): the point of corner c <- c; an F-face
/// <- its face, an E-face <- its edge, a V-face <- its vertex; an F-face's side from the point of c to the
/// point of next(c) (along edge(c), inside face(c)) <- c; a V-face's side, which crosses an old edge near one
/// of its ends, <- that edge (each edge is crossed twice, once at each end). By kind: vertices C from
/// corners; faces F, E, V from faces, edges, vertices; edges C from corners, C = 2E from edges. Costs
/// nothing when not asked for.
Mesh doo_sabin(const Mesh& mesh, Origins* origins = nullptr);

}  // namespace dlfl
