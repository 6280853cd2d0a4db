#include "cells/cell_average.h"

#include "dlfl/large_allocator.h"

namespace dlfl {

namespace {

constexpr std::int8_t in_no_cell = 4;  // above every dimension, so any cell lowers it

// dim[v] (in_no_cell for a vertex in no cell) and val[v], the number of cells of dimension dim[v] holding v.
template <class Dimensions, class Valences>
void dimensions_and_valences(const CellComplex& complex, Dimensions& dim, Valences& val) {
  dim.assign(complex.positions.size(), in_no_cell);
  val.assign(complex.positions.size(), 0);
  for (std::size_t i = 0; i < complex.num_cells(); ++i) {
    const auto d = static_cast<std::int8_t>(complex.dimension(i));
    for (std::uint32_t v : complex.cell(i)) {
      if (d < dim[v]) {
        dim[v] = d;
        val[v] = 1;
      } else if (d == dim[v]) {
        ++val[v];
      }
    }
  }
}

}  // namespace

std::vector<std::int8_t> crease_dimensions(const CellComplex& complex) {
  check_cell_complex(complex);
  std::vector<std::int8_t> dim;
  std::vector<std::uint32_t> val;
  dimensions_and_valences(complex, dim, val);
  for (auto& d : dim) {
    if (d == in_no_cell) d = -1;
  }
  return dim;
}

void cell_average(CellComplex& complex) {
  check_cell_complex(complex);
  detail::cell_average_unchecked(complex);
}

void detail::cell_average_unchecked(CellComplex& complex) {
  detail::LargeVector<std::int8_t> dim;  // huge pages, and blocks reused from the previous step
  detail::LargeVector<std::uint32_t> val;
  dimensions_and_valences(complex, dim, val);
  // Formula (1): each cell adds its centroid / val[v] to those of its vertices whose dim[v] is its dimension.
  detail::LargeVector<glm::dvec3> moved(complex.positions.size(), glm::dvec3(0.0));
  for (std::size_t i = 0; i < complex.num_cells(); ++i) {
    const auto cell = complex.cell(i);
    const auto d = static_cast<std::int8_t>(complex.dimension(i));
    glm::dvec3 centroid(0.0);
    for (std::uint32_t v : cell) centroid += complex.positions[v];
    centroid /= double(cell.size());
    for (std::uint32_t v : cell) {
      if (dim[v] == d) moved[v] += centroid / double(val[v]);
    }
  }
  // Written back in place: the positions' memory is mapped already.
  for (std::size_t v = 0; v < moved.size(); ++v) {
    if (dim[v] != in_no_cell) complex.positions[v] = moved[v];
  }
}

}  // namespace dlfl
