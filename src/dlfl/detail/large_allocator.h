#pragma once
// An allocator for the mesh's element arrays: blocks of 2 MiB and more are aligned to 2 MiB and marked for
// transparent huge pages. The operators chase links across arrays of hundreds of megabytes; with 4 KiB pages
// nearly every hop is a TLB miss, with 2 MiB pages almost none. Large blocks go through a cache of freed
// blocks (dlfl/detail/block_cache.h), so they come back already mapped. Small blocks use the ordinary heap.
// The large path stays out of line, in the library, so whether the cache is compiled in is decided there
// alone: every translation unit agrees on it whatever macros it was compiled with.

#include <cstddef>
#include <new>
#include <vector>

#include <dlfl/detail/block_cache.h>

namespace dlfl::detail {

template <class T>
struct LargeAllocator {
  using value_type = T;
  static constexpr std::size_t huge = std::size_t(2) << 20;

  LargeAllocator() = default;
  template <class U>
  LargeAllocator(const LargeAllocator<U>&) {}

  T* allocate(std::size_t n) {
    const std::size_t bytes = n * sizeof(T);
    if (bytes < huge) return static_cast<T*>(::operator new(bytes));
    return static_cast<T*>(acquire_block(bytes));
  }
  void deallocate(T* p, std::size_t n) {
    const std::size_t bytes = n * sizeof(T);
    if (bytes < huge) {
      ::operator delete(p);
    } else {
      release_block(p, bytes);
    }
  }
  template <class U>
  bool operator==(const LargeAllocator<U>&) const {
    return true;
  }
};

/// The vector type of the mesh's element arrays.
template <class T>
using LargeVector = std::vector<T, LargeAllocator<T>>;

}  // namespace dlfl::detail
