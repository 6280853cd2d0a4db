#pragma once
// Internal: the handles of one kind, in increasing order, that a test accepts. The element ranges of Mesh
// (the live ones) and the surface faces of navigation.h are this range with a test of their own.

#include <cstdint>

#include <dlfl/detail/forward_iterator.h>

namespace dlfl {

class Mesh;

namespace detail {

/// The handles H(i), i from 0 below `end`, for which `Keep::keep(mesh, H(i))` is true. A step costs O(1)
/// plus the handles it passes over.
template <class H, class Keep>
class FilteredHandles {
 public:
  class iterator : public ForwardIterator<iterator, H> {
   public:
    iterator() = default;
    /// At the first accepted handle from index `index` on (or at `end`).
    iterator(const Mesh* mesh, std::uint32_t index, std::uint32_t end)
        : mesh_(mesh), index_(index), end_(end) {
      skip();
    }
    /// The handle.
    H operator*() const { return H(index_); }
    /// The same position.
    bool operator==(const iterator& o) const { return index_ == o.index_; }

   private:
    friend ForwardIterator<iterator, H>;
    void advance() {
      ++index_;
      skip();
    }
    void skip() {
      while (index_ < end_ && !Keep::keep(*mesh_, H(index_))) ++index_;
    }
    const Mesh* mesh_ = nullptr;
    std::uint32_t index_ = 0;
    std::uint32_t end_ = 0;
  };
  /// The accepted handles of `mesh` with an index below `end`.
  FilteredHandles(const Mesh* mesh, std::uint32_t end) : mesh_(mesh), end_(end) {}
  /// At the first accepted handle.
  iterator begin() const { return iterator(mesh_, 0, end_); }
  /// Past the last one.
  iterator end() const { return iterator(mesh_, end_, end_); }

 private:
  const Mesh* mesh_;
  std::uint32_t end_;
};

}  // namespace detail
}  // namespace dlfl
