// The renderer on a large mesh: a 1M-face torus (quads) at 1600x1200, iso view, default options (edges off
// above 200k faces), flat and smooth; then with edges. Each phase timed: scene (from the mesh), raster
// (the picture), PNG (encoding in memory). The target: the whole under 2 s at 1M faces.
//
//   ./build/bin/dlfl_bench_render [N_AROUND=1000] [RUNS=3]     # N_AROUND^2 faces

#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <sstream>

#include <dlfl/build_mesh.h>
#include <dlfl/render/png.h>
#include <dlfl/render/rasterizer.h>
#include "bench_util.h"
#include "test_meshes.h"

using namespace dlfl;

int main(int argc, char** argv) {
  const int around = argc > 1 ? std::atoi(argv[1]) : 1000;
  const int runs = argc > 2 ? std::atoi(argv[2]) : 3;
  const Mesh mesh = build_mesh(test::torus_soup(around, around, 2.0, 0.7));
  std::printf("torus: %zu faces, picture 1600x1200, %d runs (best / median)\n", mesh.num_faces(), runs);
  for (int variant = 0; variant < 3; ++variant) {
    RenderOptions options;
    options.smooth = variant == 1;
    if (variant == 2) options.edges = true;
    const char* name = variant == 0 ? "flat" : variant == 1 ? "smooth" : "flat, edges";
    RenderScene scene;
    Image image;
    std::string png;
    const double steal0 = bench::steal_seconds();
    const std::clock_t cpu0 = std::clock();
    const auto total = bench::time_runs(runs, [&] {
      scene = mesh_scene(mesh);
      Camera camera(view_angles(View::iso), 1600, 1200);
      camera.include(scene.positions);
      camera.fit();
      image = render(scene, camera, options);
      std::ostringstream out;
      write_png(image, out);
      png = out.str();
    });
    const double cpu = double(std::clock() - cpu0) / CLOCKS_PER_SEC / runs;
    const auto scene_time = bench::time_runs(runs, [&] { scene = mesh_scene(mesh); });
    Camera camera(view_angles(View::iso), 1600, 1200);
    camera.include(scene.positions);
    camera.fit();
    const auto raster_time = bench::time_runs(runs, [&] { image = render(scene, camera, options); });
    const auto png_time = bench::time_runs(runs, [&] {
      std::ostringstream out;
      write_png(image, out);
      png = out.str();
    });
    std::printf(
        "%-12s total %.3f / %.3f s, CPU %.3f s per run  (scene %.3f, raster %.3f, PNG %.3f; best)  PNG %zu "
        "kB  steal %.2f s\n",
        name, total.best, total.median, cpu, scene_time.best, raster_time.best, png_time.best,
        png.size() / 1024, bench::steal_seconds() - steal0);
  }
  bench::row("peak", 0);
  return 0;
}
