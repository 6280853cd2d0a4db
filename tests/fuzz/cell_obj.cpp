// OBJ cell complexes, `v`, `p`, `l` and `f` (dlfl/cells/cell_obj.h): parse, check, write and read back
// equal; and the test that sends an OBJ file down the cell-complex path.

#include <dlfl/cells/cell_obj.h>

#include "cell_check.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace dlfl;
  if (size > fuzz::max_cell_file) return 0;
  const std::string_view text = fuzz::text_of(data, size);
  (void)obj_has_cell_statements(text);
  try {
    const CellComplex complex = parse_cell_obj(text, fuzz::input_name);
    fuzz::check_read_complex(
        complex, [&](std::ostream& out) { write_cell_obj(out, complex); },
        [](const std::string& written) { return parse_cell_obj(written, "rewritten"); });
  } catch (const Error&) {
  }
  return 0;
}
