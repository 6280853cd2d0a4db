#pragma once
// STL, binary and text: triangles only, each on its own, with a facet normal.

#include <iosfwd>
#include <string>

#include <dlfl/errors.h>
#include <dlfl/io/parsed_polygons.h>
#include <dlfl/mesh.h>

namespace dlfl {

/// Parses STL, binary or text. A file is binary when its size is 84 + 50 x the triangle count in bytes 80 to
/// 83 (whatever its header says: some binary files start with "solid" too), text when it starts with "solid"
/// otherwise. STL stores no connectivity: corners at identical positions (+0 and -0 alike) are welded into
/// one vertex, numbered in order of first appearance (the coordinates of a text file are rounded to float32
/// first, as binary STL stores them, so that both forms of a file read alike), and each triangle becomes a
/// face in file order (its vertex order, counter-clockwise seen from outside, gives its orientation; the
/// stored normal is not read). Throws IoError naming `name`, with the line of a text file or the triangle and
/// byte offset of a binary one, for: a size that matches no binary STL and no "solid" start, a truncated file
/// or trailing bytes after the triangles, a coordinate beyond float32, text that breaks the grammar (solid,
/// facet normal, outer loop, three vertex lines, endloop, endfacet, endsolid; several solids may follow each
/// other), a number that does not parse or is not finite, and a triangle with two corners at the same
/// position (it has no area).
ParsedPolygons parse_stl(std::istream& in, const std::string& name);

/// Writes `mesh` as STL, binary (an 80-byte header, the triangle count, 50 bytes per triangle) or text
/// ("solid dlfl" ... "endsolid dlfl"). The triangles are those of write_glb (gltf.h): each face that is not a
/// hole cut into n - 2 triangles by ear clipping in its plane, 2-gons and point spheres left out; each
/// triangle's facet normal is its face's unit normal (zero for a degenerate face). Coordinates are float32
/// in both forms (text writes each float's shortest round-trip decimal), so both forms read back to the same
/// triangles. Nothing is written before the checks: throws IoError naming `name` for a mesh with no triangle
/// or a coordinate beyond float32.
void write_stl(std::ostream& out, const Mesh& mesh, bool binary, const std::string& name = "STL output");

}  // namespace dlfl
