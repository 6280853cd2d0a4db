#pragma once
// Ear clipping of one face in its plane: which corners to cut off, one after another, to leave triangles.
// Shared by the triangulate operation (which cuts them with insert_edge) and the triangle-file writers (which
// only list the triangles). Internal to the library.

#include <cstdint>
#include <glm/vec2.hpp>
#include <optional>
#include <vector>

#include <dlfl/mesh.h>

namespace dlfl::detail {

/// A face's corners as nodes 0 .. n-1, in order from its first corner, projected into the face's plane (the
/// plane through its first corner normal to its Newell vector), as a circular list that loses a node with
/// each ear cut off. A corner is cut off when it is convex in that plane, its two neighbours are different
/// vertices, and no other corner lies in the triangle; when no corner is such an ear (a face not planar,
/// self-overlapping or degenerate), the most convex cuttable corner is cut instead. Among the candidates, one
/// that leaves its neighbours cuttable goes first, since a face that visits a vertex more than once can
/// otherwise be left with corners that no diagonal can cut off (a, b, a, b). O(n^2) per face. One clipper
/// can be restarted on face after face, reusing its storage.
class EarClipper {
 public:
  static constexpr std::uint32_t none = 0xFFFFFFFFu;

  /// A triangle cut off: the nodes before and after `tip` in the polygon at the time of the cut.
  struct Ear {
    std::uint32_t before, tip, after;
  };

  EarClipper() = default;
  EarClipper(const Mesh& mesh, FaceId f) { start(mesh, f); }

  /// Starts over on face f.
  void start(const Mesh& mesh, FaceId f);

  /// Cuts the next ear off and returns it, or nothing once three nodes are left or no corner can be cut
  /// without joining a vertex to itself (the remainder visits a vertex more than once).
  std::optional<Ear> cut();

  /// A node of what is left: the remainder, `remaining()` nodes long, starts there (for a triangle, the cut
  /// ears and this remainder make the face's n - 2 triangles).
  std::uint32_t rest() const { return at_; }
  std::uint32_t remaining() const { return remaining_; }
  /// The node after `node` in what is left.
  std::uint32_t next(std::uint32_t node) const { return next_[node]; }

 private:
  double turn(std::uint32_t i) const;
  bool cuttable(std::uint32_t i) const { return vertex_[prev_[i]] != vertex_[next_[i]]; }
  int neighbours_left_cuttable(std::uint32_t i) const;
  bool is_ear(std::uint32_t i) const;
  std::uint32_t next_tip();

  std::vector<VertexId> vertex_;
  std::vector<glm::dvec2> point_;
  std::vector<std::uint32_t> prev_, next_;
  std::vector<char> ear_;  // whether each node is an ear; kept up to date for the neighbours of each cut
  std::uint32_t remaining_ = 0;
  std::uint32_t at_ = 0;
};

}  // namespace dlfl::detail
