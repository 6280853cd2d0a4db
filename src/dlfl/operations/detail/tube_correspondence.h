#pragma once
// Internal to connect_faces: how the corners of a tube's two end faces pair up. The tube's long edges follow
// a fixed schedule from a starting pair of corners; the faces may share vertices, and a starting pair is
// usable only if none of its long edges would join a vertex to itself.

#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

#include <dlfl/mesh.h>

namespace dlfl::detail {

/// The long edges of a tube between faces of n1 and n2 sides: m = max(n1, n2) of them. Edge k joins the
/// corner a(k) = floor(k n1 / m) steps forward along face1 from its start and the corner b(k) = floor(k n2 /
/// m) steps backward along face2 from its start. Both advance by 0 or 1 from one edge to the next, never
/// both by 0, so each face of the tube is a quad (both advance) or a triangle (one does).
struct TubeSchedule {
  std::uint32_t n1 = 0;
  std::uint32_t n2 = 0;

  std::uint32_t edges() const { return n1 > n2 ? n1 : n2; }
  std::uint32_t a(std::uint32_t k) const { return step(k, n1); }
  std::uint32_t b(std::uint32_t k) const { return step(k, n2); }
  /// The long edges k whose face1 end is corner a(k) = alpha: the range [first, last) (empty if none).
  std::pair<std::uint32_t, std::uint32_t> edges_at_a(std::uint32_t alpha) const { return range(alpha, n1); }
  std::pair<std::uint32_t, std::uint32_t> edges_at_b(std::uint32_t beta) const { return range(beta, n2); }

 private:
  std::uint32_t step(std::uint32_t k, std::uint32_t n) const {
    return static_cast<std::uint32_t>(std::uint64_t(k) * n / edges());
  }
  // floor(k n / m) = i exactly for i m <= k n < (i + 1) m.
  std::pair<std::uint32_t, std::uint32_t> range(std::uint32_t i, std::uint32_t n) const {
    const std::uint64_t m = edges();
    return {static_cast<std::uint32_t>((i * m + n - 1) / n),
            static_cast<std::uint32_t>(((i + 1) * m + n - 1) / n)};
  }
};

/// Pairs (i, j) of positions in face1 and face2.
using PositionPairs = std::vector<std::pair<std::uint32_t, std::uint32_t>>;

/// The corners of the two end faces, each along its face from its first corner; the pairs of positions at
/// which they visit the same vertex (a long edge there would be a self-loop), and those whose vertices an
/// edge already joins (a long edge there would run beside that edge).
struct TubeEndCorners {
  std::vector<CornerId> face1;
  std::vector<CornerId> face2;
  PositionPairs shared;
  PositionPairs adjacent;

  TubeSchedule schedule() const {
    return {static_cast<std::uint32_t>(face1.size()), static_cast<std::uint32_t>(face2.size())};
  }
};

/// Reads the corners of f1 and f2 and how their vertices meet. O((n1 + n2) log(n1 + n2) + the valences of
/// f1's vertices + the number of pairs found).
TubeEndCorners tube_end_corners(const Mesh& mesh, FaceId f1, FaceId f2);

/// The vertex that the tube from face1's corner at position start1 and face2's corner at position start2
/// (the partner, twist included) would join to itself, or an invalid handle if there is none. O(shared).
VertexId self_joined_vertex(const Mesh& mesh, const TubeEndCorners& ends, std::uint32_t start1,
                            std::uint32_t start2);

/// A starting pair: positions in face1 and face2, the second before the twist.
struct TubeStart {
  std::uint32_t start1 = 0;
  std::uint32_t base2 = 0;
};

/// The best starting pair (start1, base2), with start1 and base2 fixed where given and the partner at
/// base2 + shift (mod n2): among the pairs that join no vertex to itself, those with the fewest long edges
/// beside an existing edge, then the closest corners; ties go to the smallest start1, then base2. Nothing if
/// every candidate joins a vertex to itself. O(n1 n2) when both are free.
std::optional<TubeStart> best_tube_start(const Mesh& mesh, const TubeEndCorners& ends,
                                         std::optional<std::uint32_t> start1,
                                         std::optional<std::uint32_t> base2, std::uint32_t shift);

}  // namespace dlfl::detail
