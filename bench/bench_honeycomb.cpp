// Honeycomb benchmark: one step on quad tori sized for about 10k and 1M output faces; time (median) and the
// extra peak memory of the step on top of the input. Usage: dlfl_bench_honeycomb [runs=5]

#include <cmath>
#include <cstdio>
#include <numbers>

#include <dlfl/build_mesh.h>
#include <dlfl/detail/block_cache.h>
#include <dlfl/schemes/honeycomb.h>
#include "bench_meshes.h"
#include "bench_util.h"

using namespace dlfl;

namespace {

struct Result {
  bench::Timing time;
  std::size_t faces;
  double extra_bytes_per_face;
};

Result measure(int n, int runs) {
  const Mesh input =
      build_mesh(bench::torus_soup(n, n));  // F = V = n^2, so one step gives F' = F + V = 2 n^2
  std::size_t faces = 0;
  const bench::Timing t = bench::time_runs(runs, [&] { faces = honeycomb(input).num_faces(); });
  // Peak memory of one more step, on its own: reset the high-water mark, run, read it.
  double extra = -1;
  release_block_cache();  // cached blocks are resident already and would hide the step's own footprint
  if (bench::reset_peak_rss()) {
    const long before = bench::proc_status_kib("VmRSS");
    {
      Mesh out = honeycomb(input);
      faces = out.num_faces();
    }
    const long peak = bench::proc_status_kib("VmHWM");
    extra = double(peak - before) * 1024.0 / double(faces);
  }
  return {t, faces, extra};
}
}  // namespace

int main(int argc, char** argv) {
  const int runs = argc > 1 ? std::stoi(argv[1]) : 5;
  std::printf("honeycomb, one step on a quad torus, %d runs each\n", runs);
  const double steal = bench::steal_seconds();
  const Result small = measure(71, runs);
  const Result large = measure(707, runs);
  for (const Result& r : {small, large}) {
    std::printf(
        "%9zu output faces  median %8.4f s  best %8.4f s  (%6.1f ns/face best)  extra peak %6.1f "
        "bytes/face\n",
        r.faces, r.time.median, r.time.best, 1e9 * r.time.best / double(r.faces), r.extra_bytes_per_face);
  }
  std::printf("time per face, 1M / 10k: median %.2f, best %.2f\n",
              (large.time.median / double(large.faces)) / (small.time.median / double(small.faces)),
              (large.time.best / double(large.faces)) / (small.time.best / double(small.faces)));
  std::printf("CPU steal by the VM host during the measurements: %.2f s\n", bench::steal_seconds() - steal);
  return 0;
}
