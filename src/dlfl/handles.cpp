#include <dlfl/handles.h>

#include <iterator>

#include <dlfl/detail/enum_names.h>

namespace dlfl {
namespace {
std::string name(char prefix, std::uint32_t value) {
  if (value == VertexId::invalid_index) return std::string(1, prefix) + "-";
  return prefix + std::to_string(value);
}
}  // namespace

std::string to_string(VertexId v) { return name('v', v.value); }
std::string to_string(EdgeId e) { return name('e', e.value); }
std::string to_string(FaceId f) { return name('f', f.value); }
std::string to_string(CornerId c) { return name('c', c.value); }

const char* to_string(ElementKind kind) {
  static constexpr const char* names[] = {"vertex", "edge", "face", "corner"};
  static_assert(std::size(names) == std::size_t(ElementKind::corner) + 1, "a name per enumerator, in order");
  return detail::name_at(kind, names, "unknown element kind");
}

}  // namespace dlfl
