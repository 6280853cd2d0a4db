#pragma once
// Internal to the shells (crust, rind, wireframe): the inner, mirrored copy of a mesh, built through the
// Euler operators in O(size), and the tubes that punch faces through to their twins.

#include <glm/vec3.hpp>
#include <span>
#include <string_view>
#include <vector>

#include <dlfl/mesh.h>
#include <dlfl/operations/transaction.h>

namespace dlfl::detail {

/// The copy of every element of the mesh as it was before the copy was made.
struct MirroredCopy {
  /// Per old vertex index: its copy (invalid for an index that was not live, or a point sphere left out).
  std::vector<VertexId> vertices;
  /// Per old edge index: its copy, joining the copies of its ends.
  std::vector<EdgeId> edges;

  /// The copy of corner c (of an old face with an edge): the corner of vertex(c)'s copy in the twin face.
  CornerId twin(const Mesh& mesh, CornerId c) const;
  /// The twin of an old face with an edge: the same vertices in the reverse order.
  FaceId twin(const Mesh& mesh, FaceId f) const { return mesh.face(twin(mesh, mesh.first_corner(f))); }
};

/// The order in which add_mirrored_copy inserts the copy's edges (see there). Deleting a mesh's edges in the
/// reverse order costs as little: each deletion merges one face into the rest, or strips a dangling edge.
std::vector<EdgeId> edge_build_order(const Mesh& mesh);

/// Deletes every edge of the mesh in the reverse build order, then every vertex that had one (their point
/// spheres); point spheres that were there before stay. O(size), plus the size of a component per handle.
void remove_surface(Transaction& tx);

/// Adds a copy of the whole mesh with every face reversed (v_0 ... v_{n-1} becomes v_{n-1} ... v_0), the copy
/// of vertex v at positions[v.index()], hole flags copied. V, E and F double (point spheres too, unless
/// `copy_point_spheres` is false). How: a point sphere per vertex; the edges of a spanning tree, each merging
/// a point sphere into the growing copy (O(1)); the edges that close the handles (2g per component); then the
/// edges of a spanning tree of the faces, leaves first, each splitting off exactly one face of the copy
/// (O(that face)). So the copy is O(size) plus, per handle, at most the size of its component.
MirroredCopy add_mirrored_copy(Transaction& tx, std::span<const glm::dvec3> positions,
                               bool copy_point_spheres = true);

/// Per vertex index: the position moved by -thickness along its vertex normal (`vertex_normal`; a vertex
/// with no normal stays). Unused indices get the origin. Refuses `param` (a ParameterError naming it) unless
/// thickness is finite and > 0 and every inner position is finite. O(size).
std::vector<glm::dvec3> inner_positions(const Mesh& mesh, std::string_view op, std::string_view param,
                                        double thickness);

/// Joins face f (an old face) to its twin by a tube of n quads (connect_faces, corner i of f to its twin):
/// V+0, E+n, F+n-2. Hole faces may be joined (the tube is surface).
void punch(Transaction& tx, const MirroredCopy& copy, FaceId f);

/// A closed shell: the mirrored copy at `inner` (per vertex index), then a tube from each face of `punched`
/// (old surface faces) and from each old hole face with an edge to its twin, so that open sheets close up.
/// Returns the copy.
MirroredCopy add_shell(Transaction& tx, std::span<const glm::dvec3> inner, std::span<const FaceId> punched,
                       bool copy_point_spheres = true);

}  // namespace dlfl::detail
