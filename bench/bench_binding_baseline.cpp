// The C++ side of the Python binding's benchmark (python/bench/bench_binding.py, which runs this program in
// the same run, on the same meshes):
//   build N M RUNS: build_mesh of the N x M quad torus's polygons (bench_meshes.h), what Mesh.from_arrays
//     costs beyond converting its arrays;
//   insert_edge CALLS N M RUNS: CALLS calls of Editor::insert_edge on the N x M quad torus, the diagonal of
//     face f (corners 4f and 4f + 2) for f = 0, 1, ..., each run on a fresh editor.
// Prints the best and median seconds of the runs.
// Usage: dlfl_bench_binding_baseline build [n=1000] [m=1000] [runs=5]
//        dlfl_bench_binding_baseline insert_edge [calls=100000] [n=400] [m=250] [runs=5]

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include <dlfl/build_mesh.h>
#include <dlfl/history/editor.h>
#include "bench_meshes.h"
#include "bench_util.h"

using namespace dlfl;

namespace {

long arg(int argc, char** argv, int i, long fallback) { return argc > i ? std::atol(argv[i]) : fallback; }

int usage() {
  std::fprintf(stderr,
               "usage: dlfl_bench_binding_baseline build [n] [m] [runs]\n"
               "       dlfl_bench_binding_baseline insert_edge [calls <= n*m] [n] [m] [runs]\n");
  return 2;
}

void print(const char* what, std::vector<double> seconds) {
  std::sort(seconds.begin(), seconds.end());
  std::printf("%s: best %.6f s, median %.6f s\n", what, seconds.front(), seconds[seconds.size() / 2]);
}

}  // namespace

int main(int argc, char** argv) {
  const std::string mode = argc > 1 ? argv[1] : "";
  if (mode == "build") {
    const long n = arg(argc, argv, 2, 1000), m = arg(argc, argv, 3, 1000), runs = arg(argc, argv, 4, 5);
    if (n < 3 || m < 3 || runs < 1) return usage();
    const PolygonSoup soup = bench::torus_soup(int(n), int(m));
    std::vector<double> seconds;
    for (long r = 0; r < runs; ++r)
      seconds.push_back(bench::median_seconds(1, [&] { (void)build_mesh(soup); }));
    print("build_mesh", seconds);
    return 0;
  }
  if (mode != "insert_edge") return usage();
  const long calls = arg(argc, argv, 2, 100000), n = arg(argc, argv, 3, 400), m = arg(argc, argv, 4, 250);
  const long runs = arg(argc, argv, 5, 5);
  if (calls < 0 || n < 3 || m < 3 || runs < 1 || calls > n * m) return usage();
  const Mesh torus = build_mesh(bench::torus_soup(int(n), int(m)));
  std::vector<double> seconds;
  for (long r = 0; r < runs; ++r) {
    Editor editor;
    editor.set_mesh(torus);
    seconds.push_back(bench::median_seconds(1, [&] {
      for (long f = 0; f < calls; ++f) {
        editor.insert_edge(CornerId(std::uint32_t(4 * f)), CornerId(std::uint32_t(4 * f + 2)));
      }
    }));
    if (editor.mesh().num_edges() != torus.num_edges() + std::size_t(calls)) return 1;
  }
  print("Editor::insert_edge", seconds);
  return 0;
}
