#pragma once
// The angle measurements of Meng and Prautzsch, definition 2.3, which their theorems bound: edge, vertex and
// face angles of a polyhedron, in radians. All come from the outward face normals (the Gaussian image).
//
// The Gaussian-image polygon G_v of a vertex v has the unit normals of the faces around v as its vertices, in
// rotation order, and the minor great-circle arcs between the normals of consecutive faces as its edges.
// Spherical diameters (the largest angle between two points) of G_v and of unions of them are exact: up to 90
// degrees they are attained between two normals; above, possibly between a normal and a point inside an arc
// (the regular tetrahedron's vertex angle is 125.26 degrees, not the 109.47 between two normals); and 180
// degrees also between two points inside two crossing arcs (the tetrahedron's face angle). All three are
// searched. Points inside the polygons need no search: such a point can be moved farther from the other one
// until 180 degrees; and on a convex polyhedron, where every G_v lies in an open hemisphere and the polygons
// of a face's vertices all contain the face's normal, neither can contain the antipodal image of the other,
// so an antipodal pair of a 1-ring always shows on the arcs. Faces without a normal (holes, faces of zero
// area) are left out: around a boundary vertex G_v is then an open chain of arcs, one arc per edge between
// two faces that have normals, and a normal with no such neighbour is a lone point. Two consecutive normals
// that are equal or exactly opposite (no minor arc) count as their endpoints only. On a non-convex mesh G_v
// may cross itself; it is still taken as its arcs.

#include <cstddef>

#include <dlfl/mesh.h>

namespace dlfl {

/// Edge angle: the exterior dihedral angle of the edge, the angle between the normals of its two faces (the
/// length of the dual edge in the Gaussian image). 0 for coplanar faces; for a concave edge the same unsigned
/// angle. Throws TopologyError naming the edge if a hole face lies on either side.
double edge_angle(const Mesh& mesh, EdgeId e);

/// Vertex angle: the largest angle between two supporting planes through the vertex, i.e. the spherical
/// diameter of its Gaussian-image polygon G_v (see the top of this file). 0 for a point sphere, or when no
/// face around the vertex has a normal. Cost O(valence^2).
double vertex_angle(const Mesh& mesh, VertexId v);

/// Face angle: the largest angle between two supporting planes through vertices of the face, i.e. the
/// spherical diameter of the 1-ring of the face's normal in the Gaussian image: of the union of the polygons
/// G_v of the face's vertices. Computed as the largest of the vertex angles and, for every pair v != w of the
/// face's vertices, of the largest angle between a point of G_v and a point of G_w. Cost O(sum over the
/// face's vertices v of valence(v)^2 + sum over pairs v != w of valence(v) valence(w)). Throws TopologyError
/// naming the face if it is a hole.
double face_angle(const Mesh& mesh, FaceId f);

/// Maximum and mean of one kind of angle over a mesh (radians; both 0 when `count` is 0).
struct AngleSummary {
  double max = 0.0;
  double mean = 0.0;
  std::size_t count = 0;
};

/// Edge, vertex and face angles of a whole mesh.
struct PolyhedronAngles {
  AngleSummary edge;    ///< over edges with no hole face on either side
  AngleSummary vertex;  ///< over vertices that are not point spheres
  AngleSummary face;    ///< over non-hole faces that are not point spheres
};

/// All three measurements at once, computing each face normal and each vertex angle once (the face angles
/// reuse the vertex angles) and the cross term of an edge's two ends once for both faces of the edge. Cost
/// O(sum over vertices v of valence(v)^2 + sum over faces F of (sum over F's vertices v of valence(v) +
/// sum over pairs v != w of F's vertices of valence(v) valence(w))): linear in the mesh size for bounded
/// valences and face sizes, but quadratic in a large valence or a large face. A pyramid over an n-gon costs
/// up to about 16 n^2 normal-against-arc tests (the apex n^2, the side faces 6 n^2, the base 9 n^2, which
/// stop early once 180 degrees is reached): n = 2000 takes about 0.2 s, n = 20000 about 20 s, a million quads
/// of bounded valence about 1 s.
PolyhedronAngles polyhedron_angles(const Mesh& mesh);

}  // namespace dlfl
