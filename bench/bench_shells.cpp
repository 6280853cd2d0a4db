// Shells benchmark: crust and wireframe of a closed quad torus of about 1M faces, each as one Transaction
// (the library functions) and as an editor operation (parameters checked, one undo entry). Both must be
// O(size): the figures for a quarter of the faces show the rate holds. The target: under 2 s each
// at 1M faces.
// Usage: dlfl_bench_shells [faces=1000000] [runs=3]

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include <dlfl/build_mesh.h>
#include <dlfl/history/editor.h>
#include <dlfl/operations/crust.h>
#include <dlfl/operations/transaction.h>
#include <dlfl/operations/wireframe.h>
#include "bench_meshes.h"
#include "bench_util.h"

using namespace dlfl;

namespace {

// Times `run` alone on fresh copies of `start` (the copy is made before the clock starts).
template <class Run>
void measure(const char* what, const Mesh& start, int runs, Run run) {
  std::vector<double> seconds;
  std::size_t v = 0, e = 0, f = 0;
  for (int i = 0; i < runs; ++i) {
    Mesh m = start;
    const auto t0 = std::chrono::steady_clock::now();
    const Mesh& after = run(m);
    seconds.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
    v = after.num_vertices(), e = after.num_edges(), f = after.num_faces();
  }
  std::sort(seconds.begin(), seconds.end());
  std::printf("%-26s %8zu faces -> V %8zu E %8zu F %8zu: median %.3f s, best %.3f s\n", what,
              start.num_faces(), v, e, f, seconds[seconds.size() / 2], seconds.front());
}

void run_size(long faces, int runs) {
  const int side = int(std::lround(std::sqrt(double(faces))));
  const Mesh start = build_mesh(bench::torus_soup(side, side));
  for (const char* op : {"crust", "wireframe"}) {
    const std::string name = op;
    measure((name + " (Transaction)").c_str(), start, runs, [&](Mesh& m) -> const Mesh& {
      Transaction tx(m);
      if (name == "crust") {
        crust(tx);
      } else {
        wireframe(tx);
      }
      tx.commit();
      return m;
    });
    Editor ed;
    measure((name + " (Editor::apply)").c_str(), start, runs, [&](Mesh& m) -> const Mesh& {
      ed.set_mesh(std::move(m));
      ed.apply(name, {});
      return ed.mesh();
    });
  }
}

}  // namespace

int main(int argc, char** argv) {
  const long faces = argc > 1 ? std::atol(argv[1]) : 1000000;
  const int runs = argc > 2 ? std::atoi(argv[2]) : 3;
  run_size(faces / 4, runs);
  run_size(faces, runs);
  std::printf("peak resident memory %.0f MiB\n", bench::peak_rss_mib());
  return 0;
}
