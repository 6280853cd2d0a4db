// dlfl_bench_end_to_end [runs=1] [output faces...=1000000 16000000]: whole processes, file in to file out,
// for one Catmull-Clark step to about each number of faces: `dlfl subdivide IN -s catmull-clark -o OUT`
// against cgal_subdivide and openmesh_subdivide (the same step in CGAL 5.5 and OpenMesh, with their own
// readers and writers), for a binary PLY and an OBJ input of the same torus grid of quads. Prints each
// process's wall time (median of the runs) and peak resident memory (wait4's ru_maxrss), and checks that
// every output file holds the closed-form number of faces (exit 1 if not). The files go to
// $TMPDIR/dlfl_bench_end_to_end (or /tmp), removed at the end.

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

// The run with the median wall time of `runs` runs; exit_code -1 marks a failed run.
ChildRun median_run(const std::vector<std::string>& command, int runs) {
  std::vector<ChildRun> done;
  for (int i = 0; i < runs; ++i) {
    done.push_back(run_child(command));
    if (done.back().exit_code != 0) return done.back();
  }
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
      for (const Program& program : programs) {
        const ChildRun run = median_run(program.command(bin, in, out), runs);
        const auto written = run.exit_code == 0 ? file_face_count(out) : std::nullopt;
        const bool agree = written && *written == expected;
        all_agree = all_agree && agree;
        std::printf("%-6s %10zu %-9s %9.3f %9.3f %9.3f %10.1f %10s\n", format, expected, program.label,
                    run.wall, run.user, run.system, run.peak_rss_mib,
                    run.exit_code != 0 ? "FAILED" : (agree ? "yes" : "MISMATCH"));
        std::fflush(stdout);
        fs::remove(out);
      }
      fs::remove(in);
    }
  }
  fs::remove(dir);
  std::printf("\nCPU time stolen by the VM's host meanwhile: %.1f s; load average now: %s",
              steal_seconds() - steal_before, load_average().c_str());
  std::printf("\noutput face counts %s\n", all_agree ? "agree" : "DIFFER: see the rows marked above");
  return all_agree ? 0 : 1;
}
