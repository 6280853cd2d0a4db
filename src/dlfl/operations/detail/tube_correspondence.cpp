// The pairing of a tube's end corners (see tube_correspondence.h).

#include <algorithm>
#include <glm/geometric.hpp>

#include <dlfl/navigation.h>
#include <dlfl/operations/detail/tube_correspondence.h>

namespace dlfl::detail {
namespace {

using VertexAt = std::pair<std::uint32_t, std::uint32_t>;  // (vertex index, position in the face)

std::vector<CornerId> corners_along(const Mesh& m, FaceId f) {
  std::vector<CornerId> out;
  out.reserve(m.size(f));
  for (CornerId c : m.corners(f)) out.push_back(c);
  return out;
}

std::vector<VertexAt> sorted_vertices(const Mesh& m, const std::vector<CornerId>& corners) {
  std::vector<VertexAt> out;
  out.reserve(corners.size());
  for (std::uint32_t i = 0; i < corners.size(); ++i) out.push_back({m.vertex(corners[i]).index(), i});
  std::sort(out.begin(), out.end());
  return out;
}

std::uint32_t mod(std::int64_t x, std::uint32_t n) {
  const std::int64_t r = x % std::int64_t(n);
  return static_cast<std::uint32_t>(r < 0 ? r + n : r);
}

}  // namespace

TubeEndCorners tube_end_corners(const Mesh& m, FaceId f1, FaceId f2) {
  TubeEndCorners ends;
  ends.face1 = corners_along(m, f1);
  ends.face2 = corners_along(m, f2);
  const std::vector<VertexAt> v1 = sorted_vertices(m, ends.face1), v2 = sorted_vertices(m, ends.face2);
  // The positions of a vertex in face2: a run of the sorted list.
  const auto in_face2 = [&](std::uint32_t vertex, auto&& visit) {
    auto it = std::lower_bound(v2.begin(), v2.end(), VertexAt{vertex, 0});
    for (; it != v2.end() && it->first == vertex; ++it) visit(it->second);
  };
  for (const auto& [vertex, i] : v1) {
    in_face2(vertex, [&, i = i](std::uint32_t j) { ends.shared.push_back({i, j}); });
    for (VertexId w : neighbours(m, VertexId(vertex))) {
      in_face2(w.index(), [&, i = i](std::uint32_t j) { ends.adjacent.push_back({i, j}); });
    }
  }
  return ends;
}

VertexId self_joined_vertex(const Mesh& m, const TubeEndCorners& ends, std::uint32_t start1,
                            std::uint32_t start2) {
  const TubeSchedule s = ends.schedule();
  for (const auto& [x, y] : ends.shared) {
    // Long edge k joins face1 position start1 + a(k) and face2 position start2 - b(k).
    const auto [a_first, a_last] = s.edges_at_a(mod(std::int64_t(x) - start1, s.n1));
    const auto [b_first, b_last] = s.edges_at_b(mod(std::int64_t(start2) - y, s.n2));
    if (std::max(a_first, b_first) < std::min(a_last, b_last)) return m.vertex(ends.face1[x]);
  }
  return VertexId();
}

std::optional<TubeStart> best_tube_start(const Mesh& m, const TubeEndCorners& ends,
                                         std::optional<std::uint32_t> start1,
                                         std::optional<std::uint32_t> base2, std::uint32_t shift) {
  const TubeSchedule s = ends.schedule();
  // For one start1: how many pairs of `pairs` the tube to each partner start2 runs through.
  std::vector<std::uint32_t> self_loops(s.n2), beside(s.n2);
  const auto count = [&](const PositionPairs& pairs, std::uint32_t i, std::vector<std::uint32_t>& out) {
    std::fill(out.begin(), out.end(), 0u);
    for (const auto& [x, y] : pairs) {
      // Long edge k reaches face1 position x when a(k) = x - start1; it then ends at start2 - b(k) in face2.
      const auto [k_first, k_last] = s.edges_at_a(mod(std::int64_t(x) - i, s.n1));
      for (std::uint32_t k = k_first; k < k_last; ++k) ++out[mod(std::int64_t(y) + s.b(k), s.n2)];
    }
  };
  std::optional<TubeStart> best;
  std::uint32_t best_beside = 0;
  double best_distance = 0;
  const std::uint32_t first1 = start1 ? *start1 : 0, last1 = start1 ? *start1 + 1 : s.n1;
  const std::uint32_t first2 = base2 ? *base2 : 0, last2 = base2 ? *base2 + 1 : s.n2;
  for (std::uint32_t i = first1; i < last1; ++i) {
    count(ends.shared, i, self_loops);
    count(ends.adjacent, i, beside);
    const glm::dvec3& p = m.position(m.vertex(ends.face1[i]));
    for (std::uint32_t j = first2; j < last2; ++j) {
      const std::uint32_t partner = (j + shift) % s.n2;
      if (self_loops[partner] > 0) continue;
      const double d = glm::distance(p, m.position(m.vertex(ends.face2[j])));
      if (!best || beside[partner] < best_beside || (beside[partner] == best_beside && d < best_distance)) {
        best = TubeStart{i, j};
        best_beside = beside[partner];
        best_distance = d;
      }
    }
  }
  return best;
}

}  // namespace dlfl::detail
