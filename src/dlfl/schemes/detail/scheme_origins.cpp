#include <dlfl/schemes/detail/scheme_origins.h>

namespace dlfl::detail {
namespace {

template <class Range>
std::vector<std::uint32_t> live_indices(const Range& range, std::size_t live, std::uint32_t capacity) {
  std::vector<std::uint32_t> out;
  if (live == capacity) return out;  // dense: the identity
  out.reserve(live);
  for (auto h : range) out.push_back(h.index());
  return out;
}

Origin entry(const std::vector<Origin>& table, std::uint32_t i) {
  return i < table.size() ? table[i] : Origin{};
}

}  // namespace

InputHandles::InputHandles(const Mesh& input)
    : vertices_(live_indices(input.vertices(), input.num_vertices(), input.vertex_capacity())),
      edges_(live_indices(input.edges(), input.num_edges(), input.edge_capacity())),
      faces_(live_indices(input.faces(), input.num_faces(), input.face_capacity())),
      corners_(live_indices(input.corners(), input.num_corners(), input.corner_capacity())),
      counts_{static_cast<std::uint32_t>(input.num_vertices()), static_cast<std::uint32_t>(input.num_edges()),
              static_cast<std::uint32_t>(input.num_faces()),
              static_cast<std::uint32_t>(input.num_corners())} {}

void InputHandles::fill(std::span<Origin> slots, std::initializer_list<Origin::Kind> kinds) const {
  const std::vector<std::uint32_t>* const tables[] = {&vertices_, &edges_, &faces_, &corners_};
  Origin* slot = slots.data();
  for (Origin::Kind kind : kinds) {
    // A kind at a time, and the identity apart, so that each inner loop is a plain store.
    const std::size_t k = std::size_t(kind) - std::size_t(Origin::Kind::vertex);
    const std::vector<std::uint32_t>& handles = *tables[k];
    const std::uint32_t count = counts_[k];
    if (handles.empty()) {
      for (std::uint32_t i = 0; i < count; ++i) slot[i] = {kind, i};
    } else {
      for (std::uint32_t i = 0; i < count; ++i) slot[i] = {kind, handles[i]};
    }
    slot += count;
  }
}

void reset_origins(Origins& origins, const Mesh& output) {
  origins.vertices.assign(output.vertex_capacity(), Origin{});
  origins.edges.assign(output.edge_capacity(), Origin{});
  origins.faces.assign(output.face_capacity(), Origin{});
}

Origin compose(const Origin& later, const Origins& earlier, std::span<const Origin> earlier_corners) {
  switch (later.kind) {
    case Origin::Kind::vertex:
      return entry(earlier.vertices, later.index);
    case Origin::Kind::edge:
      return entry(earlier.edges, later.index);
    case Origin::Kind::face:
      return entry(earlier.faces, later.index);
    case Origin::Kind::corner:
      return later.index < earlier_corners.size() ? earlier_corners[later.index] : Origin{};
    case Origin::Kind::none:
      break;
  }
  return {};
}

void compose(std::vector<Origin>& later, const Origins& earlier, std::span<const Origin> earlier_corners) {
  for (Origin& o : later) o = compose(o, earlier, earlier_corners);
}

void compose(Origins& later, const Origins& earlier, std::span<const Origin> earlier_corners) {
  compose(later.vertices, earlier, earlier_corners);
  compose(later.edges, earlier, earlier_corners);
  compose(later.faces, earlier, earlier_corners);
}

}  // namespace dlfl::detail
