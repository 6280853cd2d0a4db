// OFF polygon meshes (dlfl/io/off.h): parse, build, validate, write and read back.

#include <dlfl/io/off.h>

#include "polygon_reader.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace dlfl;
  return fuzz::fuzz_polygon_file(data, size, io_detail::parse_off_text,
                                 {[](std::ostream& out, const PolygonSoup& soup) { write_off(out, soup); }});
}
