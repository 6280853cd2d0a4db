#pragma once
// The value types of named mesh attributes, and their type-erased description (see `Mesh::attributes()`).

#include <cstdint>
#include <glm/vec3.hpp>
#include <string>
#include <type_traits>
#include <variant>

#include <dlfl/handles.h>

namespace dlfl {

/// The type of a named attribute's values. The order is that of the alternatives of `AttributeValue`.
enum class AttributeType : std::uint8_t {
  boolean,  ///< bool
  integer,  ///< int (32 bits)
  number,   ///< double
  point,    ///< glm::dvec3
};

/// One attribute value of any supported type; `index()` is the `AttributeType`.
using AttributeValue = std::variant<bool, int, double, glm::dvec3>;

/// A named attribute as `Mesh::attributes()` lists it.
struct AttributeInfo {
  std::string name;
  ElementKind kind;
  AttributeType type;
  AttributeValue default_value;  ///< what elements without a value of their own read (new ones, for instance)
};

/// True for the value types an attribute may have: bool, int, double, glm::dvec3.
template <class T>
inline constexpr bool is_attribute_type_v = std::is_same_v<T, bool> || std::is_same_v<T, int> ||
                                            std::is_same_v<T, double> || std::is_same_v<T, glm::dvec3>;

/// The `AttributeType` of a value type: `attribute_type_v<double> == AttributeType::number`.
template <class T>
requires is_attribute_type_v<T>
inline constexpr AttributeType attribute_type_v = std::is_same_v<T, bool>     ? AttributeType::boolean
                                                  : std::is_same_v<T, int>    ? AttributeType::integer
                                                  : std::is_same_v<T, double> ? AttributeType::number
                                                                              : AttributeType::point;

/// The type of a value.
inline AttributeType type_of(const AttributeValue& value) {
  return static_cast<AttributeType>(value.index());
}

/// "boolean", "integer", "number" or "point" (also the names the native JSON format uses).
const char* to_string(AttributeType type);

/// Equality of attribute values as `Mesh::operator==` sees it: the same type and the same bits, except that
/// every NaN equals every NaN (JSON keeps no NaN payloads). So 0.0 and -0.0 differ.
bool same_attribute_value(const AttributeValue& a, const AttributeValue& b);

}  // namespace dlfl
