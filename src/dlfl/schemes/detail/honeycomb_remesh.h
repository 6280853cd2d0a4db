#pragma once
// The remeshing of honeycomb subdivision (Akleman and Srinivasan, section 4), shared by every scheme with the
// honeycomb's topology (the DLFL honeycomb and Zhang-Wang's honeycomb with central control vertices). Only
// the new points differ between them; the operators that connect the points are the same.

#include <functional>
#include <span>
#include <vector>

#include <dlfl/mesh.h>
#include <dlfl/schemes/boundary_rule.h>
#include <dlfl/schemes/origins.h>

namespace dlfl::detail {

/// The new points of one face: `corners` are the face's corners from its first corner, and `points[i]` must
/// receive the new vertex for corner i, the one on the edge leaving that corner (both spans have the face's
/// size).
using FacePointsFn =
    std::function<void(FaceId face, std::span<const CornerId> corners, std::span<glm::dvec3> points)>;

/// A honeycomb step's mesh, with where its faces came from.
struct HoneycombRemesh {
  Mesh mesh;
  /// By input face handle: the new face that is the face's shrunken copy (its front face); invalid for
  /// removed faces and for point spheres (whose vertex is copied and has no front face).
  std::vector<FaceId> face_of_face;
  /// By input vertex handle, filled only when asked for (or when origins are): the new face around the
  /// vertex (for a point sphere, the copied point sphere's face); invalid for removed vertices.
  std::vector<FaceId> face_of_vertex;
};

/// Section 4 on the kernel's operators: for every live face of `mesh` in handle order, CREATEFACEMANIFOLD of
/// the points `face_points` gives (the front face starts at the point for the face's first corner; a hole's
/// front face is flagged as a hole again), or `create_vertex` at the same place for a point sphere; then,
/// for every live edge in handle order, INSERTEDGE between the back corners of the two points made for its
/// two sides. V' = 2E, E' = 3E, F' = F + V, every new vertex 3-valent. All elements are reserved up front.
/// `face_points` is called once per face, in handle order.
///
/// Under `boundary.rule == curve` (on a mesh with holes) a hole's face manifold has two points per corner h
/// (at vertex v_i, between boundary neighbours u and w, hole order): the boundary vertex point
/// `honeycomb_boundary_vertex(u, v_i, w, sharp)` and then the midpoint of the edge leaving h, the point made
/// for h that the edge across joins; `face_points` is not called for holes. So each boundary vertex's face
/// gets one more corner (the vertex point, of valence 2), the hole's front face has 2N corners and stays a
/// hole, and V' = 2E + H, E' = 3E + H, F' = F + V with H the hole corners. The sharp vertices are those of
/// `sharp_boundary_vertices(mesh, boundary, scheme)`; the vertex point of each vertex marked `sharp` is
/// marked `sharp` in the result (a corner kept for having two edges keeps two edges, so it needs no mark).
/// Under `hole` the hole is treated as a face, as above.
///
/// When `origins` is given it receives the honeycomb's origins (see `honeycomb`): a new vertex <- the corner
/// it is made for, a front face <- its face, a vertex's face <- the vertex, a front face's side from the
/// point of c to the point of next(c) <- next(c) (the corner it cuts off), an inserted edge <- the edge it
/// crosses; a copied point sphere and its face <- its vertex; under `curve`, a boundary vertex point <- its
/// vertex, and the hole front face's side from a vertex point to the next point <- the hole corner it cuts
/// off, like the side before it.
HoneycombRemesh honeycomb_remesh(const Mesh& mesh, const FacePointsFn& face_points, bool want_face_of_vertex,
                                 const BoundaryOptions& boundary, const char* scheme,
                                 Origins* origins = nullptr);

}  // namespace dlfl::detail
