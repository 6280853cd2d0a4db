#pragma once
// Honeycomb subdivision (Akleman and Srinivasan, "Honeycomb subdivision", sections 2 to 4): one new vertex
// per side of every edge, a shrunken copy of every face, and a new face around every old vertex. After one
// step every vertex is 3-valent; after that the number of non-hexagons stays constant.
//
// The remeshing is the paper's section 4, on the DLFL operators only:
//   1. for each face f = (v_0 .. v_{N-1}) of the input, compute v'_0 .. v'_{N-1} with formulas (1) and (2)
//      and call CREATEFACEMANIFOLD(v'_0 .. v'_{N-1}): a front face (v'_0 .. v'_{N-1}) and a back face;
//   2. for each edge of the input, INSERTEDGE between the back corners of the two new vertices made for its
//      two sides.
// The back faces merge and split into one face per old vertex (2 x valence corners); the front faces are
// never touched again.
//
// Decisions for inputs the paper does not discuss:
// - Open meshes (hole faces, one per boundary loop), by HoneycombParams::boundary.rule:
//   - `curve` (the default): the boundary rule, built like the step itself, vertex insertion then corner
//     cutting, on the boundary polygon alone. Vertex insertion: the midpoint of every boundary edge
//     (formula (1) with t = 1/2 whatever t is, so that the curve does not depend on which side of it the
//     surface lies). Corner cutting: every boundary vertex v, between boundary neighbours u and w, is cut
//     off by the chord between the midpoints of its two edges and replaced by the chord's midpoint
//     v/2 + (u + w)/4. Topologically the hole is a face whose points are the midpoints, and each vertex point
//     is one more corner of the boundary vertex's new face (it has two edges, both on the boundary): the
//     boundary loop doubles its corners, alternating 3-valent midpoints and 2-valent vertex points, as the
//     zigzag border of a hexagonal tiling does. Limit curve (docs/boundaries.md derives it): the uniform
//     quadratic B-spline whose control polygon is the polygon of the boundary edges' midpoints, a C1 curve
//     through (u + 2v + w)/4 at every boundary vertex (the vertex point is on it from the first step on, and
//     never moves again) and through (u + 7v + 7w + x)/16 halfway along each edge v w. A sharp boundary
//     vertex (marked `sharp`, or, with `sharp_corners`, with exactly two edges) keeps its place (its vertex
//     point is itself), which gives the clamped quadratic B-spline of (v, midpoints, ..., next sharp vertex)
//     between sharp vertices. A kept corner of two edges has two edges again in the result; the vertex point
//     of a marked vertex is marked `sharp` in the result. Note that after one step every other boundary
//     vertex has two edges: with `sharp_corners` they are all kept, which changes nothing, since each is
//     already the midpoint of its neighbours, where the rule would put it (up to rounding). Counts: with H
//     hole corners, V' = 2E + H, E' = 3E + H, F' = F + V; a hole of N corners becomes a hole of 2N.
//   - `hole` (the behaviour before boundary rules): hole faces are treated as ordinary faces, and the front
//     face made for a hole is flagged as a hole again. The hole therefore shrinks like any face; the result
//     is an open mesh with as many boundary loops as the input, each with as many corners as before.
// - Point spheres (a vertex without edges, whose face has one corner) have no edge to put a point on, so
//   formula (1) does not apply. They are copied through as point spheres at the same position (the only
//   affine-invariant choice for a single point), so stray vertices of a file survive the subdivision.
// - 2-gons are legal (N = 2 gives 3N - 5 = 1 and a_{0,1} = 1 - a). With the default tension a0 + a1/N, a
//   2-gon has a = 1.075, outside (0, 1), so meshes with 2-gons need a constant `a` (or other a0, a1).

#include <optional>

#include <dlfl/mesh.h>
#include <dlfl/schemes/boundary_rule.h>
#include <dlfl/schemes/origins.h>

