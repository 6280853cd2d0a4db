#include "cells/mlca.h"

#include <string>

#include "cells/cell_average.h"
#include "cells/multilinear_subdivide.h"
#include "dlfl/errors.h"

namespace dlfl {

CellComplex mlca_subdivide(const CellComplex& complex, int iterations) {
  if (iterations < 0) {
    throw InvalidArgument("mlca: iterations must be at least 0, got " + std::to_string(iterations));
  }
  check_cell_complex(complex);  // once: subdivision of a valid complex is valid
  if (iterations == 0) return complex;
  CellComplex result = detail::multilinear_subdivide_unchecked(complex);
  detail::cell_average_unchecked(result);
  for (int i = 1; i < iterations; ++i) {
    result = detail::multilinear_subdivide_unchecked(result);
    detail::cell_average_unchecked(result);
  }
  return result;
}

}  // namespace dlfl
