#pragma once
// Helpers of the cell-complex file tests: exact comparison, and (from test_helpers.h) scratch folders and
// files from strings.

#include <doctest/doctest.h>

#include <cstring>

#include <dlfl/cells/cell_complex.h>
#include "test_helpers.h"

namespace dlfl::test {

/// Same cells in the same order and bit-identical positions.
inline void check_identical(const CellComplex& a, const CellComplex& b) {
  REQUIRE(a.positions.size() == b.positions.size());
  CHECK(std::memcmp(a.positions.data(), b.positions.data(), a.positions.size() * sizeof(glm::dvec3)) == 0);
  CHECK(a.offsets == b.offsets);
  CHECK(a.indices == b.indices);
}

}  // namespace dlfl::test
