#pragma once
// Internal: the names of an enumeration's values as one table, for the `to_string` functions.

#include <cstddef>

namespace dlfl::detail {

/// The name of `value`: `names[value]`, the table listing the enumerators' names in their declaration
/// order (each caller asserts the table's size against its last enumerator); `unknown` past the table.
template <class E, std::size_t N>
constexpr const char* name_at(E value, const char* const (&names)[N], const char* unknown) {
  const auto i = static_cast<std::size_t>(value);
  return i < N ? names[i] : unknown;
}

}  // namespace dlfl::detail
