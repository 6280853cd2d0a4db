#pragma once
// Internal to the schemes: building origin maps (dlfl/schemes/origins.h). A scheme that reads a dense copy of
// its input numbers its output from the copy's handles; InputHandles turns those back into the input's own.
// Composite schemes (dual-honeycomb-dual, MLCA after a split, MHP) chain the maps of their steps with
// `compose`, which needs the origins of a step's corners as well when the next step's origins name corners.

#include <array>
#include <concepts>
#include <cstdint>
#include <initializer_list>
#include <span>
#include <vector>

#include <dlfl/mesh.h>
#include <dlfl/schemes/origins.h>

namespace dlfl::detail {

/// The input's own handle behind each index of its dense copy (see `dense_mesh`): the k-th live element of
/// each kind. Nothing is stored for a kind without removed elements (the map is the identity).
class InputHandles {
 public:
  explicit InputHandles(const Mesh& input);
  Origin vertex(std::uint32_t dense) const { return {Origin::Kind::vertex, map(vertices_, dense)}; }
  Origin edge(std::uint32_t dense) const { return {Origin::Kind::edge, map(edges_, dense)}; }
  Origin face(std::uint32_t dense) const { return {Origin::Kind::face, map(faces_, dense)}; }
  Origin corner(std::uint32_t dense) const { return {Origin::Kind::corner, map(corners_, dense)}; }

  /// Sets `slots`, from slot 0, to the origins of every input element of each of `kinds` (not none) in turn,
  /// in dense order: with {vertex, edge}, slot v <- vertex v and slot V + e <- edge e. Later slots are kept.
  void fill(std::span<Origin> slots, std::initializer_list<Origin::Kind> kinds) const;

 private:
  static std::uint32_t map(const std::vector<std::uint32_t>& handles, std::uint32_t k) {
    return handles.empty() ? k : handles[k];
  }
  std::vector<std::uint32_t> vertices_, edges_, faces_, corners_;
  std::array<std::uint32_t, 4> counts_;  // live vertices, edges, faces, corners of the input
};

/// Sizes `origins` to the capacities of `output`, every slot Kind::none.
void reset_origins(Origins& origins, const Mesh& output);

/// The origin of side `side` (of `sides`; side j leaves corner j) of the polygon that input corner c of dense
/// `m` becomes when its two edges are halved (Loop's corner triangles, P's triangles, the quad split's
/// quads): side 0 halves edge(c) and the last side edge(prev c), so they stem from those edges; side 1 is the
/// inner edge of c and side 2 of a quad the inner edge of prev(c), so they stem from those corners.
inline Origin corner_polygon_side(const Mesh& m, const InputHandles& in, CornerId c, std::uint32_t side,
                                  std::uint32_t sides) {
  if (side == 0) return in.edge(m.edge(c).index());
  if (side + 1 == sides) return in.edge(m.edge(m.prev(c)).index());
  return in.corner(side == 1 ? c.index() : m.prev(c).index());
}

/// Sets the origin of every live edge of `output` to `of_corner(k)`, k the index of the edge's side-0 corner
/// (the origin of the edge leaving output corner k).
template <std::invocable<std::uint32_t> OfCorner>
void set_edge_origins(Origins& origins, const Mesh& output, const OfCorner& of_corner) {
  for (EdgeId e : output.edges()) origins.edges[e.index()] = of_corner(output.corner(e, 0).index());
}

/// The same from a table of the origin of the edge leaving each output corner, by corner index.
inline void set_edge_origins(Origins& origins, const Mesh& output, std::span<const Origin> edge_of) {
  set_edge_origins(origins, output, [edge_of](std::uint32_t k) { return edge_of[k]; });
}

/// An origin that names an element of an intermediate mesh M, taken back to M's own origin: `earlier` says
/// where M's vertices, edges and faces come from, `earlier_corners` (by corner handle) where its corners do.
Origin compose(const Origin& later, const Origins& earlier, std::span<const Origin> earlier_corners);

/// `compose` on every entry, in place.
void compose(Origins& later, const Origins& earlier, std::span<const Origin> earlier_corners);
void compose(std::vector<Origin>& later, const Origins& earlier, std::span<const Origin> earlier_corners);

}  // namespace dlfl::detail
