// STL, binary and text (dlfl/io/stl.h): parse, weld, build, validate, write both ways and read back.

#include <dlfl/io/stl.h>

#include "polygon_reader.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace dlfl;
  // The writers take a mesh: the soup's own (to_polygons keeps the faces' order and first corners, so the
  // triangles come back in the order read and weld to the same numbering).
  return fuzz::fuzz_polygon_file(
      data, size, io_detail::parse_stl_text,
      {[](std::ostream& out, const PolygonSoup& soup) { write_stl(out, build_mesh(soup), true); },
       [](std::ostream& out, const PolygonSoup& soup) { write_stl(out, build_mesh(soup), false); }});
}
