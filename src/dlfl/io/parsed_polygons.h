#pragma once
// What a polygon-file parser returns: the polygons, plus the file line of each vertex and face for messages.

#include <cstddef>
#include <string>
#include <vector>

#include <dlfl/build_mesh.h>
#include <dlfl/mesh.h>
#include <dlfl/polygon_soup.h>

namespace dlfl {

/// A parsed file: the polygons plus, for error messages, the file line of each vertex and face (0 where a
/// line does not apply, as in binary PLY).
struct ParsedPolygons {
  PolygonSoup soup;
  std::vector<std::size_t> vertex_lines;
  std::vector<std::size_t> face_lines;
  /// How the file numbers its vertices and faces, for messages: faces from 1, vertices as the file's
  /// indices (from 1 in OBJ, from 0 in OFF and PLY).
  SoupNumbering numbering{0, 1};
};

/// Builds the mesh from parsed polygons, turning a PolygonError into an IoError at the offending file line.
Mesh build_mesh(const ParsedPolygons& parsed, const std::string& name);

}  // namespace dlfl
