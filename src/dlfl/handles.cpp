#include <dlfl/handles.h>

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
  switch (kind) {
    case ElementKind::vertex:
      return "vertex";
    case ElementKind::edge:
      return "edge";
    case ElementKind::face:
      return "face";
    case ElementKind::corner:
      return "corner";
  }
  return "unknown element kind";
}

}  // namespace dlfl
