#pragma once
// Kobbelt's sqrt(3) subdivision on triangle meshes.

#include <dlfl/mesh.h>
#include <dlfl/schemes/origins.h>

namespace dlfl {

/// One step of Kobbelt's sqrt(3) subdivision of a closed triangle mesh:
/// - face point: the centroid of the triangle;
/// - vertex point: (1 - a_n) S + a_n / n (sum of the n neighbours), with a_n = (4 - 2 cos(2 pi / n)) / 9;
/// - every old edge (a, b), with triangles (a, b, x) and (b, a, y) on its sides, is flipped: it is replaced
/// by
///   the edge between the two face points. Each old triangle is thus replaced by three triangles, one per
///   old edge side.
///
/// V' = V + F, E' = E + 3F = 3E, F' = 3F. Old vertices keep their valence, face points have valence 6. The
/// orientation is that of the input. One step only: two steps (a 1-to-9 refinement) are two calls; there is
/// no boundary rule.
///
/// Output handles (the input read with its removed elements compacted away, handles in their old order):
/// - vertices: vertex v of the input is vertex v (moved by the vertex rule); the face point of face f is
///   vertex V + f;
/// - faces: triangle k comes from input corner k (F' = C = 3F): with x = vertex(k), F = face point of
///   face(k) and G = face point of the face across edge(k), it is (x, G, F) in that order from its first
///   corner. It lies across edge(k), on the side of vertex(k).
///
/// Throws TopologyError, naming the first offending face in handle order, if a face is not a triangle
/// ("sqrt3: f7 has 4 corners; sqrt(3) subdivision needs triangles"), if a face is a hole (the flip mixes
/// every face with its neighbours, so no output triangle belongs to one old face, and sqrt(3)'s boundary rule
/// is not implemented: open meshes are refused), or if the mesh has a point sphere (naming its vertex). The
/// input is not modified. O(size), in a few sequential passes.
///
/// Origins (filled when `origins` is given; handles of `mesh` itself): a vertex point <- its vertex, a face
/// point <- its face; triangle k <- corner k; a flipped edge (between the face points on the two sides of an
/// old edge) <- that edge, the edge from vertex(c) to the face point of face(c) <- c. By kind: vertices V
/// from vertices, F from faces; faces C from corners; edges E from edges, C from corners. Costs nothing when
/// not asked for.
Mesh sqrt3(const Mesh& mesh, Origins* origins = nullptr);

}  // namespace dlfl
