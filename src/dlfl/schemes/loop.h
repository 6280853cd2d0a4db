#pragma once
// Loop subdivision on triangle meshes.

#include <dlfl/mesh.h>
#include <dlfl/schemes/boundary_rule.h>
#include <dlfl/schemes/origins.h>

namespace dlfl {

/// One step of Loop subdivision of a triangle mesh, with the standard rules:
/// - edge point: 3/8 (a + b) + 1/8 (c + d), with a, b the ends of the edge and c, d the third vertices of its
///   two triangles;
/// - vertex point: (1 - n beta) S + beta (sum of the n neighbours), with
///   beta = (5/8 - (3/8 + cos(2 pi / n) / 4)^2) / n (Loop's original weights).
///
/// Every triangle becomes four: one at each of its corners and a central one. V' = V + E, E' = 2E + 3F,
/// F' = 4F; old vertices keep their valence and every edge point has valence 6. The orientation is that of
/// the input.
///
/// Output handles (the input read with its removed elements compacted away, handles in their old order):
/// - vertices: the vertex points first (vertex v of the input is vertex v), then the edge points (vertex
///   V + e for edge e);
/// - faces: triangle k, for k < C (C = 3F corners), is the corner triangle of input corner k: (vertex point
///   of vertex(k), edge point of edge(k), edge point of edge(prev(k))), in that order from its first corner.
///   Triangle C + f is the central triangle of face f: (edge points of the edges of the first, second and
///   third corner of f), starting with the edge point of edge(first_corner(f)).
///
/// Open meshes (hole faces), by `boundary.rule` (docs/boundaries.md):
/// - `curve`, the default: the cubic B-spline boundary rule, on holes of any size. A hole face stays one hole
///   face, whose sides are the halves of its edges (2n corners for n). A boundary edge's point is its
///   midpoint; a boundary vertex with one hole corner goes to (1/8, 6/8, 1/8) of its two neighbours along the
///   loop and itself; a sharp boundary vertex stays (marked with the `sharp` vertex attribute, with exactly
///   two edges when `boundary.sharp_corners`, or where loops touch; on a fan-triangulated grid two corners
///   have a diagonal, so three edges: mark them). Inner edges and vertices keep the rules above. So the
///   boundary depends only on the boundary polygon and converges to its uniform cubic B-spline (a chain
///   between sharp vertices: to the B-spline of the chain extended by 2 p0 - p1 at each end). Counts, with F
///   the surface triangles, H holes with B corners in all: V' = V + E, E' = 2E + 3F, F' = 4F + H, B' = 2B.
///   Numbering: vertices as above; the corner triangles of the surface corners in corner order, the central
///   triangles of the surface faces in face order, then the hole faces in face order. The result carries the
///   input's `sharp` marks on the vertex points.
/// - `hole`: a triangular hole is subdivided like a face (the boundary is smoothed as if capped) and its four
///   triangles stay holes; a hole with another number of corners is refused like any non-triangle. This is
///   what a log written before boundary rules replays with.
/// A closed mesh gets the same result either way. The registered scheme's counts (from V, E, F with holes
/// counted as faces) are exact on closed meshes and under `hole`, and bound the curve rule's from above.
///
/// Throws TopologyError, naming the first offending face in handle order, if a face is not a triangle
/// ("loop: f7 has 4 corners; Loop subdivision needs triangles") or if the mesh has a point sphere (naming its
/// vertex: it has no edge, so no vertex rule). The input is not modified. O(size), in a few sequential
/// passes.
///
/// Origins (filled when `origins` is given; handles of `mesh` itself): a vertex point <- its vertex, an edge
/// point <- its edge; the corner triangle of corner c <- c, the central triangle of face f <- f; each half of
/// an old edge <- that edge, the inner edge of the corner triangle of c (between the edge points of edge(c)
/// and edge(prev c)) <- c; under `curve`, a hole face <- the input's hole face. By kind: vertices V from
/// vertices, E from edges; faces C from corners, F from faces (and H from faces); edges 2E from edges, C from
/// corners. Costs nothing when not asked for.
Mesh loop(const Mesh& mesh, const BoundaryOptions& boundary, Origins* origins = nullptr);

/// The same with the default boundary options (`curve`, sharp corners kept).
Mesh loop(const Mesh& mesh, Origins* origins = nullptr);

}  // namespace dlfl
