#include <dlfl/attribute_types.h>

#include <dlfl/detail/attribute_column.h>

namespace dlfl {

const char* to_string(AttributeType type) {
  switch (type) {
    case AttributeType::boolean:
      return "boolean";
    case AttributeType::integer:
      return "integer";
    case AttributeType::number:
      return "number";
    case AttributeType::point:
      return "point";
  }
  return "unknown attribute type";
}

bool same_attribute_value(const AttributeValue& a, const AttributeValue& b) {
  if (a.index() != b.index()) return false;
  return std::visit(
      [&](const auto& x) { return detail::same_value(x, std::get<std::decay_t<decltype(x)>>(b)); }, a);
}

}  // namespace dlfl
