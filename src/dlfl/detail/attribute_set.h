#pragma once
// The named attributes a mesh owns: columns kept sorted by (element kind, name). Copying the set copies every
// column; an empty set (the common case) costs nothing to copy.

#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include <dlfl/detail/attribute_column.h>

namespace dlfl::detail {

class AttributeSet {
 public:
  struct Entry {
    std::string name;
    std::unique_ptr<AttributeColumn> column;
  };

  AttributeSet() = default;
  AttributeSet(const AttributeSet& other);
  AttributeSet& operator=(const AttributeSet& other);
  AttributeSet(AttributeSet&&) noexcept = default;
  AttributeSet& operator=(AttributeSet&&) noexcept = default;

  bool empty() const { return entries_.empty(); }
  /// In (kind, name) order.
  const std::vector<Entry>& entries() const { return entries_; }
  /// The column of that kind and name, or null.
  AttributeColumn* find(ElementKind kind, std::string_view name) const;
  /// Adds a column under `name`, keeping the order. Precondition: none of its kind has that name yet.
  AttributeColumn& insert(std::string_view name, std::unique_ptr<AttributeColumn> column);
  /// Removes the column; false if there was none.
  bool erase(ElementKind kind, std::string_view name);
  /// Every column follows `Mesh::compact`.
  void remap(const CompactMap& map);

 private:
  std::vector<Entry>::const_iterator lower_bound(ElementKind kind, std::string_view name) const;
  std::vector<Entry> entries_;
};

/// A new, empty column for elements of `kind`, of the type of `default_value`.
std::unique_ptr<AttributeColumn> make_column(ElementKind kind, const AttributeValue& default_value);

}  // namespace dlfl::detail
