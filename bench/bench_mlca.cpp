// MLCA benchmark: one step of MLCA subdivision on a 50^3 grid of hexahedra (1M output hexahedra), on a
// 500 x 500 torus of quads as a cell complex (1M output quads) beside Catmull-Clark on the same torus as a
// DLFL mesh, and on a closed curve of 500k segments (1M output segments). Median and best wall time of
// repeated runs, and the halves of a step (multi-linear split, cell averaging) on their own.
// Usage: dlfl_bench_mlca [runs=5]

#include <cmath>
#include <cstdio>
#include <functional>
#include <numbers>
#include <string>

#include <dlfl/build_mesh.h>
#include <dlfl/cells/cell_average.h>
#include <dlfl/cells/mlca_subdivide.h>
#include <dlfl/cells/multilinear_subdivide.h>
#include <dlfl/schemes/catmull_clark.h>
#include "bench_meshes.h"
#include "bench_util.h"
#include "test_meshes.h"

using namespace dlfl;

namespace {

CellComplex hex_grid(int n) {
  CellComplex c;
  auto id = [n](int i, int j, int k) { return std::uint32_t(i + (n + 1) * (j + (n + 1) * k)); };
  for (int k = 0; k <= n; ++k) {
    for (int j = 0; j <= n; ++j) {
      for (int i = 0; i <= n; ++i)
        c.positions.push_back({i + 0.1 * std::sin(j + k), j, k + 0.1 * std::cos(i)});
    }
  }
  for (int k = 0; k < n; ++k) {
    for (int j = 0; j < n; ++j) {
      for (int i = 0; i < n; ++i) {
        c.add_cell({id(i, j, k), id(i + 1, j, k), id(i, j + 1, k), id(i + 1, j + 1, k), id(i, j, k + 1),
                    id(i + 1, j, k + 1), id(i, j + 1, k + 1), id(i + 1, j + 1, k + 1)});
      }
    }
  }
  return c;
}

CellComplex closed_curve(int n) {
  CellComplex c;
  for (int i = 0; i < n; ++i) {
    const double a = 2 * std::numbers::pi * i / n;
    c.positions.push_back({std::cos(a), std::sin(a), 0.1 * std::sin(5 * a)});
  }
  for (int i = 0; i < n; ++i) c.add_cell({std::uint32_t(i), std::uint32_t((i + 1) % n)});
  return c;
}

void report(const char* name, std::size_t in_cells, std::size_t out_cells, const bench::Timing& t) {
  std::printf("%-34s %8zu -> %8zu cells  median %7.4f s  best %7.4f s\n", name, in_cells, out_cells, t.median,
              t.best);
  std::fflush(stdout);
}

void measure_complex(const char* name, const CellComplex& input, int runs) {
  // The first run meets fresh memory from the kernel, as a one-shot `dlfl subdivide` does; later runs reuse
  // freed blocks.
  std::size_t cells = 0;
  const bench::Timing first = bench::time_runs(1, [&] { cells = mlca_subdivide(input).num_cells(); });
  report(name, input.num_cells(), cells,
         bench::time_runs(runs, [&] { cells = mlca_subdivide(input).num_cells(); }));
  report("  first run (fresh memory)", input.num_cells(), cells, first);
  report("  multi-linear split only", input.num_cells(), cells,
         bench::time_runs(runs, [&] { cells = multilinear_subdivide(input).num_cells(); }));
  CellComplex fine = multilinear_subdivide(input);
  // Averaging again costs the same as the first time: run it in place.
  report("  cell averaging only", fine.num_cells(), fine.num_cells(),
         bench::time_runs(runs, [&] { cell_average(fine); }));
}

}  // namespace

int main(int argc, char** argv) {
  const int runs = argc > 1 ? std::stoi(argv[1]) : 5;
  std::printf("one MLCA step to about 1M cells, %d runs each\n", runs);
  const double steal = bench::steal_seconds();
  measure_complex("mlca hexahedra (50^3 grid)", hex_grid(50), runs);
  const PolygonSoup soup = bench::torus_soup(500, 500);
  measure_complex("mlca quads (500^2 torus)", test::quads_of(soup), runs);
  const Mesh mesh = build_mesh(soup);
  std::size_t faces = 0;
  report("catmull-clark, same torus (DLFL)", mesh.num_faces(), faces = catmull_clark(mesh).num_faces(),
         bench::time_runs(runs, [&] { faces = catmull_clark(mesh).num_faces(); }));
  measure_complex("mlca curve (500k segments)", closed_curve(500000), runs);
  std::printf("CPU steal by the VM host during the measurements: %.2f s\n", bench::steal_seconds() - steal);
  return 0;
}
