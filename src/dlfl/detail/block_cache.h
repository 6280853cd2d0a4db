#pragma once
// A process-wide cache of large freed blocks (2 MiB multiples) for the mesh's element arrays. Memory fresh
// from the kernel must be faulted in and zeroed page by page, which costs about a third of a subdivision
// step at a million faces; a block handed back by a mesh that died is already mapped. Each step of a
// subdivision sequence frees arrays of the sizes the next one needs, so reuse is the common case.

#include <cstddef>

namespace dlfl {

/// Sets how many bytes of freed blocks the cache may keep for reuse (default 1 GiB); blocks beyond it go
/// back to the system at once. 0 turns the cache off. Lowering the limit releases cached blocks at once.
/// Thread-safe.
void set_block_cache_limit(std::size_t bytes);

/// The bytes of freed blocks the cache holds right now.
std::size_t block_cache_size();

/// Gives every cached block back to the system (the same as `set_block_cache_limit` to the current limit
/// after emptying). Thread-safe.
void release_block_cache();

namespace detail {
/// A block of `bytes` (a multiple of 2 MiB), aligned to 2 MiB and marked for huge pages: a cached one of
/// exactly that size if there is one. Throws std::bad_alloc.
void* acquire_block(std::size_t bytes);
/// Returns a block from `acquire_block` (same size) to the cache, or to the system if the cache is full.
void release_block(void* p, std::size_t bytes) noexcept;
/// Marks the 2 MiB-aligned part of [p, p + bytes) for transparent huge pages, for buffers that do not come
/// from `acquire_block` (a std::vector about to be filled). A hint: ignored where unsupported.
void advise_huge_pages(void* p, std::size_t bytes) noexcept;
}  // namespace detail

}  // namespace dlfl
