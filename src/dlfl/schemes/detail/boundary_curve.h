#pragma once
// Internal to the schemes: what the curve boundary rules of Catmull-Clark, Loop and sqrt(3) share
// (BoundaryRule::curve, docs/boundaries.md): which vertices of an open mesh are on its boundary and which of
// them stay sharp, the `sharp` marks of the result, and the numbering of an output in which every boundary
// loop stays one hole face. Defined in boundary_curve.cpp.

#include <cstdint>
#include <functional>
#include <optional>
#include <span>
#include <vector>

#include <dlfl/mesh.h>
#include <dlfl/mesh_assembler.h>
#include <dlfl/schemes/boundary_rule.h>
#include <dlfl/schemes/detail/boundary_points.h>
#include <dlfl/schemes/detail/scheme_origins.h>

namespace dlfl::detail {

/// How the curve rule treats each vertex of a dense mesh (handles 0 .. count-1).
class BoundaryVertices {
 public:
  enum class Kind : std::uint8_t {
    interior,  ///< no hole corner: the scheme's interior rule
    smooth,    ///< one hole corner (so two boundary edges, on one loop), not sharp: the boundary curve's rule
    sharp,     ///< on the boundary and kept where it is
  };

  /// A boundary vertex is sharp if it is marked, if it has several hole corners (boundary loops touch
  /// there, or one loop passes twice) or, with `sharp_corners`, if it has exactly two edges.
  BoundaryVertices(const Mesh& m, const BoundaryOptions& options,
                   const std::optional<ConstAttribute<VertexId, bool>>& marks);

  Kind kind(std::uint32_t v) const { return kinds_[v]; }
  bool is_sharp(std::uint32_t v) const { return kinds_[v] == Kind::sharp; }

  /// Binary schemes (Catmull-Clark, Loop): the vertex point (vertex v of `out`) of every boundary vertex, by
  /// the cubic B-spline rule (1/8, 6/8, 1/8) along its loop for a smooth one, unmoved for a sharp one.
  void set_binary_vertex_points(const Mesh& m, MeshAssembler& out) const;

  /// The neighbours of boundary vertex vertex(c) along the loop of hole corner c: before it (vertex(prev c))
  /// and after it (vertex(next c)). At a sharp vertex, the neighbour on the other side is replaced by the
  /// reflection 2 p - q of the one q on this side, so that a chain of the loop ends there as the cubic
  /// B-spline of the chain extended by that point, which interpolates it.
  glm::dvec3 before(const Mesh& m, CornerId c) const;
  glm::dvec3 after(const Mesh& m, CornerId c) const;

 private:
  std::vector<Kind> kinds_;
};

/// The result's `sharp` marks: vertex v of `result` (the point of input vertex v of dense `m`) is marked if
/// v is, and, with `boundary` given, if `boundary` keeps it sharp. The attribute (default false) is added
/// only when `m` has one or some vertex gets a mark.
void carry_sharp_marks(const std::optional<ConstAttribute<VertexId, bool>>& marks, Mesh& result,
                       std::uint32_t num_vertices, const BoundaryVertices* boundary = nullptr);

/// The numbering of an output built from dense `m` in which every surface corner becomes one polygon, every
/// surface face may add one, and every hole face stays one hole face. Output faces, in this order: the
/// polygons of the surface corners in corner order, `corner_sides` corners each; those of the surface faces
/// in face order, `face_sides` each (none when 0); the hole faces in face order, hole h with
/// `hole_sides(h)` output corners for each of its corners, run by run from its first corner. Output
/// corners are numbered face by face.
class OpenLayout {
 public:
  OpenLayout(const Mesh& m, std::uint32_t corner_sides, std::uint32_t face_sides,
             const std::function<std::uint32_t(FaceId)>& hole_sides);

  /// The first output corner of input corner c: of its polygon for a surface corner, of its run in the hole
  /// face for a hole corner.
  std::uint32_t corner(CornerId c) const { return first_[c.index()]; }
  /// The first output corner of surface face f's polygon.
  std::uint32_t face_polygon(FaceId f) const { return face_polygons_ + face_sides_ * rank_[f.index()]; }
  /// The rank of surface face f among the surface faces (of a hole among the holes), in face order.
  std::uint32_t rank(FaceId f) const { return rank_[f.index()]; }
  /// The output face of hole face h.
  std::uint32_t hole_face(FaceId h) const { return first_hole_face_ + rank_[h.index()]; }
  std::uint32_t num_surface_faces() const { return surface_faces_; }
  /// Offsets of the output faces, for the MeshAssembler.
  std::span<const std::uint32_t> offsets() const { return offsets_; }

  /// Binary splits (an edge point per input edge): the output corner at the point of vertex(c) that runs
  /// towards the edge point of edge(c) (the first of c's polygon or of its run in a hole), and the one that
  /// runs into the point of vertex(c) from the edge point of edge(prev c) (the last of c's polygon, or the
  /// second of prev(c)'s run). The twin of leaving(c) is arriving(next(opposite(c))).
  std::uint32_t leaving(CornerId c) const { return corner(c); }
  std::uint32_t arriving(const Mesh& m, CornerId c) const {
    return m.is_hole(m.face(c)) ? corner(m.prev(c)) + 1 : corner(c) + corner_sides_ - 1;
  }
  /// Binary splits: the output corners along the halves of every edge of m, on both sides (leaving(s) at
  /// the point of vertex(s), twin of arriving(next(opposite(s))) at the edge point, vertex `edge_base` +
  /// edge). These are all the corners of the hole faces, and the outer ones of the surface polygons.
  void set_half_edge_corners(const Mesh& m, std::uint32_t edge_base, MeshAssembler& out) const;
  /// Flags the output's hole faces.
  void set_hole_flags(MeshAssembler& out) const;

  /// The origins of the output faces: surface corner polygons <- their corner, surface face polygons and
  /// hole faces <- their face.
  void face_origins(const Mesh& m, const InputHandles& in, Origins& origins) const;
  /// The origin of the edge leaving each output corner, from `of_surface(c, i)` for corner i of the polygon
  /// of surface corner c, `of_face(f, i)` for that of surface face f, and edge(c) for every output corner of
  /// hole corner c (the pieces of a boundary edge stem from it).
  std::vector<Origin> edge_origins(const Mesh& m, const InputHandles& in,
                                   const std::function<Origin(CornerId, std::uint32_t)>& of_surface,
                                   const std::function<Origin(FaceId, std::uint32_t)>& of_face) const;

 private:
  std::uint32_t corner_sides_, face_sides_;
  std::uint32_t surface_faces_ = 0, face_polygons_ = 0, first_hole_face_ = 0;
  std::vector<std::uint32_t> first_, rank_, offsets_, hole_sides_;  // hole_sides_ by hole rank
};

}  // namespace dlfl::detail
