#pragma once
// Conversions of polygon meshes and polyhedra into cell complexes (Bajaj, Schaefer, Warren, Xu, section 3.3),
// so that MLCA can start from meshes that are not made of d-cubes.

#include <dlfl/cells/cell_complex.h>
#include <dlfl/mesh.h>
#include <dlfl/polygon_soup.h>

namespace dlfl {

/// Splits each n-gon of a polygon soup into n quads (quads too): corner j of a face becomes the quad of its
/// vertex, the midpoints of its two edges and the face centroid (the average of its vertices). In
/// tensor-product order that quad is (v_j, midpoint of v_j v_{j+1}, midpoint of v_{j-1} v_j, centroid), so
/// its boundary cycle runs the same way round as the face.
///
/// Numbering: vertex i keeps index i; then one midpoint per distinct edge (an unordered vertex pair, so the
/// faces on either side of an edge, or any number of faces at a non-manifold edge, share it) in order of
/// first appearance (faces in order, edge v_j v_{j+1} at j); then one centroid per face, in face order. Quad
/// k comes from the k-th corner of the soup. So V' = V + E + F and the cell count is the number of corners.
///
/// Throws InvalidArgument naming the face for a face of fewer than 3 vertices, an index out of range or a
/// vertex repeated within a face, and naming the vertex for a non-finite position. O(size).
CellComplex polygons_to_quads(const PolygonSoup& soup);

/// Splits a closed polyhedron whose vertices are all 3-valent (a tetrahedron, a cube, a prism, a
/// dodecahedron, ...) into one hexahedron per vertex: the vertex, the midpoints of its 3 edges, the centroids
/// of its 3 faces and the centroid of the polyhedron (the average of its vertices). The polyhedron should be
/// convex (or at least star-shaped from that centroid) for the hexahedra to be proper; this is not checked.
/// Each connected component is split as a polyhedron of its own.
///
/// The hexahedron of vertex v, with e_0, e_1, e_2 its edges in the order of its corners around it
/// (`next_around_vertex`, starting at `corner(v)`) and f_k the face of the k-th corner (which holds e_k and
/// e_{k-1}), is, in tensor-product order: (v, mid e_0, mid e_1, f_1, mid e_2, f_0, f_2, centroid). Axes e_0,
/// e_1, e_2 are then right-handed for a mesh whose faces run counter-clockwise seen from outside.
///
/// Numbering (handles of the compacted mesh): vertex v keeps its index, midpoint of edge e is V + e, centroid
/// of face f is V + E + f, centroid of the c-th component (in order of their smallest vertex) is V + E + F +
/// c. Hexahedron v is cell v.
///
/// Throws TopologyError naming the element for a vertex whose valence is not 3, a hole face (an open mesh),
/// or a component that is not a topological sphere (V - E + F != 2). O(size).
CellComplex polyhedron_to_hexahedra(const Mesh& mesh);

}  // namespace dlfl
