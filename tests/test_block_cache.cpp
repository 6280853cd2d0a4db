// The cache of freed large blocks: freed arrays are kept up to the limit and reused, and can be released.
// Compiled out (DLFL_NO_BLOCK_CACHE, the sanitizer and fuzz builds), large arrays come from the allocator at
// their exact size, so AddressSanitizer guards their end and poisons them when freed.

#include <doctest/doctest.h>

#include <dlfl/block_cache.h>
#include <dlfl/detail/large_allocator.h>

#if defined(__SANITIZE_ADDRESS__)
#define DLFL_TEST_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define DLFL_TEST_ASAN 1
#endif
#endif
#if defined(DLFL_TEST_ASAN)
#include <sanitizer/asan_interface.h>
#endif

using namespace dlfl;

#if !defined(DLFL_NO_BLOCK_CACHE)

TEST_CASE("block cache: freed large arrays are kept up to the limit and reused") {
  release_block_cache();
  set_block_cache_limit(std::size_t(64) << 20);
  const std::size_t n = (std::size_t(3) << 20) / sizeof(double);  // 3 MiB: one 4 MiB block
  const double* first = nullptr;
  {
    detail::LargeVector<double> a(n, 1.0);
    first = a.data();
    CHECK(block_cache_size() == 0);
  }
  CHECK(block_cache_size() == (std::size_t(4) << 20));
  {
    detail::LargeVector<double> b(n, 2.0);  // the same block size: the cached block comes back
    CHECK(b.data() == first);
    CHECK(b[n - 1] == 2.0);
    CHECK(block_cache_size() == 0);
  }
  // Small arrays never reach the cache.
  { detail::LargeVector<double> small(100, 0.0); }
  CHECK(block_cache_size() == (std::size_t(4) << 20));
  release_block_cache();
  CHECK(block_cache_size() == 0);
  // A limit below the block size sends blocks straight back to the system; lowering it empties the cache.
  set_block_cache_limit(std::size_t(1) << 20);
  { detail::LargeVector<double> c(n, 3.0); }
  CHECK(block_cache_size() == 0);
  set_block_cache_limit(std::size_t(64) << 20);
  { detail::LargeVector<double> d(n, 4.0), e(n, 5.0); }
  CHECK(block_cache_size() == (std::size_t(8) << 20));
  set_block_cache_limit(std::size_t(4) << 20);  // keeps the newest block only
  CHECK(block_cache_size() == (std::size_t(4) << 20));
  set_block_cache_limit(0);
  CHECK(block_cache_size() == 0);
  set_block_cache_limit(default_block_cache_limit);
}

TEST_CASE("block cache: the default limit keeps a 200 MiB block and sends a 300 MiB one back") {
  // The bound on what a library may sit on: at most 256 MiB by default.
  set_block_cache_limit(default_block_cache_limit);
  CHECK(block_cache_limit() == (std::size_t(256) << 20));
  release_block_cache();
  const auto mib = [](std::size_t n) { return (n << 20) / sizeof(double); };
  { detail::LargeVector<double> big(mib(300), 0.0); }
  CHECK(block_cache_size() == 0);
  { detail::LargeVector<double> kept(mib(200), 0.0); }
  CHECK(block_cache_size() == (std::size_t(200) << 20));
  { detail::LargeVector<double> other(mib(100), 0.0); }  // the two together pass the limit: the older goes
  CHECK(block_cache_size() == (std::size_t(100) << 20));
  release_block_cache();
  CHECK(block_cache_size() == 0);
  CHECK(block_cache_limit() == default_block_cache_limit);  // releasing keeps the limit
}

#else

TEST_CASE("block cache: compiled out, large arrays go back to the allocator at their exact size") {
  // Does nothing: no block is ever kept.
  set_block_cache_limit(std::size_t(64) << 20);
  const std::size_t n = (std::size_t(3) << 20) / sizeof(double);  // 3 MiB: the cache would give 4 MiB
  const double* first = nullptr;
  {
    detail::LargeVector<double> a(n, 1.0);
    first = a.data();
    CHECK(a[n - 1] == 1.0);
#if defined(DLFL_TEST_ASAN)
    // The array ends where the allocation does: the next byte is ASan's redzone, not the rest of a block.
    CHECK_FALSE(__asan_address_is_poisoned(first + n - 1));
    CHECK(__asan_address_is_poisoned(first + n));
#endif
  }
  CHECK(block_cache_size() == 0);
#if defined(DLFL_TEST_ASAN)
  CHECK(__asan_address_is_poisoned(first));  // freed to the allocator: a use after free is reported
#endif
  {
    detail::LargeVector<double> b(n, 2.0);
    CHECK(block_cache_size() == 0);
#if defined(DLFL_TEST_ASAN)
    CHECK(b.data() != first);  // the freed block waits in ASan's quarantine instead of coming back
#endif
  }
  CHECK(block_cache_size() == 0);
  release_block_cache();
  CHECK(block_cache_size() == 0);
  CHECK(block_cache_limit() == 0);
  set_block_cache_limit(default_block_cache_limit);
}

#endif  // DLFL_NO_BLOCK_CACHE
