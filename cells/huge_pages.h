#pragma once
// Huge-page hints for the large output arrays of the cell-complex algorithms. A `CellComplex` keeps plain
// std::vector storage, so a fresh result is faulted in page by page; at a million cells that costs more than
// the subdivision itself on a VM. Asking for transparent huge pages on the buffer before it is first written
// cuts the faults 512-fold. Internal to the library.

#include <cstddef>
#include <vector>

namespace dlfl::detail {

/// Marks the 2 MiB-aligned part of [p, p + bytes) for transparent huge pages. A hint: ignored where
/// unsupported, and harmless on memory that is already mapped.
void advise_huge_pages(void* p, std::size_t bytes) noexcept;

/// `v.reserve(n)`, then the hint on the whole reserved buffer (before anything new is written to it).
template <class T>
void reserve_huge(std::vector<T>& v, std::size_t n) {
  v.reserve(n);
  advise_huge_pages(v.data(), v.capacity() * sizeof(T));
}

}  // namespace dlfl::detail
