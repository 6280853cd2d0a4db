#pragma once
// OFF: polygons and positions.

#include <iosfwd>
#include <string>

#include <dlfl/errors.h>
#include <dlfl/io/parsed_polygons.h>

namespace dlfl {

/// Parses OFF (with optional ST/C/N prefixes). `name` is used in messages. Throws IoError with the name and
/// line for malformed or truncated input, out-of-range indices and non-finite coordinates.
ParsedPolygons parse_off(std::istream& in, const std::string& name);

/// Writes OFF, coordinates in shortest round-trip decimal so they read back bit-identical.
void write_off(std::ostream& out, const PolygonSoup& soup);

}  // namespace dlfl
