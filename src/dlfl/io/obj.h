#pragma once
// Wavefront OBJ: polygons and positions.

#include <iosfwd>
#include <string>

#include <dlfl/errors.h>
#include <dlfl/io/parsed_polygons.h>

namespace dlfl {

/// Parses OBJ: `v`, `f` with `v`, `v/vt`, `v//vn`, `v/vt/vn` and negative (relative) indices, comments;
/// other statements are ignored. `name` is used in messages. Throws IoError with the name and line for
/// malformed or truncated input, out-of-range indices and non-finite coordinates.
ParsedPolygons parse_obj(std::istream& in, const std::string& name);

/// Writes OBJ, coordinates in shortest round-trip decimal so they read back bit-identical.
void write_obj(std::ostream& out, const PolygonSoup& soup);

}  // namespace dlfl
