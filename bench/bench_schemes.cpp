// Scheme benchmark: one step of every scheme on a torus sized for about 1M output faces (sqrt(3): two steps,
// as the reference figure is for two), median and best wall time of repeated runs, beside the reference
// figures of the fastest established library on this machine (issue 4). Usage: dlfl_bench_schemes [runs=5]
//
// `dlfl_bench_schemes compare` instead measures how dual-honeycomb-dual's positions differ from sqrt(3)'s
// (same connectivity on triangle meshes; docs/schemes.md quotes the figures).

#include <cmath>
#include <cstdio>
#include <functional>
#include <glm/geometric.hpp>
#include <numbers>
#include <string>
#include <vector>

#include <dlfl/build_mesh.h>
#include <dlfl/schemes/catmull_clark.h>
#include <dlfl/schemes/doo_sabin.h>
#include <dlfl/schemes/dual.h>
#include <dlfl/schemes/dual_honeycomb_dual.h>
#include <dlfl/schemes/honeycomb.h>
#include <dlfl/schemes/loop.h>
#include <dlfl/schemes/mlca_polygons.h>
#include <dlfl/schemes/sqrt3.h>
#include <dlfl/schemes/zhang_wang_honeycomb.h>
#include "bench_meshes.h"
#include "bench_util.h"
#include "test_meshes.h"

using namespace dlfl;

namespace {

// An n x n torus of quads, or of triangles (each quad cut along a diagonal).

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

// ---- dual-honeycomb-dual against sqrt(3)

double signed_volume(const Mesh& m) {
  double volume = 0;
  for (FaceId f : m.faces()) {
    const CornerId c = m.first_corner(f);
    volume += glm::dot(m.position(m.vertex(c)),
                       glm::cross(m.position(m.vertex(m.next(c))), m.position(m.vertex(m.prev(c))))) /
              6.0;
  }
  return volume;
}

// Where dual-honeycomb-dual puts the vertex w of `m`: the average of the centroids of its faces (derived in
// tests/test_dual_honeycomb_dual.cpp); returns the vertex of `next` at that place.
VertexId follow(const Mesh& m, VertexId w, const Mesh& next) {
  glm::dvec3 sum(0.0);
  double n = 0;
  for (CornerId c : m.corners(w)) {
    glm::dvec3 centroid(0.0);
    for (CornerId d : m.corners(m.face(c))) centroid += m.position(m.vertex(d));
    sum += centroid / double(m.size(m.face(c)));
    n += 1;
  }
  const glm::dvec3 p = sum / n;
  for (VertexId v : next.vertices()) {
    if (glm::length(next.position(v) - p) < 1e-12) return v;
  }
  return VertexId();
}

// Steps of both schemes from the same triangle mesh: enclosed volume relative to the input's, and how far
// apart the two schemes put each input vertex (sqrt(3) keeps it as vertex v; dual-honeycomb-dual's is
// followed step by step), relative to the input's bounding-box diagonal.
void compare_root3(const char* name, const Mesh& input, int steps) {
  glm::dvec3 lo(1e300), hi(-1e300);
  for (VertexId v : input.vertices()) {
    lo = glm::min(lo, input.position(v));
    hi = glm::max(hi, input.position(v));
  }
  const double diagonal = glm::length(hi - lo), volume = signed_volume(input);
  std::printf("%s: V = %zu, F = %zu, volume %.6f, bounding-box diagonal %.6f\n", name, input.num_vertices(),
              input.num_faces(), volume, diagonal);
  std::printf(
      "  step   faces   volume/input: sqrt3   dhd   |  input vertices, sqrt3 vs dhd: mean and max "
      "distance / diagonal\n");
  Mesh a = input, b = input;
  std::vector<VertexId> tracked;
  for (VertexId v : input.vertices()) tracked.push_back(v);
  for (int k = 1; k <= steps; ++k) {
    Mesh next_b = dual_honeycomb_dual(b);
    for (VertexId& w : tracked) {
      w = follow(b, w, next_b);
      if (!w.valid()) {
        std::printf("  step %d: an input vertex is not where the derivation puts it\n", k);
        return;
      }
    }
    b = std::move(next_b);
    a = sqrt3(a);
    double sum = 0, largest = 0;
    std::uint32_t i = 0;
    for (VertexId v : input.vertices()) {
      (void)v;
      const double d = glm::length(a.position(VertexId(i)) - b.position(tracked[i])) / diagonal;
      sum += d;
      largest = std::max(largest, d);
      ++i;
    }
    std::printf("  %4d %7zu        %.6f  %.6f  |  %.6f  %.6f\n", k, a.num_faces(), signed_volume(a) / volume,
                signed_volume(b) / volume, sum / double(i), largest);
  }
}

int compare_main() {
  compare_root3("icosahedron", build_mesh(test::icosahedron_soup()), 4);
  compare_root3("torus 16 x 16 (triangles)", build_mesh(bench::torus_soup(16, 16, true)), 3);
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc > 1 && std::string(argv[1]) == "compare") return compare_main();
  const int runs = argc > 1 ? std::stoi(argv[1]) : 5;
  std::printf("one step of each scheme to about 1M faces, %d runs each\n", runs);
  const double steal = bench::steal_seconds();
  const Mesh quads500 = build_mesh(
      bench::torus_soup(500, 500, false));  // 4 F = 1M for Catmull-Clark; V + E + F = 1M for Doo-Sabin
  measure(
      "catmull-clark", quads500, runs, [](const Mesh& m) { return catmull_clark(m); }, 0.11);
  measure(
      "mlca (quads)", quads500, runs, [](const Mesh& m) { return mlca(m); }, 0);
  measure(
      "doo-sabin", quads500, runs, [](const Mesh& m) { return doo_sabin(m); }, 0.24);
  measure(
      "dual-honeycomb-dual", quads500, runs, [](const Mesh& m) { return dual_honeycomb_dual(m); }, 0);
  const Mesh triangles354 = build_mesh(bench::torus_soup(354, 354, true));  // 4 F = 8 n^2 = 1M
  measure(
      "loop", triangles354, runs, [](const Mesh& m) { return loop(m); }, 0.07);
  const Mesh triangles236 = build_mesh(bench::torus_soup(236, 236, true));  // 9 F = 18 n^2 = 1M
  measure(
      "sqrt3 (two steps)", triangles236, runs, [](const Mesh& m) { return sqrt3(sqrt3(m)); }, 0.12);
  const Mesh quads707 = build_mesh(bench::torus_soup(707, 707, false));  // F + V = 2 n^2 = 1M
  measure(
      "honeycomb", quads707, runs, [](const Mesh& m) { return honeycomb(m); }, 0);
  measure(
      "honeycomb-zw", quads707, runs, [](const Mesh& m) { return zhang_wang_honeycomb(m); }, 0);
  const Mesh quads1000 = build_mesh(bench::torus_soup(1000, 1000, false));  // F' = V = 1M
  measure(
      "dual", quads1000, runs, [](const Mesh& m) { return dual(m); }, 0);
  std::printf("CPU steal by the VM host during the measurements: %.2f s\n", bench::steal_seconds() - steal);
  return 0;
}
