#pragma once
// Kobbelt's sqrt(3) subdivision on triangle meshes.

#include <string_view>

#include <dlfl/mesh.h>
#include <dlfl/schemes/boundary_rule.h>
#include <dlfl/schemes/origins.h>

namespace dlfl {

/// One step of Kobbelt's sqrt(3) subdivision of a triangle mesh:
/// - face point: the centroid of the triangle;
/// - vertex point: (1 - a_n) S + a_n / n (sum of the n neighbours), with a_n = (4 - 2 cos(2 pi / n)) / 9;
/// - every old edge (a, b), with triangles (a, b, x) and (b, a, y) on its sides, is flipped: it is replaced
///   by the edge between the two face points. Each old triangle is thus replaced by three triangles, one per
///   old edge side.
///
/// On a closed mesh: V' = V + F, E' = E + 3F = 3E, F' = 3F. Old vertices keep their valence, face points have
/// valence 6. The orientation is that of the input. One step only: two steps (a 1-to-9 refinement) are two
/// calls.
///
/// Output handles (the input read with its removed elements compacted away, handles in their old order):
/// - vertices: vertex v of the input is vertex v (moved by the vertex rule); the face point of face f is
///   vertex V + f;
/// - faces: triangle k comes from input corner k (F' = C = 3F): with x = vertex(k), F = face point of
///   face(k) and G = face point of the face across edge(k), it is (x, G, F) in that order from its first
///   corner. It lies across edge(k), on the side of vertex(k).
///
/// Open meshes (hole faces), by `boundary.rule` (docs/boundaries.md):
/// - `curve`, the default: Kobbelt's boundary rule, over pairs of steps, on holes of any size. A boundary
///   loop whose hole face is not marked with the boolean face attribute `sqrt3_trisect` is kept: its
///   vertices stay, its edges are not flipped (the triangle (a, b, x) on edge a -> b gives (a, b, F) with its
///   face point F), and the result marks its hole face. A marked loop is trisected: a boundary edge a -> b
///   gets the points (r + 16 a + 10 b) / 27 and (10 a + 16 b + s) / 27 (r before a, s after b along the
///   loop), a boundary vertex goes to (4 r + 19 a + 4 b) / 27 of its neighbours and itself, the triangle
///   (a, b, x) is cut into (a, p1, x), (p1, p2, x), (p2, b, x) instead of getting a face point (its other
///   edges are flipped as usual), and the mark is dropped. These are the ternary rules of the uniform cubic
///   B-spline, so the boundary depends only on the boundary polygon and converges to its cubic B-spline, as
///   under Catmull-Clark and Loop. A sharp boundary vertex stays (marked with the `sharp` vertex attribute,
///   with exactly two edges when `boundary.sharp_corners`, or where loops touch), a neighbour beyond it
///   replaced by the reflection 2 a - b (so the point of edge a -> b near a sharp a is (2a + b) / 3); a step
///   gives a corner a third edge, so the result marks every boundary vertex it kept sharp `sharp`, besides
///   carrying the input's marks. The marks carry the parity from call to call: `-n 2`, two calls, or two
///   editor steps agree (a polygon file drops attributes, so a loop read back from one is kept again).
///   Counts, with F the surface triangles, H holes with B corners in all, T the boundary edges trisected:
///   V' = V + F + T, E' = E + 3F + T, F' = 3F + H, B' = B + 2T. Numbering: old vertices, then the face points
///   of the triangles without a trisected edge in face order, then two points per trisected edge in edge
///   order (the one nearer from(e) first); triangle of surface corner c in corner order, then the hole faces
///   in face order. Throws TopologyError, naming the input's element, for an edge with holes on both sides
///   and for a triangle with two boundary edges on marked loops (a kept step leaves every triangle one at
///   most).
/// - `hole`: open meshes are refused, as before boundary rules (the flip mixes every face with its
///   neighbours, so no output triangle belongs to one old face): "sqrt3: f3 is a hole (a boundary loop) with
///   3 corners; sqrt(3) subdivision with boundary=hole needs a closed triangle mesh (...)".
/// A closed mesh gets the same result either way. The registered scheme's counts (V + F, 3E, 3F from V, E, F
/// with holes counted as faces) are exact on closed meshes; under `curve` on an open mesh E' and F' are upper
/// bounds (3E = E + 3F + B), and V' = V + F misses the true count by T - H.
///
/// Throws TopologyError, naming the first offending face in handle order, if a face is not a triangle
/// ("sqrt3: f7 has 4 corners; sqrt(3) subdivision needs triangles") or if the mesh has a point sphere (naming
/// its vertex). The input is not modified. O(size), in a few sequential passes.
///
/// Origins (filled when `origins` is given; handles of `mesh` itself): a vertex point <- its vertex, a face
/// point <- its face, a point of a trisected edge <- that edge; triangle k <- corner k, a hole face <- the
/// input's hole face; a flipped edge (between the points on the two sides of an old edge), a kept boundary
/// edge and a third of a trisected one <- that edge; every other edge joins an old vertex to a new point of a
/// triangle and stems from the triangle's corner at that vertex (on a closed mesh: the edge from vertex(c) to
/// the face point of face(c) <- c). By kind, on a closed mesh: vertices V from vertices, F from faces; faces
/// C from corners; edges E from edges, C from corners (open: vertices V, F - T from faces, 2T from edges;
/// faces C from corners, H from faces; edges E + 2T from edges, C - T from corners). Costs nothing when not
/// asked for.
Mesh sqrt3(const Mesh& mesh, const BoundaryOptions& boundary, Origins* origins = nullptr);

/// The same with the default boundary options (`curve`, sharp corners kept).
Mesh sqrt3(const Mesh& mesh, Origins* origins = nullptr);

/// The boolean face attribute by which a sqrt(3) step under the curve rule marks the hole faces of the loops
/// it kept, so that the next step trisects them (see `sqrt3`).
inline constexpr std::string_view sqrt3_trisect_attribute = "sqrt3_trisect";

}  // namespace dlfl
