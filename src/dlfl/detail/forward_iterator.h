#pragma once
// Internal: what every iterator of the mesh ranges has in common, written once (CRTP, so it costs nothing:
// no virtual call, everything inline).

#include <cstddef>

namespace dlfl::detail {

/// The member types and the two increments of a forward iterator over values `Value`. `Derived` gives
/// `operator*`, `operator==` and a `void advance()` that moves it to the next item (a private one needs
/// `friend ForwardIterator`).
template <class Derived, class Value>
class ForwardIterator {
 public:
  using value_type = Value;
  using difference_type = std::ptrdiff_t;

  /// Moves to the next item.
  Derived& operator++() {
    self().advance();
    return self();
  }
  /// Moves to the next item, giving the iterator as it was.
  Derived operator++(int) {
    Derived old = self();
    self().advance();
    return old;
  }

 private:
  Derived& self() { return static_cast<Derived&>(*this); }
};

}  // namespace dlfl::detail
