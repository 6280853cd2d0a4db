// The cache of freed large blocks: freed arrays are kept up to the limit and reused, and can be released.

#include <doctest/doctest.h>

#include <dlfl/detail/block_cache.h>
#include <dlfl/detail/large_allocator.h>

using namespace dlfl;

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
  set_block_cache_limit(std::size_t(1) << 30);
}
