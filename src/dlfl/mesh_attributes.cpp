// The named attributes of a mesh: lookup, the type-erased API, and their part of operator==. The typed API
// (templates in mesh.h) goes through the same lookup.

#include <dlfl/errors.h>
#include <dlfl/mesh.h>

namespace dlfl {
namespace {

std::string describe(ElementKind kind, std::string_view name) {
  return std::string(to_string(kind)) + " attribute '" + std::string(name) + "'";
}

[[noreturn]] void no_such(ElementKind kind, std::string_view name, const char* type) {
  std::string message = "mesh has no " + describe(kind, name);
  if (type) message += std::string(" of type ") + type;
  throw InvalidArgument(message);
}

void check_index(const Mesh& mesh, ElementKind kind, std::string_view name, std::uint32_t index) {
  if (index >= mesh.capacity(kind)) {
    throw InvalidArgument(describe(kind, name) + ": index " + std::to_string(index) + " is not below the " +
                          to_string(kind) + " capacity " + std::to_string(mesh.capacity(kind)));
  }
}

}  // namespace

detail::AttributeColumn* Mesh::find_column(ElementKind kind, std::string_view name,
                                           AttributeType type) const {
  detail::AttributeColumn* c = attributes_.find(kind, name);
  if (c && c->type() != type) {
    throw InvalidArgument(describe(kind, name) + " has type " + to_string(c->type()) + ", not " +
                          to_string(type));
  }
  return c;
}

detail::AttributeColumn& Mesh::column(ElementKind kind, std::string_view name, AttributeType type) const {
  detail::AttributeColumn* c = find_column(kind, name, type);
  if (!c) no_such(kind, name, to_string(type));
  return *c;
}

detail::AttributeColumn& Mesh::add_column(ElementKind kind, std::string_view name,
                                          const AttributeValue& default_value) {
  if (name.empty())
    throw InvalidArgument("add_attribute: the name of a " + std::string(to_string(kind)) +
                          " attribute must not be empty");
  if (detail::AttributeColumn* c = find_column(kind, name, type_of(default_value))) return *c;
  return attributes_.insert(name, detail::make_column(kind, default_value));
}

std::vector<AttributeInfo> Mesh::attributes() const {
  std::vector<AttributeInfo> list;
  list.reserve(attributes_.entries().size());
  for (const auto& e : attributes_.entries()) {
    list.push_back({e.name, e.column->kind(), e.column->type(), e.column->default_value()});
  }
  return list;
}

bool Mesh::has_attribute(ElementKind kind, std::string_view name) const {
  return attributes_.find(kind, name) != nullptr;
}

void Mesh::add_attribute(ElementKind kind, std::string_view name, const AttributeValue& default_value) {
  add_column(kind, name, default_value);
}

void Mesh::remove_attribute(ElementKind kind, std::string_view name) {
  if (!attributes_.erase(kind, name)) no_such(kind, name, nullptr);
}

AttributeValue Mesh::attribute_value(ElementKind kind, std::string_view name, std::uint32_t index) const {
  const detail::AttributeColumn* c = attributes_.find(kind, name);
  if (!c) no_such(kind, name, nullptr);
  check_index(*this, kind, name, index);
  return c->value(index);
}

void Mesh::set_attribute_value(ElementKind kind, std::string_view name, std::uint32_t index,
                               const AttributeValue& value) {
  detail::AttributeColumn* c = attributes_.find(kind, name);
  if (!c) no_such(kind, name, nullptr);
  check_index(*this, kind, name, index);
  if (type_of(value) != c->type()) {
    throw InvalidArgument("set_attribute_value: " + describe(kind, name) + " has type " +
                          to_string(c->type()) + ", the value is of type " + to_string(type_of(value)));
  }
  c->set_value(index, value);
}

bool Mesh::same_attributes(const Mesh& a, const Mesh& b) {
  const auto& x = a.attributes_.entries();
  const auto& y = b.attributes_.entries();
  if (x.size() != y.size()) return false;
  for (std::size_t i = 0; i < x.size(); ++i) {
    const detail::AttributeColumn& p = *x[i].column;
    const detail::AttributeColumn& q = *y[i].column;
    if (x[i].name != y[i].name || p.kind() != q.kind() || p.type() != q.type() ||
        !same_attribute_value(p.default_value(), q.default_value())) {
      return false;
    }
    // The elements agree (operator== checked them), so a's live handles are b's.
    const bool same_values = detail::visit_column(p, [&](const auto& typed) {
      using Column = std::decay_t<decltype(typed)>;
      using H = typename Column::handle_type;
      const auto& other = static_cast<const Column&>(q);
      for (H h : a.elements<H>()) {
        if (!detail::same_value(typed.get(h.index()), other.get(h.index()))) return false;
      }
      return true;
    });
    if (!same_values) return false;
  }
  return true;
}

}  // namespace dlfl
