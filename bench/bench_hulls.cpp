// Hulls benchmark: convex_hull of random points in a ball and on a sphere (every point a vertex of the
// hull), from the library function; and dual_hull, for comparison. The target: under 2 s for 1M
// points.
// Usage: dlfl_bench_hulls [points=1000000] [runs=3] [only=convex_hull|dual_hull]

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <glm/geometric.hpp>
#include <random>
#include <string>
#include <vector>

#include <dlfl/operations/convex_hull.h>
#include <dlfl/operations/dual_hull.h>
#include "bench_util.h"

using namespace dlfl;

namespace {

// Uniform in the unit ball (rejection from the cube), or on the unit sphere (normalized Gaussians).
std::vector<glm::dvec3> random_points(std::size_t n, bool on_sphere) {
  std::mt19937_64 rng(12345);
  std::uniform_real_distribution<double> cube(-1.0, 1.0);
  std::normal_distribution<double> gauss;
  std::vector<glm::dvec3> out;
  out.reserve(n);
  while (out.size() < n) {
    if (on_sphere) {
      const glm::dvec3 g(gauss(rng), gauss(rng), gauss(rng));
      if (glm::length(g) > 0) out.push_back(glm::normalize(g));
    } else {
      const glm::dvec3 p(cube(rng), cube(rng), cube(rng));
      if (glm::dot(p, p) <= 1.0) out.push_back(p);
    }
  }
  return out;
}

// Wall times, and the best run's CPU time (on a shared machine the wall time of a run can be twice its CPU
// time); the first run also pays for mapping fresh memory, which the block cache spares the others.
void measure(const std::string& what, const std::vector<glm::dvec3>& points, int runs, bool dual) {
  std::size_t v = 0, e = 0, f = 0;
  double cpu = 1e300;
  const bench::Timing t = bench::time_runs(runs, [&] {
    const std::clock_t start = std::clock();
    const Mesh m = dual ? dual_hull(points) : convex_hull(points);
    cpu = std::min(cpu, double(std::clock() - start) / CLOCKS_PER_SEC);
    v = m.num_vertices(), e = m.num_edges(), f = m.num_faces();
  });
  char note[160];
  std::snprintf(note, sizeof note, "best %.3f s, CPU %.3f s; V %zu E %zu F %zu", t.best, cpu, v, e, f);
  bench::row(what + " " + std::to_string(points.size()), t.median, note);
}

}  // namespace

int main(int argc, char** argv) {
  const std::size_t n = argc > 1 ? std::strtoull(argv[1], nullptr, 10) : 1000000;
  const int runs = argc > 2 ? std::atoi(argv[2]) : 3;
  const std::vector<glm::dvec3> ball = random_points(n, false), sphere = random_points(n, true);
  const std::string only = argc > 3 ? argv[3] : "";
  if (only != "dual_hull") {
    measure("convex_hull, ball", ball, runs, false);
    measure("convex_hull, sphere", sphere, runs, false);
  }
  if (only != "convex_hull") {
    measure("dual_hull, ball", ball, runs, true);
    measure("dual_hull, sphere", sphere, runs, true);
  }
  return 0;
}
