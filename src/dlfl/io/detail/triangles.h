#pragma once
// The triangles that the triangle formats (glTF, STL) write: each face that is not a hole cut into n - 2
// triangles by ear clipping in its plane, with the face's normal. Internal to the library.

#include <cstdint>
#include <glm/vec3.hpp>
#include <iosfwd>
#include <string>
#include <vector>

#include <dlfl/mesh.h>

namespace dlfl::io_detail {

/// The faces written and their triangles. Face i of the list has the corners
/// `corners[first_corner[i] .. first_corner[i + 1])`, in order from its first corner; each triangle is three
/// indices into `corners`, counter-clockwise seen from outside, and `triangle_face` names its face by its
/// place in `faces`.
struct MeshTriangles {
  std::vector<FaceId> faces;
  std::vector<glm::dvec3> normals;  ///< per face: its unit normal, zero for a degenerate face (geometry.h)
  std::vector<std::uint32_t> first_corner;
  std::vector<CornerId> corners;
  std::vector<std::uint32_t> triangles;
  std::vector<std::uint32_t> triangle_face;

  std::size_t num_triangles() const { return triangle_face.size(); }
};

/// The triangles of every live face of `mesh` that has three corners or more and is not a hole, faces in
/// handle order: a face of n corners gives n - 2 triangles, whose areas sum to the face's area when it is a
/// planar simple polygon, convex or not (detail/ear_clipping.h). A part that ear clipping cannot cut (a face
/// visiting a vertex more than once as a, b, a, b) is fanned into degenerate triangles, so that the count
/// stays n - 2. 2-gons and point spheres have no area and give none. Throws IoError naming `file` when there
/// is no triangle at all or a corner's coordinate is beyond the range of a 32-bit float, which both formats
/// store.
MeshTriangles mesh_triangles(const Mesh& mesh, const std::string& file);

/// Writes the triangles of `mesh` as STL (stl.h), binary or text.
void write_stl_triangles(std::ostream& out, const Mesh& mesh, const MeshTriangles& triangles, bool binary);

}  // namespace dlfl::io_detail
