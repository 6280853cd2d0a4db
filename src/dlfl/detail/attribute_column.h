#pragma once
// The storage of one named attribute: its values by element handle and its default. The mesh keeps columns
// behind the type-erased `AttributeColumn`; typed access (`Attribute<H, T>`) goes to `TypedColumn<H, T>`
// directly, with no virtual call.

#include <bit>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <type_traits>

#include <dlfl/attribute_types.h>
#include <dlfl/compact_map.h>
#include <dlfl/detail/value_vector.h>

namespace dlfl::detail {

// Value equality as Mesh::operator== sees it: bit for bit, but any NaN equals any NaN.
inline bool same_value(bool a, bool b) { return a == b; }
inline bool same_value(int a, int b) { return a == b; }
inline bool same_value(double a, double b) {
  return (std::isnan(a) && std::isnan(b)) ||
         std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b);
}
inline bool same_value(const glm::dvec3& a, const glm::dvec3& b) {
  return same_value(a.x, b.x) && same_value(a.y, b.y) && same_value(a.z, b.z);
}

/// One attribute's values, whatever their type. Slots past `size()` read the default: the column grows only
/// when a value is written, so operators that add elements never touch it.
class AttributeColumn {
 public:
  virtual ~AttributeColumn() = default;
  virtual std::unique_ptr<AttributeColumn> clone() const = 0;
  virtual ElementKind kind() const = 0;
  virtual AttributeType type() const = 0;
  virtual AttributeValue default_value() const = 0;
  /// The value of slot `index` (the default past `size()`).
  virtual AttributeValue value(std::uint32_t index) const = 0;
  /// Precondition: `type_of(value) == type()`.
  virtual void set_value(std::uint32_t index, const AttributeValue& value) = 0;
  /// Follows `Mesh::compact`.
  virtual void remap(const CompactMap& map) = 0;
  virtual void reserve(std::size_t slots) = 0;
  /// Slots stored (never more than the mesh has).
  virtual std::size_t size() const = 0;
};

/// The column of an attribute of values T on elements named by handles H.
template <class H, class T>
class TypedColumn final : public AttributeColumn {
 public:
  using handle_type = H;
  using value_type = T;

  explicit TypedColumn(const T& default_value) : default_(default_value) {}

  /// Read access: the default past the stored slots.
  const T& get(std::uint32_t index) const { return index < values_.size() ? values_[index] : default_; }
  /// Write access: grows the column (filling the default) up to `index` first.
  T& slot(std::uint32_t index) {
    if (index >= values_.size()) [[unlikely]]
      values_.resize(std::size_t(index) + 1, default_);
    return values_[index];
  }
  const T& default_ref() const { return default_; }
  const ValueVector<T>& stored() const { return values_; }

  std::unique_ptr<AttributeColumn> clone() const override { return std::make_unique<TypedColumn>(*this); }
  ElementKind kind() const override { return element_kind_v<H>; }
  AttributeType type() const override { return attribute_type_v<T>; }
  AttributeValue default_value() const override { return default_; }
  AttributeValue value(std::uint32_t index) const override { return get(index); }
  void set_value(std::uint32_t index, const AttributeValue& value) override {
    slot(index) = std::get<T>(value);
  }
  void remap(const CompactMap& map) override { remap_slots(values_, map.of<H>()); }
  void reserve(std::size_t slots) override { values_.reserve(slots); }
  std::size_t size() const override { return values_.size(); }

 private:
  ValueVector<T> values_;
  T default_;
};

/// Calls `f` with the column as the `TypedColumn<H, T>` it is, T being its type.
template <class H, class Column, class F>
decltype(auto) visit_typed_column(Column& column, F&& f) {
  constexpr bool is_const = std::is_const_v<Column>;
  auto typed = [&]<class T>(T*) -> decltype(auto) {
    using Typed = std::conditional_t<is_const, const TypedColumn<H, T>, TypedColumn<H, T>>;
    return f(static_cast<Typed&>(column));
  };
  switch (column.type()) {
    case AttributeType::boolean:
      return typed(static_cast<bool*>(nullptr));
    case AttributeType::integer:
      return typed(static_cast<int*>(nullptr));
    case AttributeType::number:
      return typed(static_cast<double*>(nullptr));
    case AttributeType::point:
      break;
  }
  return typed(static_cast<glm::dvec3*>(nullptr));
}

/// Calls `f` with the column as the `TypedColumn<H, T>` it is, H and T being its element kind and type.
template <class Column, class F>
decltype(auto) visit_column(Column& column, F&& f) {
  switch (column.kind()) {
    case ElementKind::vertex:
      return visit_typed_column<VertexId>(column, f);
    case ElementKind::edge:
      return visit_typed_column<EdgeId>(column, f);
    case ElementKind::face:
      return visit_typed_column<FaceId>(column, f);
    case ElementKind::corner:
      break;
  }
  return visit_typed_column<CornerId>(column, f);
}

}  // namespace dlfl::detail
