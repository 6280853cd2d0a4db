#include <dlfl/detail/block_cache.h>

#include <cstdint>

#include <cstdlib>
#include <mutex>
#include <new>
#include <vector>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace dlfl {
namespace {

constexpr std::size_t huge = std::size_t(2) << 20;

}  // namespace

#if defined(DLFL_NO_BLOCK_CACHE)

// Compiled out: nothing is kept, and every block is exactly the array, so that AddressSanitizer sees the
// first byte past its end and poisons it once freed.
void set_block_cache_limit(std::size_t) {}

std::size_t block_cache_limit() { return 0; }

std::size_t block_cache_size() { return 0; }

void release_block_cache() {}

namespace detail {

void* acquire_block(std::size_t bytes) { return ::operator new(bytes); }

void release_block(void* p, std::size_t) noexcept { ::operator delete(p); }

}  // namespace detail

#else

namespace {

std::size_t rounded(std::size_t bytes) { return (bytes + huge - 1) / huge * huge; }

struct Block {
  void* p;
  std::size_t bytes;
};

struct Cache {
  std::mutex mutex;
  std::vector<Block> blocks;  // oldest first
  std::size_t total = 0;
  std::size_t limit = default_block_cache_limit;

  // Frees the oldest blocks until `total + incoming <= limit`. Caller holds the mutex.
  void shrink_for(std::size_t incoming) {
    std::size_t drop = 0;
    while (drop < blocks.size() && total + incoming > limit) {
      std::free(blocks[drop].p);
      total -= blocks[drop].bytes;
      ++drop;
    }
    blocks.erase(blocks.begin(), blocks.begin() + std::ptrdiff_t(drop));
  }
};

Cache& cache() {
  static Cache* c = new Cache;  // never destroyed: arrays of static meshes may be freed after main
  return *c;
}

}  // namespace

void set_block_cache_limit(std::size_t bytes) {
  Cache& c = cache();
  std::lock_guard lock(c.mutex);
  c.limit = bytes;
  c.shrink_for(0);
}

std::size_t block_cache_limit() {
  Cache& c = cache();
  std::lock_guard lock(c.mutex);
  return c.limit;
}

std::size_t block_cache_size() {
  Cache& c = cache();
  std::lock_guard lock(c.mutex);
  return c.total;
}

void release_block_cache() {
  Cache& c = cache();
  std::lock_guard lock(c.mutex);
  for (const Block& b : c.blocks) std::free(b.p);
  c.blocks.clear();
  c.total = 0;
}

namespace detail {

void* acquire_block(std::size_t bytes) {
  bytes = rounded(bytes);
  {
    Cache& c = cache();
    std::lock_guard lock(c.mutex);
    for (std::size_t i = c.blocks.size(); i-- > 0;) {  // newest first: most likely still in cache
      if (c.blocks[i].bytes == bytes) {
        void* p = c.blocks[i].p;
        c.total -= bytes;
        c.blocks.erase(c.blocks.begin() + std::ptrdiff_t(i));
        return p;
      }
    }
  }
  void* p = std::aligned_alloc(huge, bytes);
  if (!p) throw std::bad_alloc();
  advise_huge_pages(p, bytes);
  return p;
}

void release_block(void* p, std::size_t bytes) noexcept {
  bytes = rounded(bytes);
  Cache& c = cache();
  std::lock_guard lock(c.mutex);
  if (bytes > c.limit) {
    std::free(p);
    return;
  }
  c.shrink_for(bytes);
  c.blocks.push_back({p, bytes});
  c.total += bytes;
}

}  // namespace detail

#endif  // DLFL_NO_BLOCK_CACHE

namespace detail {

void advise_huge_pages(void* p, std::size_t bytes) noexcept {
#if defined(__linux__) && defined(MADV_HUGEPAGE)
  const auto first = (reinterpret_cast<std::uintptr_t>(p) + huge - 1) & ~(huge - 1);
  const auto last = (reinterpret_cast<std::uintptr_t>(p) + bytes) & ~(huge - 1);
  if (first < last) ::madvise(reinterpret_cast<void*>(first), last - first, MADV_HUGEPAGE);
#else
  (void)p;
  (void)bytes;
#endif
}

}  // namespace detail
}  // namespace dlfl
