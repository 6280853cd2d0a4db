#pragma once
// Root-3 subdivision built the DLFL way: dual, honeycomb, dual.

#include <dlfl/mesh.h>
#include <dlfl/schemes/honeycomb.h>

namespace dlfl {

/// One root-3 step as dual(honeycomb(dual(mesh), p)), the way the DLFL literature derives it from the
/// honeycomb scheme. The input is not modified.
///
/// Topology (closed meshes; the boundary rules add points along the boundary). Let the input have V vertices,
/// E edges, F faces and C = 2E corners. Its dual D has F vertices, E edges and V faces (face v of D has
/// valence(v) sides, vertex f of D has valence size(f)). The honeycomb step H of D has 2E vertices, all
/// 3-valent, 3E edges, and F + V faces: a front face of valence(v) sides per face of D (per input vertex v)
/// and a face of 2 size(f) sides per vertex of D (per input face f). The final dual therefore has
///   V' = V + F,  E' = 3E,  F' = 2E (= C), every face a triangle (H is 3-valent),
/// with a vertex per input vertex keeping its valence and a vertex per input face f of valence 2 size(f).
/// Its edges are: one between each input vertex and each face it bounds (one per corner, 2E of them, the
/// duals of H's front-face edges), and one between the two faces of each input edge (E of them, the duals of
/// the edges the honeycomb inserts). The topology of every component is kept.
///
/// Comparison with Kobbelt's sqrt(3) (`sqrt3`, dlfl/schemes/sqrt3.h). On a triangle mesh (3F = 2E) the result
/// has V' = V + F, E' = 3E, F' = 3F triangles, old vertices keeping their valence and one 6-valent vertex per
/// old triangle, joined to its three corners and, across every old edge, to the neighbouring triangle's
/// vertex: exactly the connectivity of sqrt(3) (insert a vertex per triangle, connect it to the corners, flip
/// the old edges). The positions differ: sqrt(3) keeps the old positions in play (new vertex = triangle
/// centroid, old vertex relaxed by alpha_n = (4 - 2 cos(2 pi / n)) / 9), while here no input position is used
/// directly: the points come from face centroids of the first dual, smoothed by the honeycomb's a_{n,m}
/// coefficient rule on D's faces (one per input vertex), then averaged by the second dual. Since the
/// honeycomb keeps each face's centroid, an input vertex goes to the average of the centroids of its faces
/// whatever the parameters: on a triangle mesh 1/3 v + 2/3 (average of its neighbours), sqrt(3)'s rule with
/// alpha_n replaced by 2/3. docs/schemes.md measures the difference. For example, on a
/// regular tetrahedron centred at the origin an old vertex v moves to v / 9 (sqrt(3): 7 v / 27) and the
/// vertex of the face opposite v sits at -a v / 9 with the honeycomb tension a of a triangle (sqrt(3):
/// -v / 3). Unlike sqrt(3), this works on any polygon mesh (always giving triangles).
///
/// Open meshes, by `p.boundary.rule`:
/// - `curve` (the default): the three steps with their boundary rules (see `dual` and `honeycomb`). The first
///   dual keeps and marks the sharp boundary vertices (two edges with `sharp_corners`, or marked `sharp`);
///   the honeycomb and the second dual then keep the marked ones only, since the honeycomb leaves every other
///   boundary vertex with two edges. One step maps the boundary polygon p to the points
///   (p_{i-1} + 5 p_i + 7 p_{i+1} + 3 p_{i+2}) / 16 and (3 p_i + 7 p_{i+1} + 5 p_{i+2} + p_{i+3}) / 16
///   (between sharp vertices), which depend on the boundary polygon alone; their limit is the uniform quartic
///   B-spline whose control points are the twice-midpointed polygon (p_{i-1} + 2 p_i + p_{i+1}) / 4
///   (docs/boundaries.md). Counts: those of the three steps in turn (each header's closed forms).
/// - `hole`: refused by the first dual, as before.
///
/// Handles: those of dual(honeycomb(dual(mesh), p)) (see `dual` and `honeycomb`; the honeycomb's tombstones
/// are compacted away by the second dual), so deterministic.
///
/// Errors: TopologyError (from the first dual, prefixed "dual-honeycomb-dual: ") for point spheres, hole
/// faces under `boundary = hole` and edges with the same face on both sides.
/// InvalidArgument for honeycomb parameters that do not fit the dual's faces (see `check_honeycomb_params`):
/// the dual's N-sided faces are the input's N-valent vertices, so with the default tension a vertex of
/// valence 2 (a = 1.075) is rejected.
///
/// Origins (filled when `origins` is given; handles of `mesh` itself), those of the three steps taken back
/// to the input: the vertex of an input vertex <- that vertex, the vertex of an input face <- that face; the
/// triangle for input corner c (the dual of the honeycomb vertex made for c's corner of the first dual) <- c,
/// and it holds the vertices of vertex(c) and face(c); the edge from the vertex of v to the vertex of a face
/// f at v <- the corner of v in f; the edge between the vertices of the two faces of an input edge <- that
/// edge. By kind: vertices V from vertices, F from faces; faces C from corners; edges C from corners, E from
/// edges. Costs nothing when not asked for.
Mesh dual_honeycomb_dual(const Mesh& mesh, const HoneycombParams& p = {}, Origins* origins = nullptr);

}  // namespace dlfl
