#pragma once
// The description of a cell complex that `dlfl info` prints and `dlfl.info` returns in Python.

#include <string>

#include <dlfl/cells/cell_complex.h>

namespace dlfl {

/// A JSON object: "vertices", "cells", "cells_by_dimension" ({"0": n0, ..., "3": n3}) and "bbox" ([[min],
/// [max]], all zero without vertices). `indent` as nlohmann::json::dump takes it (-1: one line). O(size).
std::string cell_complex_info_json(const CellComplex& complex, int indent = 2);

}  // namespace dlfl
