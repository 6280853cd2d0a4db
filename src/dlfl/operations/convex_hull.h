#pragma once
// convex_hull: the convex hull of a point set, or of a mesh's vertices, as a closed polyhedron of planar,
// strictly convex faces (docs/modeling.md, "Hulls").

#include <glm/vec3.hpp>
#include <span>

#include <dlfl/mesh.h>

namespace dlfl {

/// The convex hull of `points`: a closed genus-0 mesh whose vertices are points of the set (in increasing
/// order of their index; of coincident points, one), whose faces are planar, strictly convex polygons,
/// counter-clockwise seen from outside, no two neighbours coplanar, and which holds every point inside or
/// on it. It passes `convexity_violation` (dlfl/analysis/convex_polyhedron.h) around its vertex centroid,
/// so it is valid input for the Meng-Prautzsch schemes.
///
/// Method (docs/modeling.md, "Hulls"): the exact hull, built by a randomized incremental construction in
/// BRIO order whose points are located by a walk over the current hull, every orientation decided exactly;
/// its coplanar triangles are merged into faces, and points on its faces and edges left out. The structural
/// work is expected O(n) and the sort O(n); the walks are short because consecutive points are close (no
/// worst-case bound). Near-degenerate features are then simplified with an angle tolerance (4e-9 radians,
/// `detail::hull_angle_tolerance`): faces whose normals differ by at most that merge (if the merged face
/// stays within 2.5e-10 of the bounding-box diagonal of its plane), and a vertex at which a face turns by at
/// most that is left out; so a point may lie outside the result by at most the tolerance times the length of
/// the edges around it (0 for inputs without such near-degeneracies).
///
/// Throws ParameterError naming "points" (the message says why) for: fewer than 4 points; a non-finite
/// coordinate; points that all coincide, lie on one line or in one plane; points so nearly coplanar that the
/// vertex centroid of their hull is within 1e-8 of the diagonal of a face plane; and the rare inputs that
/// stay too close to degenerate for the tolerances (the message names the failed check).
Mesh convex_hull(std::span<const glm::dvec3> points);

/// The convex hull of the positions of the mesh's live vertices (point spheres included), as above. Its
/// vertices keep their vertex attribute values; every attribute of the mesh is declared on the result
/// (faces, edges and corners reading the defaults). Refusals name "mesh".
Mesh convex_hull(const Mesh& mesh);

}  // namespace dlfl
