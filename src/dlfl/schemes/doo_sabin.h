#pragma once
// Doo-Sabin subdivision on any polygon mesh.

#include <dlfl/mesh.h>
#include <dlfl/schemes/boundary_rule.h>
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
/// 2-gons are fine (n = 2: alpha = 7/8, 1/8), and so are inner vertices of valence 2 (their V-faces are
/// 2-gons).
///
/// Open meshes (hole faces, one per boundary loop), by `boundary.rule`:
/// - `curve` (the default): Chaikin's rule along the boundary polygon. A hole corner h at vertex a, between
///   the boundary edges from z to a and from a to b (hole order), gets two points instead of one:
///   out(h) = 3/4 a + 1/4 b on its own edge and in(h) = 3/4 a + 1/4 z on the edge before, both on the
///   boundary; they replace the hole's points in the E-faces of the boundary edges and in the V-face of a
///   (which thus has two corners for the hole's one), and the hole's F-face, still a hole, runs
///   in(h_0), out(h_0), in(h_1), ... So the boundary of the result depends only on the boundary polygon, and
///   it is Chaikin's refinement of it: its limit is the uniform quadratic B-spline of the boundary polygon,
///   which passes through the midpoint of every boundary edge (tangent to the edge) and through
///   (z + 6 a + b) / 8 next to each vertex a (docs/boundaries.md derives it). The faces inside are the usual
///   F-faces of their corners. A sharp boundary vertex (marked `sharp`, or with exactly two edges when
///   `boundary.sharp_corners`; see BoundaryOptions) keeps its place: both points of its hole corner are the
///   vertex itself (one output vertex), and the points next to it on its two edges are the edge midpoints,
///   which is the clamped quadratic B-spline (Bezier at both ends) of each chain of the boundary between
///   sharp vertices. A sharp corner with one face would get a 2-gon V-face (its face's point and the kept
///   vertex); that V-face is left out, so the kept vertex has three edges and no 2-gon is made; the kept
///   vertex is marked `sharp` in the result, so it stays in place over later steps.
///   Counts: with H hole corners, S of them at sharp vertices and K dissolved V-faces, V' = 2E + H - S,
///   E' = 4E + H - S - K, F' = V + E + F - K; the hole F-face of a hole of n corners, s of them sharp, has
///   2n - s corners. Handles: as below, the in-points of the split hole corners numbered after the nc corner
///   points in corner order, and V-faces that are left out take no face handle (those after them shift).
/// - `hole` (the behaviour before boundary rules): hole faces are treated as faces: the boundary is smoothed
///   as if the hole were capped by a face, so its new points are pulled towards the hole's centroid. The
///   F-face of a hole is flagged as a hole again; its E-faces and V-faces are ordinary faces. The result is
///   an open mesh with as many boundary loops as the input, each with as many corners as before.
/// On a closed mesh both give the same result, bit for bit.
///
/// Throws TopologyError, naming the vertex, for a point sphere (a vertex with no edge has no face to put a
/// point in) and for a vertex of valence 1 (its V-face would have one corner and an edge from a point to
/// itself). O(size) plus O(n) per face of more than 64 sides (its sums are evaluated in closed form).
///
/// Origins (filled when `origins` is given; handles of `mesh` itself): the point of corner c <- c; an F-face
/// <- its face, an E-face <- its edge, a V-face <- its vertex; an F-face's side from the point of c to the
/// point of next(c) (along edge(c), inside face(c)) <- c; a V-face's side, which crosses an old edge near one
/// of its ends, <- that edge (each edge is crossed twice, once at each end). Under `curve`: both points of a
/// hole corner <- that corner; the side in(h) -> out(h) <- h; the edge between a face's point and a kept
/// corner whose V-face is left out <- the face's corner there. By kind: vertices C from corners; faces F, E,
/// V from faces, edges, vertices; edges C from corners, C = 2E from edges. Costs nothing when not asked for.
Mesh doo_sabin(const Mesh& mesh, const BoundaryOptions& boundary, Origins* origins = nullptr);

/// The same with the default boundary options (`curve`, sharp corners kept).
Mesh doo_sabin(const Mesh& mesh, Origins* origins = nullptr);

}  // namespace dlfl
