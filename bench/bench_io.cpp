// Mesh file speed: OBJ and binary PLY of a closed quad torus, read (split into parsing and build_mesh) and
// written, in MB/s of file bytes (docs/formats.md, "I/O speed"). Usage: dlfl_bench_io [faces=1000000]
// [runs=5]

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>

#include <dlfl/build_mesh.h>
#include <dlfl/io/detail/file_bytes.h>
#include <dlfl/io/detail/obj_lines.h>
#include <dlfl/io/detail/text_io.h>
#include <dlfl/io/mesh_io.h>
#include <dlfl/thread_count.h>
#include "bench_meshes.h"
#include "bench_util.h"

using namespace dlfl;

namespace {

// Megabytes (10^6 bytes) per second.
double mb_per_s(std::uintmax_t bytes, double seconds) { return double(bytes) / 1e6 / seconds; }

void report(const char* what, std::uintmax_t bytes, const bench::Timing& t, const std::string& note = {}) {
  std::printf("%-28s %8.3f s  %8.1f MB/s  (best %.3f s, %.1f MB/s)  %s\n", what, t.median,
              mb_per_s(bytes, t.median), t.best, mb_per_s(bytes, t.best), note.c_str());
  std::fflush(stdout);
}

}  // namespace

int main(int argc, char** argv) {
  const long faces = argc > 1 ? std::atol(argv[1]) : 1000000;
  const int runs = argc > 2 ? std::atoi(argv[2]) : 5;
  if (faces < 9 || runs < 1) {
    std::fprintf(stderr, "usage: dlfl_bench_io [faces>=9] [runs>=1]\n");
    return 2;
  }
  // A grid as square as the face count allows: n x m with n * m close to `faces`.
  int n = 3;
  while (long(n + 1) * (n + 1) <= faces) ++n;
  const int m = int(faces / n);
  const Mesh mesh = build_mesh(bench::torus_soup(n, m));
  const auto dir = std::filesystem::temp_directory_path() / "dlfl_bench_io";
  std::filesystem::create_directories(dir);
  std::printf("closed quad torus %d x %d = %ld faces, %u threads, median of %d runs\n", n, m, long(n) * m,
              thread_count(), runs);
  const double steal = bench::steal_seconds();
  bool all_equal = true;

  for (const char* ext : {".obj", ".ply"}) {
    const auto path = dir / (std::string("torus") + ext);
    const std::string name = path.string();
    const bench::Timing write = bench::time_runs(runs, [&] { write_mesh(mesh, path); });
    const std::uintmax_t bytes = std::filesystem::file_size(path);
    std::printf("%s: %.1f MB\n", ext, double(bytes) / 1e6);
    report((std::string("write_mesh ") + ext).c_str(), bytes, write);

    Mesh back;
    const bench::Timing read = bench::time_runs(runs, [&] { back = read_mesh(path); });
    const bool equal = back == mesh;
    all_equal = all_equal && equal;
    report((std::string("read_mesh ") + ext).c_str(), bytes, read, equal ? "equal" : "NOT EQUAL");

    // The split of read_mesh: the parser (file to polygons, reading included, as read_mesh reads) and
    // build_mesh.
    ParsedPolygons parsed;
    const bench::Timing parse = bench::time_runs(runs, [&] {
      const io_detail::FileBytes file(path);
      parsed = ext == std::string(".obj") ? io_detail::parse_obj_text(file.view(), name)
                                          : io_detail::parse_ply_text(file.view(), name);
    });
    report("  parse (file to polygons)", bytes, parse);
    std::size_t size = 0;
    const bench::Timing load =
        bench::time_runs(runs, [&] { size += io_detail::FileBytes(path).view().size(); });
    report("    of which reading the file", bytes, load);
    const bench::Timing build = bench::time_runs(runs, [&] { back = build_mesh(parsed, name); });
    report("  build_mesh", bytes, build);
    if (ext == std::string(".obj")) {
      // The OBJ parser proper on the text in memory, serial and chunked, run by turns so that a busy machine
      // slows both alike.
      const std::string text = io_detail::read_file(path);
      bench::Timing serial, chunked;
      for (int r = 0; r < runs; ++r) {
        const bench::Timing s =
            bench::time_runs(1, [&] { parsed = io_detail::parse_obj_serial(text, name); });
        const bench::Timing c =
            bench::time_runs(1, [&] { parsed = io_detail::parse_obj_chunked(text, name); });
        serial.median += s.median / runs;  // the mean, here
        chunked.median += c.median / runs;
        serial.best = r == 0 ? s.best : std::min(serial.best, s.best);
        chunked.best = r == 0 ? c.best : std::min(chunked.best, c.best);
      }
      report("  OBJ text, serial parser", bytes, serial, "(mean, not median)");
      report("  OBJ text, chunked parser", bytes, chunked, "(mean, not median)");
    }
    std::filesystem::remove(path);
  }
  std::filesystem::remove(dir);
  std::printf("CPU steal by the VM host during the measurements: %.2f s\n", bench::steal_seconds() - steal);
  return all_equal ? 0 : 1;
}
