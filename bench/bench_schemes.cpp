// Scheme benchmark: one step of every scheme on a torus sized for about 1M output faces (sqrt(3): two steps,
// as the reference figure is for two), median and best wall time of repeated runs, beside the reference
// figures of the fastest established library on this machine (issue 4). Usage: dlfl_bench_schemes [runs=5]

#include <cmath>
#include <cstdio>
#include <functional>
#include <numbers>
#include <string>

#include "bench_util.h"
#include "dlfl/build_mesh.h"
#include "schemes/catmull_clark.h"
#include "schemes/doo_sabin.h"
#include "schemes/dual.h"
#include "schemes/dual_honeycomb_dual.h"
#include "schemes/honeycomb.h"
#include "schemes/loop.h"
#include "schemes/mlca.h"
#include "schemes/sqrt3.h"
#include "schemes/zhang_wang_honeycomb.h"

using namespace dlfl;

namespace {

// An n x n torus of quads, or of triangles (each quad cut along a diagonal).
Mesh torus(int n, bool triangles) {
  PolygonSoup s;
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) {
      const double u = 2 * std::numbers::pi * i / n, v = 2 * std::numbers::pi * j / n;
      s.positions.push_back(
          {(2 + 0.5 * std::cos(v)) * std::cos(u), (2 + 0.5 * std::cos(v)) * std::sin(u), 0.5 * std::sin(v)});
    }
  }
  auto id = [&](int i, int j) { return std::uint32_t((i % n) * n + (j % n)); };
  for (int i = 0; i < n; ++i) {
    for (int j = 0; j < n; ++j) {
      if (triangles) {
        s.add_face({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
        s.add_face({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
      } else {
        s.add_face({id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j + 1)});
      }
    }
  }
  return build_mesh(s);
}

void measure(const char* name, const Mesh& input, int runs, const std::function<Mesh(const Mesh&)>& step,
             double reference) {
  std::size_t faces = 0;
  const bench::Timing t = bench::time_runs(runs, [&] { faces = step(input).num_faces(); });
  std::printf("%-22s %8zu -> %8zu faces  median %7.4f s  best %7.4f s", name, input.num_faces(), faces,
              t.median, t.best);
  if (reference > 0) std::printf("   reference %.2f s", reference);
  std::printf("\n");
  std::fflush(stdout);
}

}  // namespace

int main(int argc, char** argv) {
  const int runs = argc > 1 ? std::stoi(argv[1]) : 5;
  std::printf("one step of each scheme to about 1M faces, %d runs each\n", runs);
  const double steal = bench::steal_seconds();
  const Mesh quads500 = torus(500, false);  // 4 F = 1M for Catmull-Clark; V + E + F = 1M for Doo-Sabin
  measure(
      "catmull-clark", quads500, runs, [](const Mesh& m) { return catmull_clark(m); }, 0.11);
  measure(
      "mlca (quads)", quads500, runs, [](const Mesh& m) { return mlca(m); }, 0);
  measure(
      "doo-sabin", quads500, runs, [](const Mesh& m) { return doo_sabin(m); }, 0.24);
  measure(
      "dual-honeycomb-dual", quads500, runs, [](const Mesh& m) { return dual_honeycomb_dual(m); }, 0);
  const Mesh triangles354 = torus(354, true);  // 4 F = 8 n^2 = 1M
  measure(
      "loop", triangles354, runs, [](const Mesh& m) { return loop(m); }, 0.07);
  const Mesh triangles236 = torus(236, true);  // 9 F = 18 n^2 = 1M
  measure(
      "sqrt3 (two steps)", triangles236, runs, [](const Mesh& m) { return sqrt3(sqrt3(m)); }, 0.12);
  const Mesh quads707 = torus(707, false);  // F + V = 2 n^2 = 1M
  measure(
      "honeycomb", quads707, runs, [](const Mesh& m) { return honeycomb(m); }, 0);
  measure(
      "honeycomb-zw", quads707, runs, [](const Mesh& m) { return zhang_wang_honeycomb(m); }, 0);
  const Mesh quads1000 = torus(1000, false);  // F' = V = 1M
  measure(
      "dual", quads1000, runs, [](const Mesh& m) { return dual(m); }, 0);
  std::printf("CPU steal by the VM host during the measurements: %.2f s\n", bench::steal_seconds() - steal);
  return 0;
}
