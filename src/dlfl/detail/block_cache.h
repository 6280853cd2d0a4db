#pragma once
// A process-wide cache of large freed blocks (2 MiB multiples) for the mesh's element arrays. Memory fresh
// from the kernel must be faulted in and zeroed page by page, which costs about a third of a subdivision
// step at a million faces; a block handed back by a mesh that died is already mapped. Each step of a
// subdivision sequence frees arrays of the sizes the next one needs, so reuse is the common case.
//
// Built with DLFL_NO_BLOCK_CACHE (ASan, MSan and fuzz builds; not TSan) the cache is compiled out: a block
// kept for reuse, or rounded up to 2 MiB, would hide a use after free or a read past the end from
// AddressSanitizer, so every block then comes from operator new at its exact size.

#include <cstddef>

namespace dlfl {

/// Sets how many bytes of freed blocks the cache may keep for reuse (default 1 GiB); blocks beyond it go
/// back to the system at once. 0 turns the cache off. Lowering the limit releases cached blocks at once.
/// Thread-safe. Does nothing when the cache is compiled out (DLFL_NO_BLOCK_CACHE).
void set_block_cache_limit(std::size_t bytes);

/// The bytes of freed blocks the cache holds right now; always 0 when the cache is compiled out.
std::size_t block_cache_size();

/// Gives every cached block back to the system (the same as `set_block_cache_limit` to the current limit
/// after emptying). Thread-safe.
void release_block_cache();

namespace detail {
/// A block for `bytes` (2 MiB or more): `bytes` rounded up to a multiple of 2 MiB, aligned to 2 MiB and
/// marked for huge pages, a cached one of that size if there is one. With the cache compiled out, exactly
/// `bytes` from operator new. Throws std::bad_alloc.
void* acquire_block(std::size_t bytes);
/// Returns a block from `acquire_block` (same `bytes`) to the cache, or to the system if the cache is full.
void release_block(void* p, std::size_t bytes) noexcept;
/// Marks the 2 MiB-aligned part of [p, p + bytes) for transparent huge pages, for buffers that do not come
/// from `acquire_block` (a std::vector about to be filled). A hint: ignored where unsupported.
void advise_huge_pages(void* p, std::size_t bytes) noexcept;
}  // namespace detail

}  // namespace dlfl
