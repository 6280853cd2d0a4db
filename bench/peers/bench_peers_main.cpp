// dlfl_bench_peers [runs=3] [output faces...=1000000 16000000]: one step of Catmull-Clark, Loop, sqrt3,
// Doo-Sabin and honeycomb to about each number of output faces, in this library, CGAL 5.5
// (Subdivision_method_3) and OpenMesh (Subdivider::Uniform), from the same closed torus grid, built with the
// same compiler flags (issue 17; docs/performance.md). Every timed step runs cold, in a fresh dlfl_peer_step
// process, the libraries taking turns (cold_runs.h); dlfl runs with its default thread count and, at the
// smallest size, with DLFL_THREADS=1 too. Use 3 runs or more: the median then leaves out the step that
// follows a large process, which this VM slows down. Exits with 1 if any library's face count differs from
// the closed form.

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>
#include <thread>
#include <vector>

#include "bench_util.h"
#include "child_process.h"
#include "cold_runs.h"
#include "peer_table.h"

using namespace dlfl::bench;

int main(int argc, char** argv) {
  const int runs = argc > 1 ? std::atoi(argv[1]) : 3;
  std::vector<std::size_t> sizes;
  for (int i = 2; i < argc; ++i) sizes.push_back(std::size_t(std::atoll(argv[i])));
  if (sizes.empty()) sizes = {1000000, 16000000};
  std::sort(sizes.begin(), sizes.end());
  if (runs < 1 || sizes.front() < 100) {
    std::fprintf(stderr, "usage: dlfl_bench_peers [runs=3] [output faces...]\n");
    return 2;
  }
  const std::string helper = own_folder() + "/dlfl_peer_step";
  const char* threads = std::getenv("DLFL_THREADS");
  std::printf("cold steps, median of %d fresh processes each; dlfl threads: %s (%u cores)\n\n", runs,
              threads ? threads : "default", std::thread::hardware_concurrency());
  const double steal_before = steal_seconds();
  print_detail_header();
  std::vector<PeerRow> rows;
  try {
    for (Scheme scheme : all_schemes) {
      for (std::size_t faces : sizes) {
        PeerRow row;
        row.scheme = scheme;
        row.n = grid_side(scheme, faces);
        row.expected_faces = output_faces(scheme, row.n);
        std::vector<Variant> variants = {
            {"dlfl", scheme, row.n, 0}, {"cgal", scheme, row.n, 0}, {"openmesh", scheme, row.n, 0}};
        if (faces == sizes.front()) variants.push_back({"dlfl", scheme, row.n, 1});
        const auto results = cold_runs(helper, variants, runs, rows.size());
        row.dlfl = results[0];
        row.cgal = results[1];
        row.openmesh = results[2];
        if (results.size() > 3) row.dlfl_one_thread = results[3];
        print_detail(row, "dlfl", row.dlfl);
        print_detail(row, "dlfl 1T", row.dlfl_one_thread);
        print_detail(row, "CGAL", row.cgal);
        print_detail(row, "OpenMesh", row.openmesh);
        rows.push_back(std::move(row));
      }
    }
  } catch (const std::exception& e) {
    std::fprintf(stderr, "dlfl_bench_peers: %s\n", e.what());
    return 1;
  }
  print_summary(rows);
  print_scaling(rows);
  std::printf("\nCPU time stolen by the VM's host meanwhile: %.1f s; load average now: %s",
              steal_seconds() - steal_before, load_average().c_str());
  const bool agree = std::all_of(rows.begin(), rows.end(), faces_agree);
  std::printf("\nface counts %s\n", agree ? "agree across libraries" : "DIFFER: see the rows marked above");
  return agree ? 0 : 1;
}
