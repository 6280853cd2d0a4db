// OBJ polygon meshes (dlfl/io/obj.h): parse, build, validate, write and read back.

#include <dlfl/io/obj.h>

#include "polygon_reader.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace dlfl;
  return fuzz::fuzz_polygon_file(data, size, io_detail::parse_obj_text,
                                 {[](std::ostream& out, const PolygonSoup& soup) { write_obj(out, soup); }});
}
