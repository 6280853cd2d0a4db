// VTK legacy unstructured grids, ASCII and BINARY (dlfl/cells/vtk.h): parse, check, write both ways and read
// back equal.

#include <dlfl/cells/vtk.h>

#include "cell_check.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace dlfl;
  if (size > fuzz::max_cell_file) return 0;
  try {
    const CellComplex complex = parse_vtk(fuzz::text_of(data, size), fuzz::input_name);
    for (bool binary : {true, false}) {
      fuzz::check_read_complex(
          complex, [&](std::ostream& out) { write_vtk(out, complex, binary); },
          [](const std::string& text) { return parse_vtk(text, "rewritten"); });
    }
  } catch (const Error&) {
  }
  return 0;
}
