// OFF polygon meshes (dlfl/io/off.h): parse, build, validate, write and read back.

#include <dlfl/io/off.h>

#include "polygon_reader.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace dlfl;
  if (size > fuzz::max_mesh_file) return 0;
  try {
    fuzz::check_polygon_file(fuzz::text_of(data, size), io_detail::parse_off_text,
                             {[](std::ostream& out, const PolygonSoup& soup) { write_off(out, soup); }});
  } catch (const Error&) {
  }
  return 0;
}
