#include <dlfl/cells/cell_complex.h>

#include <cmath>
#include <string>

#include <dlfl/errors.h>

namespace dlfl {

void CellComplex::add_cell(std::span<const std::uint32_t> cell) {
  if (dimension_of_size(cell.size()) < 0) {
    throw InvalidArgument("cell " + std::to_string(num_cells()) + " has " + std::to_string(cell.size()) +
                          " vertices; a d-cube has 1, 2, 4 or 8");
  }
  if (indices.size() + cell.size() > 0xFFFFFFFFu) {  // offsets are 32-bit
    throw InvalidArgument("cell " + std::to_string(num_cells()) +
                          ": more than 2^32 - 1 vertex indices in one complex");
  }
  append_list(cell);
}

void check_cell_complex(const CellComplex& complex) {
  if (complex.offsets.empty() || complex.offsets.front() != 0 ||
      complex.offsets.back() != complex.indices.size()) {
    throw InvalidArgument("cell complex: offsets do not describe the index list");
  }
  for (std::size_t v = 0; v < complex.positions.size(); ++v) {
    const glm::dvec3& p = complex.positions[v];
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) {
      throw InvalidArgument("cell complex: vertex " + std::to_string(v) + " has a non-finite coordinate");
    }
  }
  // All offsets first: a cell is read only once its range is known to lie inside `indices`.
  for (std::size_t i = 0; i < complex.num_cells(); ++i) {
    if (complex.offsets[i + 1] < complex.offsets[i] || complex.offsets[i + 1] > complex.indices.size()) {
      throw InvalidArgument("cell complex: offsets decrease or run past the index list at cell " +
                            std::to_string(i));
    }
  }
  const std::size_t nv = complex.positions.size();
  for (std::size_t i = 0; i < complex.num_cells(); ++i) {
    const auto cell = complex.cell(i);
    if (CellComplex::dimension_of_size(cell.size()) < 0) {
      throw InvalidArgument("cell " + std::to_string(i) + " has " + std::to_string(cell.size()) +
                            " vertices; a d-cube has 1, 2, 4 or 8");
    }
    for (std::uint32_t v : cell) {
      if (v >= nv) {
        throw InvalidArgument("cell " + std::to_string(i) + " uses vertex " + std::to_string(v) +
                              " but there are " + std::to_string(nv) + " vertices");
      }
    }
    for (std::size_t j = 0; j < cell.size(); ++j) {  // at most 8 vertices: pairwise is cheapest
      for (std::size_t k = j + 1; k < cell.size(); ++k) {
        if (cell[j] == cell[k]) {
          throw InvalidArgument("cell " + std::to_string(i) + " uses vertex " + std::to_string(cell[j]) +
                                " twice");
        }
      }
    }
  }
}

}  // namespace dlfl
