#pragma once
// An allocator for the mesh's element arrays: blocks of 2 MiB and more are aligned to 2 MiB and marked for
// transparent huge pages. The operators chase links across arrays of hundreds of megabytes; with 4 KiB pages
// nearly every hop is a TLB miss, with 2 MiB pages almost none. Small blocks use the ordinary heap.

#include <cstddef>
#include <cstdlib>
#include <new>
#include <vector>

#if defined(__linux__)
#include <sys/mman.h>
#endif

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
    const std::size_t rounded = (bytes + huge - 1) / huge * huge;
    void* p = std::aligned_alloc(huge, rounded);
    if (!p) throw std::bad_alloc();
#if defined(__linux__) && defined(MADV_HUGEPAGE)
    ::madvise(p, rounded, MADV_HUGEPAGE);  // a hint; ignored where unsupported
#endif
    return static_cast<T*>(p);
  }
  void deallocate(T* p, std::size_t n) {
    if (n * sizeof(T) < huge) {
      ::operator delete(p);
    } else {
      std::free(p);
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
