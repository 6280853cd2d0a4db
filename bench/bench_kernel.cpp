// Kernel benchmark: a closed quad mesh (a torus grid) of about 1M faces, built, validated, written and read.
// Prints medians (and best runs where noted: the least disturbed by a shared machine).
// Usage: dlfl_bench_kernel [faces=1000000] [runs=5] [folder for temporary files=/tmp]

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <numbers>
#include <string>

#include <dlfl/build_mesh.h>
#include <dlfl/io/mesh_io.h>
#include <dlfl/validate.h>
#include "bench_meshes.h"
#include "bench_util.h"

using namespace dlfl;

int main(int argc, char** argv) {
  const long faces = argc > 1 ? std::stol(argv[1]) : 1000000;
  const int runs = argc > 2 ? std::stoi(argv[2]) : 5;
  const std::filesystem::path dir = argc > 3 ? argv[3] : std::filesystem::temp_directory_path();
  const int side = int(std::lround(std::sqrt(double(faces))));
  const double steal = bench::steal_seconds();
  std::printf("closed quad torus %d x %d = %d faces, median of %d runs\n", side, side, side * side, runs);

  PolygonSoup soup;
  bench::row("generate polygon soup",
             bench::median_seconds(runs, [&] { soup = bench::torus_soup(side, side); }));
  Mesh mesh;
  const bench::Timing build = bench::time_runs(runs, [&] { mesh = build_mesh(soup); });
  bench::row("build DLFL (build_mesh)", build.median, "best " + std::to_string(build.best));
  bool valid = false;
  const bench::Timing check = bench::time_runs(runs, [&] { valid = validate(mesh).valid(); });
  bench::row("validate", check.median,
             std::string(valid ? "valid" : "INVALID") + ", best " + std::to_string(check.best));
  bench::row("build + validate", build.median + check.median,
             "best " + std::to_string(build.best + check.best));

  for (const char* ext : {".obj", ".ply"}) {
    const auto path = dir / (std::string("dlfl_bench_kernel") + ext);
    // Time first, then look at the result (argument evaluation order is unspecified).
    const double write = bench::median_seconds(runs, [&] { write_mesh(mesh, path); });
    bench::row(std::string("write ") + ext, write,
               std::to_string(std::filesystem::file_size(path) >> 20) + " MiB");
    Mesh back;
    const double read = bench::median_seconds(runs, [&] { back = read_mesh(path); });
    bench::row(std::string("read ") + ext + " (parse + build)", read, back == mesh ? "equal" : "NOT EQUAL");
    std::filesystem::remove(path);
  }
  std::printf("CPU steal by the VM host during the measurements: %.2f s\n", bench::steal_seconds() - steal);
  return valid ? 0 : 1;
}
