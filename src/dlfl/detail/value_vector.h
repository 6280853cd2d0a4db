#pragma once
// Contiguous storage for per-element values. `std::vector<bool>` packs bits and hands out proxies, so a bool
// value could be neither referenced nor viewed as a span; bools get a plain array of `bool` instead.

#include <algorithm>
#include <cstddef>
#include <memory>
#include <type_traits>
#include <utility>

#include <dlfl/detail/large_allocator.h>

namespace dlfl::detail {

/// A growable array of `bool`, one byte each: the subset of `std::vector` that value storage needs.
class BoolVector {
 public:
  BoolVector() = default;
  BoolVector(const BoolVector& other) { *this = other; }
  BoolVector(BoolVector&& other) noexcept
      : data_(std::move(other.data_)),
        size_(std::exchange(other.size_, 0)),
        capacity_(std::exchange(other.capacity_, 0)) {}
  BoolVector& operator=(const BoolVector& other) {
    if (this == &other) return *this;
    if (capacity_ < other.size_) {
      data_ = std::make_unique_for_overwrite<bool[]>(other.size_);
      capacity_ = other.size_;
    }
    std::copy(other.begin(), other.end(), data_.get());
    size_ = other.size_;
    return *this;
  }
  BoolVector& operator=(BoolVector&& other) noexcept {
    data_ = std::move(other.data_);
    size_ = std::exchange(other.size_, 0);
    capacity_ = std::exchange(other.capacity_, 0);
    return *this;
  }

  std::size_t size() const { return size_; }
  bool* data() { return data_.get(); }
  const bool* data() const { return data_.get(); }
  bool* begin() { return data_.get(); }
  bool* end() { return data_.get() + size_; }
  const bool* begin() const { return data_.get(); }
  const bool* end() const { return data_.get() + size_; }
  bool& operator[](std::size_t i) { return data_[i]; }
  const bool& operator[](std::size_t i) const { return data_[i]; }

  /// Room for `n` values without reallocating.
  void reserve(std::size_t n) {
    if (n > capacity_) reallocate(n);
  }
  /// Grows (geometrically, so repeated growth by one is amortised O(1)) filling `value`, or shrinks.
  void resize(std::size_t n, bool value = false) {
    if (n > capacity_) reallocate(std::max(n, 2 * capacity_));
    if (n > size_) std::fill(data_.get() + size_, data_.get() + n, value);
    size_ = n;
  }
  /// Removes the values in [first, last), moving the later ones down.
  void erase(bool* first, bool* last) {
    std::copy(last, end(), first);
    size_ -= static_cast<std::size_t>(last - first);
  }

 private:
  void reallocate(std::size_t capacity) {
    auto grown = std::make_unique_for_overwrite<bool[]>(capacity);
    std::copy(begin(), end(), grown.get());
    data_ = std::move(grown);
    capacity_ = capacity;
  }

  std::unique_ptr<bool[]> data_;
  std::size_t size_ = 0;
  std::size_t capacity_ = 0;
};

/// The storage of values of type T, indexed by handle: `LargeVector<T>` (huge pages for big arrays), except
/// for bool (see `BoolVector`).
template <class T>
using ValueVector = std::conditional_t<std::is_same_v<T, bool>, BoolVector, LargeVector<T>>;

}  // namespace dlfl::detail
