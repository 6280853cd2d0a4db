#pragma once
// Getting around a mesh beyond the corner circulators of mesh.h: the vertices and faces around a vertex or a
// face, the edge between two vertices, the corner of a vertex in a face, boundaries, and the surface faces
// (holes left out). Ranges are light views, O(1) per step, read in a for loop:
//
//   for (VertexId w : neighbours(mesh, v)) ...   // around v, in the order of mesh.corners(v)
//   for (FaceId g : neighbours(mesh, f)) ...     // across each edge of f
//   for (VertexId u : vertices(mesh, f)) ...     // along f, from its first corner
//   for (FaceId g : faces(mesh, v)) ...          // around v
//
// Like the element accessors, the ranges do not check their argument (it must be live); the functions that
// answer a question (`find_edge`, `corner_in_face`, `is_boundary`) throw InvalidArgument for a removed one.
// Several items of a range may be the same element: a 2-gon joins two vertices twice, a face may visit a
// vertex more than once or lie on both sides of an edge.

#include <cstddef>
#include <utility>

#include <dlfl/detail/forward_iterator.h>
#include <dlfl/mesh.h>

namespace dlfl {

/// The corners of a cycle (see `CornerCycle`), each shown as `Map::of(mesh, corner)`.
template <class Advance, class Map>
class MappedCorners {
  // What the range gives per corner: a VertexId, EdgeId or FaceId.
  using Value = decltype(Map::of(std::declval<const Mesh&>(), CornerId()));

 public:
  class iterator : public detail::ForwardIterator<iterator, Value> {
   public:
    iterator() = default;
    /// At the corner `at` of the cycle.
    iterator(const Mesh* mesh, typename CornerCycle<Advance>::iterator at) : mesh_(mesh), at_(at) {}
    /// The element of the corner.
    Value operator*() const { return Map::of(*mesh_, *at_); }
    /// The same place in the cycle.
    bool operator==(const iterator& o) const { return at_ == o.at_; }

   private:
    friend detail::ForwardIterator<iterator, Value>;
    void advance() { ++at_; }
    const Mesh* mesh_ = nullptr;
    typename CornerCycle<Advance>::iterator at_;
  };
  /// The cycle from `first`; empty for an invalid `first`.
  MappedCorners(const Mesh& mesh, CornerId first) : mesh_(&mesh), cycle_(&mesh, first) {}
  iterator begin() const { return iterator(mesh_, cycle_.begin()); }
  iterator end() const { return iterator(mesh_, cycle_.end()); }

 private:
  const Mesh* mesh_;
  CornerCycle<Advance> cycle_;
};

namespace detail {
struct VertexOfCorner {
  static VertexId of(const Mesh& mesh, CornerId c) { return mesh.vertex(c); }
};
struct FaceOfCorner {
  static FaceId of(const Mesh& mesh, CornerId c) { return mesh.face(c); }
};
struct EdgeOfCorner {
  static EdgeId of(const Mesh& mesh, CornerId c) { return mesh.edge(c); }
};
struct VertexAcross {  // the far end of the corner's edge
  static VertexId of(const Mesh& mesh, CornerId c) { return mesh.vertex(mesh.next(c)); }
};
struct FaceAcross {  // the face on the other side of the corner's edge
  static FaceId of(const Mesh& mesh, CornerId c) { return mesh.face(mesh.opposite(c)); }
};
// Where a range over the edges of a vertex or face starts: nowhere for a point sphere, which has none.
inline CornerId first_with_edge(const Mesh& mesh, CornerId c) {
  return mesh.edge(c).valid() ? c : CornerId();
}
}  // namespace detail

/// The vertices joined to v by an edge, one per edge, in the order of `mesh.corners(v)` (turning clockwise
/// seen from outside). Empty for a point sphere.
inline MappedCorners<detail::AroundVertex, detail::VertexAcross> neighbours(const Mesh& mesh, VertexId v) {
  return {mesh, detail::first_with_edge(mesh, mesh.corner(v))};
}

/// The edges at v, in the order of `neighbours(mesh, v)`. Empty for a point sphere.
inline MappedCorners<detail::AroundVertex, detail::EdgeOfCorner> edges(const Mesh& mesh, VertexId v) {
  return {mesh, detail::first_with_edge(mesh, mesh.corner(v))};
}

/// The faces around v, one per corner of v, in the order of `mesh.corners(v)`. A point sphere has its one
/// face.
inline MappedCorners<detail::AroundVertex, detail::FaceOfCorner> faces(const Mesh& mesh, VertexId v) {
  return {mesh, mesh.corner(v)};
}

/// The vertices of f, one per corner, counter-clockwise seen from outside from its first corner.
inline MappedCorners<detail::AlongFace, detail::VertexOfCorner> vertices(const Mesh& mesh, FaceId f) {
  return {mesh, mesh.first_corner(f)};
}

/// The edges of f, in the order of `vertices(mesh, f)` (edge i runs from vertex i to vertex i+1). Empty for
/// a point sphere's face.
inline MappedCorners<detail::AlongFace, detail::EdgeOfCorner> edges(const Mesh& mesh, FaceId f) {
  return {mesh, detail::first_with_edge(mesh, mesh.first_corner(f))};
}

/// The faces across the edges of f, in the order of `edges(mesh, f)`. Empty for a point sphere's face.
inline MappedCorners<detail::AlongFace, detail::FaceAcross> neighbours(const Mesh& mesh, FaceId f) {
  return {mesh, detail::first_with_edge(mesh, mesh.first_corner(f))};
}

/// An edge between u and v, or an invalid EdgeId if there is none (with two, as in a 2-gon, the first around
/// u). O(valence of u). Throws InvalidArgument for a removed vertex.
EdgeId find_edge(const Mesh& mesh, VertexId u, VertexId v);

/// The corner of vertex v in face f, or an invalid CornerId if f does not visit v (if it visits v more than
/// once, the first around v). O(valence of v). Throws InvalidArgument for a removed vertex or face.
CornerId corner_in_face(const Mesh& mesh, VertexId v, FaceId f);

/// True if a hole face is around v (v is on the boundary of an open mesh, or inside a hole). O(valence).
/// Throws InvalidArgument for a removed vertex.
bool is_boundary(const Mesh& mesh, VertexId v);

/// True if a hole face is on either side of e. Throws InvalidArgument for a removed edge.
bool is_boundary(const Mesh& mesh, EdgeId e);

namespace detail {
struct IsSurfaceFace {
  static bool keep(const Mesh& mesh, FaceId f) { return mesh.is_alive(f) && !mesh.is_hole(f); }
};
}  // namespace detail

/// The live faces that are not holes, in increasing handle order; `mesh.num_surface_faces()` counts them.
class SurfaceFaces : public detail::FilteredHandles<FaceId, detail::IsSurfaceFace> {
 public:
  /// The surface faces of `mesh`.
  explicit SurfaceFaces(const Mesh& mesh) : FilteredHandles(&mesh, mesh.face_capacity()) {}
};

/// The surface faces of a mesh (see `SurfaceFaces`).
inline SurfaceFaces surface_faces(const Mesh& mesh) { return SurfaceFaces(mesh); }

}  // namespace dlfl
