#pragma once
// Direct assembly of a DLFL when a scheme knows its output connectivity in closed form: for every corner, its
// vertex and its twin (the corner across its outgoing edge). No hashing, no search: O(size) writes. This is
// how the classic schemes (Catmull-Clark, Doo-Sabin, Loop, sqrt(3), dual) reach their speed; the honeycomb is
// built with the Euler operators instead, as its paper prescribes.

#include <cstdint>
#include <glm/vec3.hpp>
#include <span>
#include <vector>

#include <dlfl/mesh.h>

namespace dlfl {

/// Assembles a closed mesh. Face f owns the corners `offset(f) .. offset(f+1)-1`, in order around the face;
/// the caller gives each corner's vertex and twin, and each vertex's position. Handles are the indices used
/// here: vertex i is VertexId(i), face f is FaceId(f), corner k is CornerId(k). Edges are numbered in order
/// of their smaller corner, which is the edge's side 0.
///
/// The caller is trusted: `finish()` checks only that twins pair up and that every vertex has a corner
/// (cheap); that twins run along one edge in opposite directions is left to `validate`, which the tests of
/// every scheme run. Not for general input (use `build_mesh` for polygon soups).
class MeshAssembler {
 public:
  /// Faces of any sizes: `offsets` has one entry per face plus a final one equal to the number of corners.
  MeshAssembler(std::size_t num_vertices, std::span<const std::uint32_t> offsets);
  /// `num_faces` faces of `face_size` corners each.
  MeshAssembler(std::size_t num_vertices, std::size_t num_faces, std::uint32_t face_size);

  /// The most vertices, faces or corners an assembled mesh may have: every index and every count stays
  /// below the invalid handle 2^32 - 1.
  static constexpr std::size_t max_count = 0xFFFFFFFEu;
  /// Throws InvalidArgument naming the count if one exceeds `max_count`. Both constructors call it before
  /// they allocate anything; a count that does not even fit std::size_t is refused by them the same way.
  static void check_counts(std::size_t num_vertices, std::size_t num_faces, std::size_t num_corners);

  std::size_t num_vertices() const { return mesh_.positions_.size(); }
  std::size_t num_faces() const { return mesh_.faces_.size(); }
  std::size_t num_corners() const { return mesh_.corners_.size(); }

  void set_position(std::uint32_t v, const glm::dvec3& p) { mesh_.positions_[v] = p; }
  /// Corner k sits at vertex `v`; its outgoing edge is shared with corner `twin` (which must name k back).
  void set_corner(std::uint32_t k, std::uint32_t v, std::uint32_t twin) {
    mesh_.corners_[k].vertex = VertexId(v);
    twin_[k] = twin;
  }
  void set_hole(std::uint32_t f, bool hole) {
    // Counted here, so that finish() needs no pass over the faces for it.
    hole_faces_ += std::size_t(hole) - std::size_t(mesh_.faces_[f].hole);
    mesh_.faces_[f].hole = hole;
  }

  /// Links faces, creates edges and vertex anchors, and returns the mesh. Throws InvalidArgument if a twin
  /// does not name its corner back or a vertex has no corner.
  Mesh finish();

 private:
  // Checks the counts and sizes every array (twins unset, vertices without a corner).
  void allocate(std::size_t num_vertices, std::size_t num_faces, std::size_t num_corners);
  // Face f owns the corners begin .. end-1, linked in that order. Inline: it runs for every face.
  void set_face(std::uint32_t f, std::uint32_t begin, std::uint32_t end) {
    mesh_.faces_[f] = {CornerId(begin), end - begin, true, false};
    for (std::uint32_t k = begin; k < end; ++k) {
      auto& c = mesh_.corners_[k];
      c.face = FaceId(f);
      c.next = CornerId(k + 1 == end ? begin : k + 1);
      c.prev = CornerId(k == begin ? end - 1 : k - 1);
    }
  }

  Mesh mesh_;
  detail::LargeVector<std::uint32_t> twin_;
  std::size_t hole_faces_ = 0;
};

}  // namespace dlfl
