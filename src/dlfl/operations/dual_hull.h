#pragma once
// dual_hull: the polar dual of the convex hull about its vertex centroid (docs/modeling.md, "Hulls").

#include <glm/vec3.hpp>
#include <span>

#include <dlfl/mesh.h>

namespace dlfl {

/// The polar dual of H = convex_hull(points) about c, the centroid of H's vertices: a vertex for every face
/// of H, at the pole of its plane, c + r^2 n / d (n the face's outward unit normal, d > 0 its plane's
/// distance from c); a face for every vertex of H, around it as the faces of H go around the vertex; an edge
/// across every edge. So V' = F, E' = E, F' = V, and the face of vertex v lies in the plane
/// {x : (v - c).(x - c) = r^2}. r^2 is the mean distance d of H's face planes times the mean distance of
/// its vertices from c, which keeps the size: a cube or a regular polyhedron gets a dual with the same
/// circumradius. The dual of a convex polyhedron with c inside is convex: planar, strictly convex faces.
/// Its vertex i is the pole of H's face i.
///
/// Refuses (ParameterError naming "points") what convex_hull refuses, and the rare hulls whose dual is too
/// close to degenerate for the convexity check (a face of H with a corner of almost zero angle gives a
/// dual face that almost does not turn there; the message names the failed check).
Mesh dual_hull(std::span<const glm::dvec3> points);

/// The dual hull of the positions of the mesh's live vertices. Every attribute of the mesh is declared on
/// the result, with default values (its elements stand for faces, vertices and edges of the hull, not of
/// the mesh). Refusals name "mesh".
Mesh dual_hull(const Mesh& mesh);

}  // namespace dlfl
