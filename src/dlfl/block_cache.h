#pragma once
// How much freed memory the library keeps for reuse. The mesh's element arrays of 2 MiB and more come from a
// process-wide cache of freed blocks: memory fresh from the kernel must be faulted in page by page, which
// costs about a third of a subdivision step at a million faces, while a block handed back by a mesh that died
// is already mapped. A library should not sit on memory it no longer needs, so the cache is bounded: by
// default it keeps at most 256 MiB (`default_block_cache_limit`), and a block larger than the limit goes back
// to the system at once. A program that runs many big steps in a row (a benchmark, a batch job) can raise the
// limit; one that is done with meshes can empty the cache. docs/performance.md has the figures.

#include <cstddef>

namespace dlfl {

/// The cache's limit until `set_block_cache_limit` changes it: 256 MiB.
inline constexpr std::size_t default_block_cache_limit = std::size_t(256) << 20;

/// Sets how many bytes of freed blocks the cache may keep for reuse (default `default_block_cache_limit`);
/// blocks beyond it go back to the system at once. 0 turns the cache off. Lowering the limit releases cached
/// blocks at once. Thread-safe. Does nothing when the cache is compiled out (DLFL_NO_BLOCK_CACHE, the ASan
/// and fuzz builds).
void set_block_cache_limit(std::size_t bytes);

/// The limit in force: `default_block_cache_limit` until `set_block_cache_limit` changes it; 0 when the cache
/// is compiled out.
std::size_t block_cache_limit();

/// The bytes of freed blocks the cache holds right now; always 0 when the cache is compiled out.
std::size_t block_cache_size();

/// Gives every cached block back to the system; the limit stays. Thread-safe.
void release_block_cache();

}  // namespace dlfl
