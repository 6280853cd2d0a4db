#pragma once
// PLY: polygons and positions, ASCII or binary little-endian.

#include <iosfwd>
#include <string>

#include <dlfl/errors.h>
#include <dlfl/io/parsed_polygons.h>

namespace dlfl {

/// Parses PLY, ASCII or binary_little_endian: the vertex x/y/z (any numeric type) and the face
/// vertex_indices list, skipping other properties and elements. Throws IoError with the name and the line
/// (or, in binary files, the element) for malformed or truncated input.
ParsedPolygons parse_ply(std::istream& in, const std::string& name);

/// Writes PLY: binary little-endian doubles, or ASCII in shortest round-trip decimal.
void write_ply(std::ostream& out, const PolygonSoup& soup, bool binary);

}  // namespace dlfl
