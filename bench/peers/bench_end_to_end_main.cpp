// dlfl_bench_end_to_end [runs=1] [output faces...=1000000 16000000]: whole processes, file in to file out,
// for one Catmull-Clark step to about each number of faces: `dlfl subdivide IN -s catmull-clark -o OUT`
// against cgal_subdivide and openmesh_subdivide (the same step in CGAL 5.5 and OpenMesh, with their own
// readers and writers), for a binary PLY and an OBJ input of the same torus grid of quads. Prints each
// process's wall time (median of the runs; the programs take turns) and peak resident memory (wait4's
// ru_maxrss), and checks that every output file holds the closed-form number of faces (exit 1 if not). The
// files go to $TMPDIR/dlfl_bench_end_to_end (or /tmp), removed at the end.

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include <dlfl/build_mesh.h>
#include <dlfl/io/mesh_io.h>
#include "bench_meshes.h"
#include "bench_util.h"
#include "child_process.h"
#include "file_face_count.h"
#include "peer_schemes.h"

using namespace dlfl::bench;
namespace fs = std::filesystem;

namespace {

struct Program {
  const char* label;
  std::vector<std::string> (*command)(const std::string& bin, const std::string& in, const std::string& out);
};

const Program programs[] = {
    {"dlfl",
     [](const std::string& bin, const std::string& in, const std::string& out) {
       return std::vector<std::string>{bin + "/dlfl", "subdivide", in, "-s", "catmull-clark", "-o", out};
     }},
    {"CGAL",
     [](const std::string& bin, const std::string& in, const std::string& out) {
       return std::vector<std::string>{bin + "/cgal_subdivide", in, out};
     }},
    {"OpenMesh",
     [](const std::string& bin, const std::string& in, const std::string& out) {
       return std::vector<std::string>{bin + "/openmesh_subdivide", in, out};
     }},
};

// One program's runs on one input: all its runs, and whether every output held the expected faces.
struct Runs {
  std::vector<ChildRun> done;
  bool failed = false;
  bool faces_agree = true;
};

// The run with the median wall time.
ChildRun median_run(std::vector<ChildRun> done) {
  std::sort(done.begin(), done.end(), [](const ChildRun& a, const ChildRun& b) { return a.wall < b.wall; });
  return done[done.size() / 2];
}

}  // namespace

int main(int argc, char** argv) {
  const int runs = argc > 1 ? std::atoi(argv[1]) : 1;
  std::vector<std::size_t> sizes;
  for (int i = 2; i < argc; ++i) sizes.push_back(std::size_t(std::atoll(argv[i])));
  if (sizes.empty()) sizes = {1000000, 16000000};
  if (runs < 1 || *std::min_element(sizes.begin(), sizes.end()) < 100) {
    std::fprintf(stderr, "usage: dlfl_bench_end_to_end [runs=1] [output faces...]\n");
    return 2;
  }
  const std::string bin = own_folder();
  const char* tmp = std::getenv("TMPDIR");
  const fs::path dir = fs::path(tmp ? tmp : "/tmp") / "dlfl_bench_end_to_end";
  fs::create_directories(dir);
  bool all_agree = true;
  std::size_t turn = 0;  // which program goes first in the next round
  const double steal_before = steal_seconds();
  std::printf("whole processes, one Catmull-Clark step, median of %d run(s)\n\n", runs);
  std::printf("%-6s %10s %-9s %9s %9s %9s %10s %10s\n", "format", "out faces", "program", "wall s", "user s",
              "sys s", "peak MiB", "faces ok");
  for (std::size_t faces : sizes) {
    const std::size_t n = grid_side(Scheme::catmull_clark, faces);
    const std::size_t expected = output_faces(Scheme::catmull_clark, n);
    const dlfl::Mesh input = dlfl::build_mesh(torus_soup(int(n), int(n)));
    for (const char* format : {"ply", "obj"}) {
      const std::string in = (dir / (std::string("in.") + format)).string();
      const std::string out = (dir / (std::string("out.") + format)).string();
      dlfl::write_mesh(input, in);  // PLY binary (the default)
      // The programs take turns, each round starting with the next one: on this VM the process right after a
      // large one has ended can be much slower (docs/performance.md), and no program should always be that
      // one.
      std::vector<Runs> measured(std::size(programs));
      for (int round = 0; round < runs; ++round, ++turn) {
        for (std::size_t k = 0; k < measured.size(); ++k) {
          const std::size_t p = (turn + k) % measured.size();
          if (measured[p].failed) continue;
          const ChildRun run = run_child(programs[p].command(bin, in, out));
          measured[p].failed = run.exit_code != 0;
          const auto written = measured[p].failed ? std::nullopt : file_face_count(out);
          measured[p].faces_agree = measured[p].faces_agree && written && *written == expected;
          measured[p].done.push_back(run);
          fs::remove(out);
        }
      }
      for (std::size_t p = 0; p < measured.size(); ++p) {
        const ChildRun run = median_run(measured[p].done);
        all_agree = all_agree && !measured[p].failed && measured[p].faces_agree;
        std::printf("%-6s %10zu %-9s %9.3f %9.3f %9.3f %10.1f %10s\n", format, expected, programs[p].label,
                    run.wall, run.user, run.system, run.peak_rss_mib,
                    measured[p].failed ? "FAILED" : (measured[p].faces_agree ? "yes" : "MISMATCH"));
      }
      std::fflush(stdout);
      fs::remove(in);
    }
  }
  fs::remove(dir);
  std::printf("\nCPU time stolen by the VM's host meanwhile: %.1f s; load average now: %s",
              steal_seconds() - steal_before, load_average().c_str());
  std::printf("\noutput face counts %s\n", all_agree ? "agree" : "DIFFER: see the rows marked above");
  return all_agree ? 0 : 1;
}
