// PLY polygon meshes, ASCII and binary little-endian (dlfl/io/ply.h): parse, build, validate, write both ways
// and read back.

#include <dlfl/io/ply.h>

#include "polygon_reader.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace dlfl;
  return fuzz::fuzz_polygon_file(
      data, size, io_detail::parse_ply_text,
      {[](std::ostream& out, const PolygonSoup& soup) { write_ply(out, soup, true); },
       [](std::ostream& out, const PolygonSoup& soup) { write_ply(out, soup, false); }});
}
