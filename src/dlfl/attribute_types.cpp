#include <dlfl/attribute_types.h>

#include <iterator>

#include <dlfl/detail/attribute_column.h>
#include <dlfl/detail/enum_names.h>

namespace dlfl {

const char* to_string(AttributeType type) {
  static constexpr const char* names[] = {"boolean", "integer", "number", "point"};
  static_assert(std::size(names) == std::size_t(AttributeType::point) + 1, "a name per enumerator, in order");
  return detail::name_at(type, names, "unknown attribute type");
}

bool same_attribute_value(const AttributeValue& a, const AttributeValue& b) {
  if (a.index() != b.index()) return false;
  return std::visit(
      [&](const auto& x) { return detail::same_value(x, std::get<std::decay_t<decltype(x)>>(b)); }, a);
}

}  // namespace dlfl
