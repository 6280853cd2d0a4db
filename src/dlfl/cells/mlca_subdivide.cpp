#include <dlfl/cells/mlca_subdivide.h>

#include <algorithm>
#include <cstdint>
#include <string>

#include <dlfl/cells/cell_average.h>
#include <dlfl/cells/multilinear_subdivide.h>
#include <dlfl/errors.h>

namespace dlfl {

CellComplex mlca_subdivide(const CellComplex& complex, int iterations) {
  if (iterations < 0) {
    throw InvalidArgument("mlca: iterations must be at least 0, got " + std::to_string(iterations));
  }
  check_cell_complex(complex);  // once: subdivision of a valid complex is valid
  // Refuse a result beyond 32-bit indices before spending the time: after t steps a d-cell has become 2^(dt)
  // cells of 2^d vertices each.
  std::uint64_t final_indices = 0;
  int top_dimension = 0;
  for (std::size_t i = 0; i < complex.num_cells(); ++i) {
    top_dimension = std::max(top_dimension, complex.dimension(i));
    const std::int64_t bits = std::int64_t(complex.dimension(i)) * (std::int64_t(iterations) + 1);
    final_indices += bits >= 33 ? std::uint64_t(1) << 33 : std::uint64_t(1) << bits;
    if (final_indices > 0xFFFFFFFFu) {
      throw InvalidArgument("mlca: " + std::to_string(iterations) +
                            " iterations would give more cell vertex indices than 32 bits can address");
    }
  }
  if (iterations == 0) return complex;
  // Points alone never split and never move (0-cells are interpolated): one step is as good as any number.
  if (top_dimension == 0) iterations = 1;
  CellComplex result = detail::multilinear_subdivide_unchecked(complex);
  detail::cell_average_unchecked(result);
  for (int i = 1; i < iterations; ++i) {
    result = detail::multilinear_subdivide_unchecked(result);
    detail::cell_average_unchecked(result);
  }
  return result;
}

}  // namespace dlfl
