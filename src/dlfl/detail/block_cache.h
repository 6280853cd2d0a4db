#pragma once
// The inside of the process-wide cache of large freed blocks (2 MiB multiples) for the mesh's element arrays;
// dlfl/block_cache.h says why it exists and holds its public controls. Each step of a subdivision sequence
// frees arrays of the sizes the next one needs, so reuse is the common case.
//
// Built with DLFL_NO_BLOCK_CACHE (ASan, MSan and fuzz builds; not TSan) the cache is compiled out: a block
// kept for reuse, or rounded up to 2 MiB, would hide a use after free or a read past the end from
// AddressSanitizer, so every block then comes from operator new at its exact size.

#include <cstddef>

#include <dlfl/block_cache.h>  // the public controls: limit, size, release

namespace dlfl {

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
