#include <dlfl/detail/parallel_for.h>

#include <atomic>
#include <charconv>
#include <cstdlib>
#include <exception>
#include <functional>
#include <memory>
#include <mutex>
#include <string>
#include <string_view>
#include <thread>
#include <vector>

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <dlfl/errors.h>
#include <dlfl/thread_count.h>

namespace dlfl {
namespace {

constexpr unsigned most_threads = 1024;

unsigned default_thread_count() {
  if (const char* text = std::getenv("DLFL_THREADS")) {
    const std::string_view s(text);
    unsigned n = 0;
    const auto [end, error] = std::from_chars(s.data(), s.data() + s.size(), n);
    if (error == std::errc() && end == s.data() + s.size() && n >= 1 && n <= most_threads) return n;
  }
  return std::max(1u, std::thread::hardware_concurrency());
}

// The arena that runs the library's chunks: its own, so that the library's thread count neither changes nor
// depends on how the application uses TBB. Replaced, never changed, when the count changes; a pass holds a
// shared_ptr to the arena it started in.
struct Threads {
  std::mutex mutex;
  unsigned count = 0;  // 0: not chosen yet
  std::shared_ptr<tbb::task_arena> arena;

  std::pair<unsigned, std::shared_ptr<tbb::task_arena>> current() {
    std::lock_guard lock(mutex);
    if (count == 0) count = default_thread_count();
    // TBB has at most a worker per core beyond the caller and warns on a larger arena; more threads than
    // cores would not run at once anyway, and the results do not depend on the count.
    const unsigned cores = std::max(1u, std::thread::hardware_concurrency());
    if (count > 1 && !arena) arena = std::make_shared<tbb::task_arena>(int(std::min(count, cores)));
    return {count, arena};
  }
  void set(unsigned n) {
    std::lock_guard lock(mutex);
    count = n;
    arena.reset();
  }
};

Threads& threads() {
  static Threads* t = new Threads;  // never destroyed: a pass may run during static destruction
  return *t;
}

}  // namespace

unsigned thread_count() { return threads().current().first; }

void set_thread_count(unsigned count) {
  if (count > most_threads) {
    throw InvalidArgument("set_thread_count: " + std::to_string(count) + " threads; at most " +
                          std::to_string(most_threads));
  }
  threads().set(count);
}

namespace detail {

namespace {

#if defined(__SANITIZE_THREAD__)
#define DLFL_THREAD_SANITIZER 1
#elif defined(__has_feature)
#if __has_feature(thread_sanitizer)
#define DLFL_THREAD_SANITIZER 1
#endif
#endif

#if defined(DLFL_THREAD_SANITIZER)
// Under ThreadSanitizer the chunks run on plain std::threads: libtbb is not instrumented, so its hand-offs
// would be invisible and every chunk would look racy. What TSan checks is the chunk bodies, the library's own
// code, and those are the same here. Slower (threads made per pass), which only the sanitizer build pays.
void run_chunks(unsigned count, std::size_t chunks, const std::function<void(std::size_t)>& run) {
  std::atomic<std::size_t> next = 0;
  std::exception_ptr error;
  std::mutex error_mutex;
  auto worker = [&] {
    for (std::size_t c; (c = next++) < chunks;) {
      try {
        run(c);
      } catch (...) {
        std::lock_guard lock(error_mutex);
        if (!error) error = std::current_exception();
        next = chunks;  // stop handing out chunks
      }
    }
  };
  std::vector<std::thread> helpers;
  for (unsigned t = 1; t < count && t < chunks; ++t) helpers.emplace_back(worker);
  worker();
  for (std::thread& h : helpers) h.join();
  if (error) std::rethrow_exception(error);
}
#endif

}  // namespace

void parallel_chunks(std::size_t n, std::size_t grain, ChunkBody body) {
  if (grain == 0) grain = 1;
  const std::size_t chunks = chunk_count(n, grain);
  if (chunks == 0) return;
  auto run = [&](std::size_t c) { body(c * grain, std::min(n, (c + 1) * grain)); };
  if (chunks == 1) {
    run(0);
    return;
  }
  const auto [count, arena] = threads().current();
  if (count == 1) {
    for (std::size_t c = 0; c < chunks; ++c) run(c);
    return;
  }
#if defined(DLFL_THREAD_SANITIZER)
  (void)arena;
  run_chunks(count, chunks, run);
#else
  arena->execute([&] {
    tbb::parallel_for(tbb::blocked_range<std::size_t>(0, chunks, 1),
                      [&](const tbb::blocked_range<std::size_t>& r) {
                        for (std::size_t c = r.begin(); c != r.end(); ++c) run(c);
                      });
  });
#endif
}

}  // namespace detail
}  // namespace dlfl
