// set_attribute: writes one value of a named mesh attribute (dlfl/attributes.h), creating the attribute on
// its first write. Undo restores the old value, and removes the attribute again if this write created it.

#include <cmath>
#include <string>

#include <dlfl/errors.h>
#include <dlfl/operations/detail/operation_table.h>

namespace dlfl::detail {
namespace {

ElementKind element_kind(const std::string& element) {
  if (element == "vertex") return ElementKind::vertex;
  if (element == "edge") return ElementKind::edge;
  if (element == "face") return ElementKind::face;
  return ElementKind::corner;
}

// The attribute's type: the existing attribute's, else the one asked for, else from the value's size.
AttributeType value_type(const Mesh& m, const Params& p) {
  const ElementKind kind = element_kind(p.text("element"));
  const std::string& name = p.text("name");
  for (const AttributeInfo& a : m.attributes()) {
    if (a.kind == kind && a.name == name) return a.type;
  }
  const std::string& type = p.text("type");
  if (type == "boolean") return AttributeType::boolean;
  if (type == "integer") return AttributeType::integer;
  if (type == "number") return AttributeType::number;
  if (type == "point") return AttributeType::point;
  return p.get("value").as_numbers().size() == 3 ? AttributeType::point : AttributeType::number;
}

// The numbers as a value of `type`; ParameterError naming `field` if they cannot be one.
AttributeValue as_value(AttributeType type, const std::vector<double>& n, const char* field) {
  const auto fail = [&](const std::string& what) {
    throw ParameterError("set_attribute: parameter " + std::string(field) + " " + what, field);
  };
  if (type == AttributeType::point) {
    if (n.size() != 3) fail("must be three numbers x,y,z for a point attribute");
    return glm::dvec3(n[0], n[1], n[2]);
  }
  if (n.size() != 1) fail("must be one number for a " + std::string(to_string(type)) + " attribute");
  switch (type) {
    case AttributeType::boolean:
      if (n[0] != 0.0 && n[0] != 1.0) fail("must be 0 or 1 for a boolean attribute");
      return n[0] == 1.0;
    case AttributeType::integer:
      if (n[0] != std::floor(n[0]) || std::abs(n[0]) > 2147483647.0) fail("must be a 32-bit whole number");
      return static_cast<int>(n[0]);
    default:
      return n[0];
  }
}

AttributeValue default_of(AttributeType type, const Params& p) {
  if (p.has("default")) return as_value(type, p.get("default").as_numbers(), "default");
  switch (type) {
    case AttributeType::boolean:
      return false;
    case AttributeType::integer:
      return 0;
    case AttributeType::number:
      return 0.0;
    case AttributeType::point:
      return glm::dvec3(0.0);
  }
  return 0.0;
}

}  // namespace

std::vector<OperationSpec> attribute_operation_specs() {
  return {edit_operation(
      "set_attribute", "writes one value of a named attribute, creating the attribute on its first write",
      {param("element", ParamType::text, "the kind of element").one_of({"vertex", "edge", "face", "corner"}),
       param("name", ParamType::text, "the attribute's name"),
       param("index", ParamType::integer, "the element's handle").at_least(0),
       param("value", ParamType::numbers, "one number (boolean 0/1, integer, number) or x,y,z (point)"),
       param("type", ParamType::text, "auto",
             "the type of a new attribute; auto: point for x,y,z, else number")
           .one_of({"auto", "boolean", "integer", "number", "point"}),
       param("default", ParamType::numbers, "the default of a new attribute").optional("zero")},
      "V+0, E+0, F+0",
      [](Transaction& tx, const Params& p) {
        const ElementKind kind = element_kind(p.text("element"));
        const AttributeType type = value_type(tx.mesh(), p);
        tx.add_attribute(kind, p.text("name"), default_of(type, p));
        tx.set_attribute(kind, p.text("name"), static_cast<std::uint32_t>(p.integer("index")),
                         as_value(type, p.get("value").as_numbers(), "value"));
        return Params{};
      },
      [](const Mesh& m, Params& p) {
        const auto index = p.integer("index");
        if (index >= std::int64_t(VertexId::invalid_index) ||
            !m.is_alive(element_kind(p.text("element")), static_cast<std::uint32_t>(index))) {
          throw ParameterError(
              "set_attribute: parameter index = " + std::to_string(index) + ": no such " + p.text("element"),
              "index");
        }
        const AttributeType type = value_type(m, p);
        as_value(type, p.get("value").as_numbers(), "value");  // checked before anything changes
        if (p.has("default")) as_value(type, p.get("default").as_numbers(), "default");
      })};
}

}  // namespace dlfl::detail
