#pragma once
// Loop subdivision on triangle meshes.

#include <dlfl/mesh.h>
#include <dlfl/schemes/origins.h>

namespace dlfl {

/// One step of Loop subdivision of a closed triangle mesh, with the standard rules:
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
/// Hole faces: a triangular hole is subdivided like a face (the boundary is smoothed as if capped) and its
/// four triangles stay holes. A hole with another number of corners is refused like any non-triangle.
///
/// Throws TopologyError, naming the first offending face in handle order, if a face is not a triangle
/// ("loop: f7 has 4 corners; Loop subdivision needs triangles") or if the mesh has a point sphere (naming its
/// vertex: it has no edge, so no vertex rule). The input is not modified. O(size), in a few sequential
/// passes.
///
/// Origins (filled when `origins` is given; handles of `mesh` itself): a vertex point <- its vertex, an edge
/// point <- its edge; the corner triangle of corner c <- c, the central triangle of face f <- f; each half of
/// an old edge <- that edge, the inner edge of the corner triangle of c (between the edge points of edge(c)
/// and edge(prev c)) <- c. By kind: vertices V from vertices, E from edges; faces C from corners, F from
/// faces; edges 2E from edges, C from corners. Costs nothing when not asked for.
Mesh loop(const Mesh& mesh, Origins* origins = nullptr);

}  // namespace dlfl
