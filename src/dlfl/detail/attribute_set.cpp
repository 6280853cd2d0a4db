#include <dlfl/detail/attribute_set.h>

#include <algorithm>

namespace dlfl::detail {

AttributeSet::AttributeSet(const AttributeSet& other) { *this = other; }

AttributeSet& AttributeSet::operator=(const AttributeSet& other) {
  if (this == &other) return *this;
  std::vector<Entry> copy;
  copy.reserve(other.entries_.size());
  for (const Entry& e : other.entries_) copy.push_back({e.name, e.column->clone()});
  entries_ = std::move(copy);
  return *this;
}

std::vector<AttributeSet::Entry>::const_iterator AttributeSet::lower_bound(ElementKind kind,
                                                                           std::string_view name) const {
  return std::lower_bound(entries_.begin(), entries_.end(), std::pair(kind, name),
                          [](const Entry& e, const std::pair<ElementKind, std::string_view>& key) {
                            const ElementKind k = e.column->kind();
                            return k != key.first ? k < key.first : std::string_view(e.name) < key.second;
                          });
}

AttributeColumn* AttributeSet::find(ElementKind kind, std::string_view name) const {
  const auto it = lower_bound(kind, name);
  if (it == entries_.end() || it->column->kind() != kind || it->name != name) return nullptr;
  return it->column.get();
}

AttributeColumn& AttributeSet::insert(std::string_view name, std::unique_ptr<AttributeColumn> column) {
  const auto at = lower_bound(column->kind(), name);
  return *entries_.insert(at, Entry{std::string(name), std::move(column)})->column;
}

bool AttributeSet::erase(ElementKind kind, std::string_view name) {
  const auto it = lower_bound(kind, name);
  if (it == entries_.end() || it->column->kind() != kind || it->name != name) return false;
  entries_.erase(it);
  return true;
}

void AttributeSet::remap(const CompactMap& map) {
  for (Entry& e : entries_) e.column->remap(map);
}

namespace {
template <class H>
std::unique_ptr<AttributeColumn> column_of(const AttributeValue& default_value) {
  return std::visit(
      [](const auto& d) -> std::unique_ptr<AttributeColumn> {
        return std::make_unique<TypedColumn<H, std::decay_t<decltype(d)>>>(d);
      },
      default_value);
}
}  // namespace

std::unique_ptr<AttributeColumn> make_column(ElementKind kind, const AttributeValue& default_value) {
  switch (kind) {
    case ElementKind::vertex:
      return column_of<VertexId>(default_value);
    case ElementKind::edge:
      return column_of<EdgeId>(default_value);
    case ElementKind::face:
      return column_of<FaceId>(default_value);
    case ElementKind::corner:
      break;
  }
  return column_of<CornerId>(default_value);
}

}  // namespace dlfl::detail
