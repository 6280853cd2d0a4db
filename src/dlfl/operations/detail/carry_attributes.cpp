// carry_attributes: see carry_attributes.h.

#include <dlfl/operations/detail/carry_attributes.h>

#include <vector>

#include <dlfl/attribute_types.h>
#include <dlfl/operations/detail/convex_hull_3d.h>

namespace dlfl::detail {

namespace {

Origin::Kind origin_kind(ElementKind kind) {
  switch (kind) {
    case ElementKind::vertex:
      return Origin::Kind::vertex;
    case ElementKind::edge:
      return Origin::Kind::edge;
    case ElementKind::face:
      return Origin::Kind::face;
    case ElementKind::corner:
      break;
  }
  return Origin::Kind::corner;
}

}  // namespace

void carry_attributes(const Mesh& from, const Origins& origins, std::span<const Origin> corners, Mesh& to) {
  declare_attributes(from, to);
  for (const AttributeInfo& a : from.attributes()) {
    const std::span<const Origin> of = a.kind == ElementKind::vertex
                                           ? std::span<const Origin>(origins.vertices)
                                       : a.kind == ElementKind::edge ? std::span<const Origin>(origins.edges)
                                       : a.kind == ElementKind::face ? std::span<const Origin>(origins.faces)
                                                                     : corners;
    const Origin::Kind wanted = origin_kind(a.kind);
    for (std::uint32_t i = 0; i < of.size(); ++i) {
      if (of[i].kind != wanted) continue;
      const AttributeValue value = from.attribute_value(a.kind, a.name, of[i].index);
      if (!same_attribute_value(value, a.default_value)) to.set_attribute_value(a.kind, a.name, i, value);
    }
  }
}

}  // namespace dlfl::detail
