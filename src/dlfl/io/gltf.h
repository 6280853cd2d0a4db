#pragma once
// glTF 2.0 binary (.glb), for viewers and other programs: one mesh of one triangle primitive. Written, not
// read.

#include <iosfwd>
#include <string>

#include <dlfl/errors.h>
#include <dlfl/mesh.h>

namespace dlfl {

/// Writes `mesh` as a .glb file: a 12-byte header, a JSON chunk padded with spaces and a BIN chunk padded
/// with zeros to 4 bytes, holding one node with one mesh of one primitive of triangles (mode 4). Each face
/// that is not a hole becomes n - 2 triangles by ear clipping in its plane (right for planar faces, convex or
/// not; io/detail/triangles.h); 2-gons and point spheres have no area and are left out. The vertices are the
/// faces' corners, split per face, so that each carries its face's normal (flat shading) and its face:
/// attributes POSITION (float32, with the min and max glTF requires), NORMAL (float32, unit; +z for a
/// degenerate face) and _FACE_INDEX (the face's handle index as a float32, which is exact up to 2^24; glTF
/// allows unsigned 32-bit integers only for indices), and indices as uint32. Nothing is written before
/// the checks: throws IoError naming `name` for a mesh with no triangle, a coordinate beyond float32, or a
/// face handle index of 2^24 or more.
void write_glb(std::ostream& out, const Mesh& mesh, const std::string& name = "glTF output");

}  // namespace dlfl