namespace dlfl {

/// Parameters of formulas (1) and (2) of the paper.
struct HoneycombParams {
  /// The point (1 - t) v_m + t v_{m+1} on each edge of a face; must be in [0, 1].
  double t = 0.5;
  /// A constant tension in (0, 1). When unset, a face of N vertices uses a = a0 + a1 / N (the paper's choice
  /// with the defaults below: faces with more sides converge faster).
  std::optional<double> a;
  double a0 = 0.45;
  double a1 = 1.25;
  /// What the step does at the boundary loops of an open mesh (see above); the default is the boundary rule.
  BoundaryOptions boundary = {};
  /// The lateral rule against the bricklayers' problem (docs/lateral_artifacts.md): when the input is a
  /// control mesh (an inner vertex whose valence is not 3) with a flat region (two neighbouring faces in one
  /// plane), the step's new faces are planarized (vertices moved, the counts, 3-valence and topology
  /// unchanged; vertices on a hole stay), and kept only if that makes no more concave edges and no larger
  /// mean dihedral angle than the plain step. Off by default: off, or otherwise, the plain step, bit for bit.
  bool planarize = false;
};

/// Coefficient a_{n,m} of formula (2) for a face of N vertices with tension a: a if n = m, else
/// beta (1 - a) / (3N - 5) with beta = 3 + 2 cos(2 (n - m) pi / N). For 0 < a < 1 all coefficients are
/// positive and each row sums to 1. Throws InvalidArgument unless N >= 2 and n, m are in [0, N).
double honeycomb_coefficient(int N, int n, int m, double a);

/// The tension used for a face of N vertices: `p.a` when set, else p.a0 + p.a1 / N.
double honeycomb_tension(const HoneycombParams& p, int N);

/// Checks the parameters against a mesh: t in [0, 1]; a in (0, 1) when set, otherwise a0 + a1/N in (0, 1)
/// for every face size N >= 2 present in the mesh (hole faces included under `boundary = hole`, left out
/// under `curve`, whose holes do not use formula (2); point spheres excluded). Throws
/// InvalidArgument with a message that names the parameter and value, e.g. "honeycomb: parameter t = 1.5 is
/// outside [0, 1]". O(faces).
void check_honeycomb_params(const Mesh& mesh, const HoneycombParams& p);

/// One step of honeycomb subdivision of a valid mesh. The input is not modified; the result is a new mesh
/// with V' = 2E, E' = 3E, F' = F + V (hole faces counted as faces, point spheres aside; under the boundary
/// rule, H more vertices and edges for H hole corners), every vertex 3-valent (but the 2-valent boundary
/// vertex points of the boundary rule), and the topology (Euler characteristic and genus of every component)
/// of the input.
///
/// Handles are deterministic: the live faces of the input are visited in handle order, each appending its
/// CREATEFACEMANIFOLD (its front face starts at v'_0, the point for the face's first corner; under the
/// boundary rule a hole's starts at the vertex point of its first corner's vertex, followed by the midpoint
/// made for that corner) or, for a point sphere, one `create_vertex`; then one `insert_edge(back corner of
/// side 0, back corner of side 1)` per live edge in handle order. The result keeps the tombstones those
/// operators leave (no `compact()`).
///
/// Throws InvalidArgument for bad parameters (see `check_honeycomb_params`), or if a new point is not finite
/// (coordinates near overflow). Formula (2) costs O(N^2) per face of up to 64 sides (weights tabulated once
/// per size) and O(N) above (a closed form of its cosine sum), so one huge face cannot make a step
/// quadratic. Every element of the result is reserved up front, so the arrays never regrow.
///
/// Origins (filled when `origins` is given; handles of `mesh` itself; the result's tombstones have none):
/// - a new vertex <- the input corner it is made for (the point on the edge leaving the corner, in its face);
/// - a front face <- its input face (same size); the face around an old vertex <- that vertex (2 x valence
///   corners: the points of the corners at the vertex and of the corners before them);
/// - a front face's side from the point of corner c to the point of next(c) <- next(c), the corner it cuts
///   off; the edge inserted across an old edge <- that edge (it joins the points of its two side corners);
/// - a copied point sphere (vertex and face) <- its vertex;
/// - under the boundary rule, a boundary vertex point <- its vertex, and the hole front face's sides on both
///   sides of it <- the hole corner at that vertex.
/// By kind: vertices C from corners; faces F from faces, V from vertices; edges C from corners, E from edges.
/// Costs nothing when not asked for.
Mesh honeycomb(const Mesh& mesh, const HoneycombParams& p = {}, Origins* origins = nullptr);

}  // namespace dlfl
