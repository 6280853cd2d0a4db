// A cell complex beside the DLFL: a cube of 8 vertices as one hexahedron with a crease curve along one edge,
// smoothed by two MLCA steps. Usage: example_cell_complex
#include <dlfl/dlfl.h>

#include <cstdio>

int main() {
  dlfl::CellComplex complex;
  for (int i = 0; i < 8; ++i)
    complex.positions.push_back({double(i & 1), double((i >> 1) & 1), double(i >> 2)});
  complex.add_cell({0, 1, 2, 3, 4, 5, 6, 7});  // the hexahedron, in tensor-product order
  complex.add_cell({0, 1});                    // a crease: this edge is a curve of its own
  dlfl::check_cell_complex(complex);
  const dlfl::CellComplex smooth = dlfl::mlca_subdivide(complex, 2);
  std::printf("cells %zu -> %zu, vertices %zu -> %zu\n", complex.num_cells(), smooth.num_cells(),
              complex.positions.size(), smooth.positions.size());
  // Two steps: the hexahedron into 8^2 = 64, the crease segment into 2^2 = 4.
  return smooth.num_cells() == 64 + 4 ? 0 : 1;
}
