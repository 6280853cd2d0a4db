#pragma once
// hexagonalize: the bricklayers' solution to the honeycomb's lateral artifacts (Akleman and Srinivasan,
// "Honeycomb subdivision", section 5; docs/lateral_artifacts.md, docs/modeling.md "Cleanup and shape"): the
// control mesh is turned into hexagons, and the hexagons that straddle a sharp edge or a border are cut along
// it, as a bricklayer cuts tiles along the edge of a wall. Every new vertex lies on the old surface; when
// every bend of the input is at a sharp edge (flat regions meeting at creases) the shape does not change.
//
// Construction, on a valid mesh:
// 1. The honeycomb's topology with points that stay on their own face: the point for corner c of face f (on
//    the edge leaving c) is halfway between that edge's midpoint and f's centroid. Every face f gets its
//    shrunken copy (the points of its corners, in f's plane), and every vertex v a face of 2 x valence
//    corners (the two points of each face at v, in order around v); the edge that joins the points on both
//    sides of an old edge crosses it.
// 2. An edge is sharp when the normals of its two faces differ by more than `angle` degrees, or when it is on
//    a border (a hole on one side). A vertex with two or more sharp edges is cut: its face is split along its
//    sharp edges. Each crossing of a sharp edge e = (v, w) gets a point on e for each cut end: at one third
//    of e from that end when both ends are cut (the crossing then runs along e between the two points,
//    which keeps every such point 3-valent), at e's midpoint when one end is cut (or e is on a border). The
//    face of a cut vertex v is then cut into one piece per sector between its sharp edges: through a new
//    vertex at v's position (its hub, joined to the point of each sharp edge at v) when v has three or more
//    sharp edges, is on a border, or its two sharp edges are not in line; by one edge between the points of
//    its two sharp edges when they are in line. On a border, the piece on the hole's side is left out, so
//    the border is the old one with each edge's midpoint added.
// Every piece lies in the faces of one sector, so when the faces of each sector are coplanar (the case the
// construction is for) every face of the result is planar and the sharp edges become lines of edges, with
// the third edges of their points alternating sides (a cut honeycomb). Every vertex is 3-valent but the hubs
// (valence: the vertex's sharp edges) and the border's midpoints (3) and hubs.
//
// Counts, with E edges, V vertices, F faces (holes not counted) and B border edges of the input; k_v the
// sharp edges at v; the cut vertices those with k_v >= 2; H hubs, L in-line cut vertices (cut by one edge); C
// the points on sharp edges that are not on a border (for each such edge, its number of cut ends):
//   V' = 2E + C + H,   E' = 3E - B + C + L + (sum of k_v over the hubs),
//   F' = F + V + (sum of k_v - 1 over the cut vertices) - (the border's vertices) + holes,
// the holes being as many as before (a border of N edges becomes one of 2N). Point spheres are kept as they
// are. Topology and orientation are kept.
//
// Named attributes are declared on the result and carried where an element of the result stands for an
// input element of the same kind (see `hexagonalize`'s origins): a face's shrunken copy keeps the face's
// values, a hole its hole's, a hub its vertex's, a point sphere its own; the edges crossing or lying along an
// input edge keep that edge's values; the corners at the point of corner c (in f's shrunken copy and in the
// face of c's vertex) keep c's. Everything else (the points of the corners and of the sharp edges, the faces
// of the vertices) reads the default.

#include <dlfl/mesh.h>
#include <dlfl/schemes/origins.h>

namespace dlfl {

struct HexagonalizeOptions {
  /// An edge between two faces is sharp when their normals differ by more than this, in degrees; in [0, 180].
  /// A face without a normal (zero area) makes none of its edges sharp. Border edges are always sharp.
  double angle = 1.0;
};

/// Refuses, with a ParameterError naming the parameter: `angle` outside [0, 180] (or not a number); a mesh
/// (`mesh`) with a 2-gon that is not a hole (its shrunken copy would be a 2-gon, which no polygon list
/// holds), or with an edge that has the same face on both sides. O(size).
void check_hexagonalize(const Mesh& mesh, const HexagonalizeOptions& options = {});

/// The hexagonalized mesh (see above), a new mesh; the input is not modified. Checks first (see
/// `check_hexagonalize`). Handles: the points of the corners in handle order, then the points on sharp edges
/// (edge handle order, the edge's side-0 end first), then the hubs (vertex handle order), then the point
/// spheres; faces: the shrunken copies in face handle order, then the faces and pieces of each vertex in
/// vertex handle order, then the holes. O(size).
///
/// Origins (filled when `origins` is given; handles of `mesh`): the point of corner c <- c, a point on a
/// sharp edge <- that edge, a hub <- its vertex; a shrunken copy <- its face, the face or a piece of vertex v
/// <- v, a hole <- its hole; the side of a shrunken copy from the point of c to that of next(c) <- next(c),
/// the edges crossing input edge e and the edges along it <- e, the edge across an in-line cut vertex <- that
/// vertex; a point sphere's vertex <- its vertex, its face <- its face.
Mesh hexagonalize(const Mesh& mesh, const HexagonalizeOptions& options = {}, Origins* origins = nullptr);

}  // namespace dlfl
