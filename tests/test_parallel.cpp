// The parallel passes (dlfl/thread_count.h): every index is visited once, in chunks that do not depend on the
// thread count, and a scheme's result is the same mesh, bit for bit, on one thread and on several.

#include <doctest/doctest.h>

#include <atomic>
#include <cstdlib>
#include <vector>

#include <dlfl/build_mesh.h>
#include <dlfl/detail/parallel_for.h>
#include <dlfl/errors.h>
#include <dlfl/mesh_hash.h>
#include <dlfl/schemes/catmull_clark.h>
#include <dlfl/thread_count.h>
#include <dlfl/validate.h>
#include "test_meshes.h"

using namespace dlfl;

namespace {
// Restores the default thread count when a test ends, whatever it set.
struct DefaultThreadsAfter {
  ~DefaultThreadsAfter() { set_thread_count(0); }
};
}  // namespace

TEST_CASE("parallel_chunks: each index once, in chunks of the grain, on any number of threads") {
  DefaultThreadsAfter restore;
  for (unsigned threads : {1u, 2u, 5u}) {
    set_thread_count(threads);
    CHECK(thread_count() == threads);
    const std::size_t n = 10 * 1000 + 7, grain = 1000;
    std::vector<std::atomic<int>> seen(n);
    std::vector<std::atomic<int>> chunk_calls(detail::chunk_count(n, grain));
    CHECK(chunk_calls.size() == 11);
    detail::parallel_chunks(n, grain, [&](std::size_t begin, std::size_t end) {
      // The bounds are the chunk's own: a multiple of the grain, and the grain long but for the last.
      CHECK(begin % grain == 0);
      CHECK(end == std::min(n, begin + grain));
      ++chunk_calls[begin / grain];
      for (std::size_t i = begin; i < end; ++i) ++seen[i];
    });
    int wrong = 0;
    for (const auto& s : seen) wrong += s != 1;
    for (const auto& c : chunk_calls) wrong += c != 1;
    CHECK(wrong == 0);
  }
}

TEST_CASE("parallel_for: nothing for an empty range; an exception in a body reaches the caller") {
  DefaultThreadsAfter restore;
  set_thread_count(2);
  int calls = 0;
  detail::parallel_for(0, [&](std::size_t) { ++calls; });
  CHECK(calls == 0);
  CHECK_THROWS_AS(detail::parallel_for(
                      100000,
                      [](std::size_t i) {
                        if (i == 77777) throw InvalidArgument("index 77777");
                      },
                      1000),
                  InvalidArgument);
}

TEST_CASE("thread count: set, reset to DLFL_THREADS, refused beyond 1024") {
  DefaultThreadsAfter restore;
  CHECK(thread_count() >= 1);
  set_thread_count(3);
  CHECK(thread_count() == 3);
  ::setenv("DLFL_THREADS", "4", 1);
  set_thread_count(0);
  CHECK(thread_count() == 4);
  ::setenv("DLFL_THREADS", "four", 1);  // not a number: the number of cores
  set_thread_count(0);
  CHECK(thread_count() >= 1);
  ::unsetenv("DLFL_THREADS");
  CHECK_THROWS_AS(set_thread_count(1025), InvalidArgument);
}

TEST_CASE("catmull-clark: the same mesh, bit for bit, on 1, 2 and 7 threads") {
  DefaultThreadsAfter restore;
  // 60 x 50 quads: 12,000 corners, 48,000 after the step; several chunks in every pass.
  const Mesh input = build_mesh(test::torus_soup(60, 50));
  set_thread_count(1);
  const Mesh serial = catmull_clark(catmull_clark(input));
  CHECK(validate(serial).valid());
  for (unsigned threads : {2u, 7u}) {
    set_thread_count(threads);
    const Mesh parallel = catmull_clark(catmull_clark(input));
    CHECK(parallel == serial);
    CHECK(mesh_hash(parallel) == mesh_hash(serial));
  }
}
