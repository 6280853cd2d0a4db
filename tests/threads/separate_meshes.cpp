// Different meshes on different threads are safe, and so are many readers of one mesh (docs/threads.md). Four
// threads each build, subdivide, validate, edit, undo, write and read back meshes of their own at once, while
// sharing what the library shares between meshes: the block cache of large arrays, the scheme and operation
// registries, the registry of temporary files. Each thread's results must equal those computed on one thread
// beforehand. Built with -DDLFL_SANITIZE=thread, ThreadSanitizer reports any data race and fails the test;
// without it, the test still checks that concurrent results are the sequential ones.

#include <unistd.h>
#include <cstdio>
#include <filesystem>
#include <string>
#include <thread>
#include <vector>

#include <dlfl/build_mesh.h>
#include <dlfl/detail/block_cache.h>
#include <dlfl/history/editor.h>
#include <dlfl/io/mesh_io.h>
#include <dlfl/mesh_hash.h>
#include <dlfl/schemes/scheme_registry.h>
#include <dlfl/validate.h>

namespace {

using namespace dlfl;

// A quad torus of n x n faces: large enough (n = 200: 160,000 corners, 3 MiB of corners) that its arrays go
// through the block cache.
PolygonSoup torus(int n) {
  PolygonSoup soup;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const double u = 6.283185307179586 * i / n, v = 6.283185307179586 * j / n;
      soup.positions.push_back(
          {(2 + std::cos(v)) * std::cos(u), (2 + std::cos(v)) * std::sin(u), std::sin(v)});
    }
  auto at = [n](int i, int j) { return static_cast<std::uint32_t>(((i + n) % n) * n + (j + n) % n); };
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) soup.add_face({at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j + 1)});
  return soup;
}

// One thread's work; returns the hashes it saw, in order.
std::vector<std::string> work(int n, const std::filesystem::path& folder) {
  std::vector<std::string> hashes;
  Mesh m = build_mesh(torus(n));
  hashes.push_back(mesh_hash(m));
  for (const char* scheme : {"honeycomb", "catmull-clark", "doo-sabin", "dual"}) {
    const Mesh next = apply_scheme(m, scheme);
    if (!validate(next).valid()) hashes.push_back(std::string("invalid after ") + scheme);
    hashes.push_back(mesh_hash(next));
  }
  Editor editor;
  editor.set_mesh(m);
  editor.subdivide("honeycomb");
  const CornerId c = editor.mesh().first_corner(FaceId(0));
  editor.insert_edge(c, editor.mesh().next(editor.mesh().next(c)));  // a diagonal of face 0
  hashes.push_back(mesh_hash(editor.mesh()));
  editor.undo();
  editor.undo();
  hashes.push_back(editor.mesh() == m ? "undone" : "undo differs");
  const std::filesystem::path file = folder / ("torus-" + std::to_string(n) + ".ply");
  write_mesh(m, file);
  hashes.push_back(read_mesh(file) == m ? "read back" : "read back differs");
  return hashes;
}

}  // namespace

int main() {
  const std::filesystem::path folder =
      std::filesystem::temp_directory_path() / ("dlfl_threads_" + std::to_string(getpid()));
  std::filesystem::create_directories(folder);
  const std::vector<int> sizes = {200, 210, 220, 230};
  std::vector<std::vector<std::string>> expected;
  for (int n : sizes) expected.push_back(work(n, folder));
  std::vector<std::vector<std::string>> got(sizes.size());
  for (int round = 0; round < 2; ++round) {  // the second round finds the cache filled by the first
    std::vector<std::thread> threads;
    for (std::size_t i = 0; i < sizes.size(); ++i)
      threads.emplace_back([&, i] { got[i] = work(sizes[i], folder); });
    for (std::thread& t : threads) t.join();
    for (std::size_t i = 0; i < sizes.size(); ++i) {
      if (got[i] != expected[i]) {
        std::fprintf(stderr, "thread %zu (torus %d) got other results than on one thread\n", i, sizes[i]);
        return 1;
      }
    }
  }
  // One mesh, many readers: schemes, validation and hashes read their input only.
  const Mesh shared = build_mesh(torus(200));
  const std::string honeycomb_hash = mesh_hash(apply_scheme(shared, "honeycomb"));
  std::vector<int> same(4, 0);
  {
    std::vector<std::thread> threads;
    for (int i = 0; i < 4; ++i)
      threads.emplace_back([&, i] {
        same[i] = mesh_hash(apply_scheme(shared, "honeycomb")) == honeycomb_hash && validate(shared).valid();
      });
    for (std::thread& t : threads) t.join();
  }
  for (int i = 0; i < 4; ++i) {
    if (!same[i]) {
      std::fprintf(stderr, "reader %d of one shared mesh got another result\n", i);
      return 1;
    }
  }
  std::filesystem::remove_all(folder);
  std::printf("4 threads x 2 rounds: results equal to the sequential ones; block cache holds %zu bytes\n",
              block_cache_size());
  return 0;
}
