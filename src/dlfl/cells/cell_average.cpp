#include <dlfl/cells/cell_average.h>

#include <span>

#include <dlfl/detail/large_allocator.h>

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
  const std::size_t nv = complex.positions.size(), nc = complex.num_cells();
  auto centroid_of = [&](std::span<const std::uint32_t> cell) {
    glm::dvec3 sum(0.0);
    for (std::uint32_t v : cell) sum += complex.positions[v];
    return sum / double(cell.size());
  };
  // Formula (1), with the division by val[v] done once per vertex at the end: sum[v] gathers the centroids of
  // the cells of dimension dim[v] that contain v, val[v] counts them.
  detail::LargeVector<glm::dvec3> sum(nv, glm::dvec3(0.0));  // huge pages, blocks reused from the last step
  detail::LargeVector<std::uint32_t> val;
  bool mixed = false;
  for (std::size_t i = 1; i < nc && !mixed; ++i) mixed = complex.dimension(i) != complex.dimension(0);
  if (!mixed) {  // one dimension, so dim[v] is that dimension for every vertex in a cell: one pass
    val.assign(nv, 0);
    for (std::size_t i = 0; i < nc; ++i) {
      const auto cell = complex.cell(i);
      const glm::dvec3 centroid = centroid_of(cell);
      for (std::uint32_t v : cell) {
        sum[v] += centroid;
        ++val[v];
      }
    }
  } else {
    detail::LargeVector<std::int8_t> dim;
    dimensions_and_valences(complex, dim, val);
    for (std::size_t i = 0; i < nc; ++i) {
      const auto cell = complex.cell(i);
      const auto d = static_cast<std::int8_t>(complex.dimension(i));
      const glm::dvec3 centroid = centroid_of(cell);
      for (std::uint32_t v : cell) {
        if (dim[v] == d) sum[v] += centroid;
      }
    }
  }
  // Written back in place (the positions' memory is mapped already); a vertex in no cell has val 0 and stays.
  for (std::size_t v = 0; v < nv; ++v) {
    if (val[v] > 0) complex.positions[v] = sum[v] / double(val[v]);
  }
}

}  // namespace dlfl
