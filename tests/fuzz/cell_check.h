#pragma once
// What a successful read of a cell complex promises: `check_cell_complex` accepts it, and it writes and
// reads back equal.

#include <functional>
#include <sstream>
#include <string>

#include <dlfl/cells/cell_complex.h>
#include <dlfl/errors.h>

#include "fuzz_common.h"

namespace dlfl::fuzz {

inline constexpr std::size_t max_cell_file = 64 * 1024;

inline bool same_complex(const CellComplex& a, const CellComplex& b) {
  return a.positions == b.positions && a.offsets == b.offsets && a.indices == b.indices;
}

inline void check_read_complex(const CellComplex& complex, const std::function<void(std::ostream&)>& write,
                               const std::function<CellComplex(const std::string&)>& read) {
  try {
    check_cell_complex(complex);
  } catch (const Error& e) {
    finding(std::string("the complex read fails check_cell_complex: ") + e.what());
  }
  std::ostringstream out;
  write(out);
  CellComplex again;
  try {
    again = read(out.str());
  } catch (const Error& e) {
    finding(std::string("what was read does not read back after writing: ") + e.what());
  }
  check(same_complex(complex, again), "what was read reads back different after writing");
}

}  // namespace dlfl::fuzz
