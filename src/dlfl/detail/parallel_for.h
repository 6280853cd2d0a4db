#pragma once
// Internal: the library's one way of running a loop on several threads (dlfl/thread_count.h). The loop's
// index range is cut into chunks of a fixed size, so that which indices one call of the body sees never
// depends on the number of threads: a body that writes only its own indices, or reduces each chunk on its own
// and lets the caller combine the chunks in order, gives the serial result bit for bit.

#include <cstddef>
#include <type_traits>

namespace dlfl::detail {

/// Indices per chunk when the caller gives none: large enough that scheduling costs nothing beside the work,
/// small enough that two threads share a million-element pass evenly.
inline constexpr std::size_t parallel_grain = std::size_t(1) << 14;

/// A borrowed callable `void(std::size_t begin, std::size_t end)`: no allocation; it refers to the callable,
/// which must outlive it (a lambda written in the call does: it lives until the call returns).
class ChunkBody {
 public:
  template <class F>
  requires(!std::is_same_v<std::decay_t<F>, ChunkBody>)
      ChunkBody(F&& f)  // NOLINT: implicit, so that a lambda passes as it is
      : object_(const_cast<void*>(static_cast<const void*>(&f))),
        call_([](void* o, std::size_t b, std::size_t e) {
          (*static_cast<std::remove_reference_t<F>*>(o))(b, e);
        }) {}
  void operator()(std::size_t begin, std::size_t end) const { call_(object_, begin, end); }

 private:
  void* object_;
  void (*call_)(void*, std::size_t, std::size_t);
};

/// Calls body(begin, end) once for each chunk [c * grain, min((c + 1) * grain, n)) of [0, n), on up to
/// thread_count() threads (on the calling thread alone when there is one chunk or one thread). Returns when
/// every chunk is done. If bodies throw, one of the exceptions is rethrown after the others have stopped, so
/// a body that may throw should do so only for errors that make the result void (the message may then come
/// from any failing chunk): a deterministic error report checks serially first.
void parallel_chunks(std::size_t n, std::size_t grain, ChunkBody body);

/// f(i) for every i in [0, n), in chunks of `grain` (see parallel_chunks).
template <class F>
void parallel_for(std::size_t n, F&& f, std::size_t grain = parallel_grain) {
  auto chunk = [&f](std::size_t begin, std::size_t end) {
    for (std::size_t i = begin; i < end; ++i) f(i);
  };
  parallel_chunks(n, grain, ChunkBody(chunk));
}

/// The number of chunks parallel_chunks cuts [0, n) into.
inline std::size_t chunk_count(std::size_t n, std::size_t grain = parallel_grain) {
  return (n + grain - 1) / grain;
}

}  // namespace dlfl::detail
