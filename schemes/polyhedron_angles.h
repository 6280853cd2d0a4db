#pragma once
// The angle measurements of Meng and Prautzsch, definition 2.3, which their theorems bound: edge, vertex and
// face angles of a polyhedron, in radians. All come from the outward face normals (the Gaussian image).

#include <cstddef>

#include "dlfl/mesh.h"

namespace dlfl {

/// Edge angle: the exterior dihedral angle of the edge, the angle between the normals of its two faces (the
/// length of the dual edge in the Gaussian image). 0 for coplanar faces; for a concave edge the same unsigned
/// angle. Use on edges between two non-hole faces.
double edge_angle(const Mesh& mesh, EdgeId e);

/// Vertex angle: the largest angle between two supporting planes through the vertex, i.e. the spherical
/// diameter of the vertex's face in the Gaussian image. That face is the spherical polygon of the normals of
/// the faces around the vertex, and its diameter is the largest angle between two of them. O(valence^2).
/// Hole faces are left out; 0 for a point sphere.
double vertex_angle(const Mesh& mesh, VertexId v);

/// Face angle: the largest angle between two supporting planes through vertices of the face, i.e. the
/// spherical diameter of the 1-ring of the face's normal in the Gaussian image: the largest angle between the
/// normals of two faces that share a vertex with this face (the face itself included). Hole faces are left
/// out.
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
  AngleSummary face;    ///< over non-hole faces
};

/// All three measurements at once, computing each face normal once. Cost O(sum over vertices of
/// valence^2 + sum over faces of the size of their vertex 1-ring squared), linear for bounded valences and
/// face sizes.
PolyhedronAngles polyhedron_angles(const Mesh& mesh);

}  // namespace dlfl
