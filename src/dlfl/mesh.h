#pragma once
// The Doubly Linked Face List (DLFL): a closed, orientable 2-manifold mesh stored as faces that are circular
// doubly linked lists of corners. See docs/kernel.md for the model, the handle rules and the operator
// conventions.

#include <array>
#include <cstddef>
#include <cstdint>
#include <glm/vec3.hpp>
#include <memory>
#include <optional>
#include <string_view>
#include <vector>

#include <dlfl/attribute_types.h>
#include <dlfl/attributes.h>
#include <dlfl/compact_map.h>
#include <dlfl/detail/attribute_set.h>
#include <dlfl/detail/filtered_handles.h>
#include <dlfl/detail/forward_iterator.h>
#include <dlfl/detail/large_allocator.h>
#include <dlfl/detail/mesh_listeners.h>
#include <dlfl/handles.h>

namespace dlfl {

namespace detail {
/// Handles of removed elements that an operator brings back instead of appending new ones, plus "anchors" (a
/// face's first corner, a vertex's representative corner) to set when it finishes. This is how the inverse of
/// an operator restores a mesh with the very same handles; every operator returns a `Step` whose `reuse` is
/// filled in that way. Unset (invalid) fields mean "append new elements" and "no anchor to set". Internal to
/// `Mesh::apply`: the public operators always append.
struct Reuse {
  /// Corners to bring back, in the order the operator documents.
  std::array<CornerId, 2> corners{};
  EdgeId edge{};
  FaceId face{};
  VertexId vertex{};
  /// After the operator: `first_corner(face_anchors[i].face) = face_anchors[i].corner`.
  struct FaceAnchor {
    FaceId face{};
    CornerId corner{};
  };
  /// After the operator: `corner(vertex_anchors[i].vertex) = vertex_anchors[i].corner`.
  struct VertexAnchor {
    VertexId vertex{};
    CornerId corner{};
  };
  std::array<FaceAnchor, 2> face_anchors{};
  std::array<VertexAnchor, 2> vertex_anchors{};
};

/// "Append new elements, set no anchor": what the public operators pass.
inline constexpr Reuse no_reuse{};

/// How the two corner circulators step (see `CornerCycle`).
struct AlongFace;
struct AroundVertex;
}  // namespace detail

/// One Euler operator with its arguments, as a value. `Mesh::apply` runs it and returns the exact inverse.
struct Step {
  enum class Kind : std::uint8_t {
    create_vertex,     ///< uses position
    delete_vertex,     ///< uses vertex
    insert_edge,       ///< uses corner1, corner2
    delete_edge,       ///< uses edge
    subdivide_edge,    ///< uses edge, position
    unsubdivide_edge,  ///< uses vertex
    set_position,      ///< uses vertex, position
    set_hole,          ///< uses face, hole
  };
  Kind kind = Kind::create_vertex;
  bool hole = false;  // set_hole only; beside `kind`, where it takes no room of its own
  VertexId vertex{};
  EdgeId edge{};
  FaceId face{};
  CornerId corner1{};
  CornerId corner2{};
  glm::dvec3 position{0.0};
  detail::Reuse reuse{};
};

/// What `insert_edge` did. `split()` tells which of the two cases happened.
struct InsertEdgeResult {
  EdgeId edge;          ///< the new edge; its side 0 starts at vertex(c1), its side 1 at vertex(c2)
  FaceId created_face;  ///< split: the new face (the smaller part); invalid on a merge
  FaceId removed_face;  ///< merge: the face that was absorbed (now removed); invalid on a split
  Step inverse;         ///< applying this restores the mesh exactly
  bool split() const { return created_face.valid(); }
};

/// What `delete_edge` did.
struct DeleteEdgeResult {
  FaceId created_face;  ///< the edge had the same face on both sides: the new face (the smaller part)
  FaceId removed_face;  ///< the edge separated two faces: the one that was absorbed
  Step inverse;         ///< applying this restores the mesh exactly
};

template <class Advance>
class CornerCycle;
template <class H, class T>
class MeshData;

/// A closed orientable 2-manifold in DLFL form.
///
/// Storage is contiguous arrays addressed by 32-bit handles. Removing an element leaves a tombstone: handles
/// of live elements never change and are never reused until `compact()`. New elements are appended in a fixed
/// order, so the same operations always give the same handles.
///
/// Element accessors (`vertex(c)`, `next(c)`, ...) do not check their argument: it must be a live handle (see
/// `is_alive`). Every operator checks its preconditions and throws `InvalidArgument` or `TopologyError`,
/// leaving the mesh unchanged.
///
/// Named attributes (`add_vertex_attribute` and friends) and attached containers (`MeshData`, see
/// dlfl/mesh_data.h) hold values per element; see docs/kernel.md for how they follow the operators.
class Mesh {
 public:
  Mesh() = default;
  /// Copies every element and attribute. Containers attached to `other` are not attached to the copy.
  Mesh(const Mesh& other) = default;
  /// As the copy constructor; containers attached to this mesh's old data detach.
  Mesh& operator=(const Mesh& other) = default;
  /// Takes the data, attributes and attached containers of `other`, which is left empty.
  Mesh(Mesh&& other) noexcept : Mesh() { *this = std::move(other); }
  /// As the move constructor; containers attached to this mesh's old data detach.
  Mesh& operator=(Mesh&& other) noexcept;

  // ---- sizes
  // -------------------------------------------------------------------------------------------------

  std::size_t num_vertices() const { return live_vertices_; }
  std::size_t num_edges() const { return live_edges_; }
  /// Every live face: surface faces, hole faces and the faces of point spheres alike.
  std::size_t num_faces() const { return live_faces_; }
  /// The live faces flagged as holes (the boundary loops of an open mesh, see `is_hole`).
  std::size_t num_hole_faces() const { return live_hole_faces_; }
  /// The live faces that are not holes (point-sphere faces included): the faces a polygon file would get,
  /// point spheres aside. `surface_faces(mesh)` (dlfl/navigation.h) iterates them.
  std::size_t num_surface_faces() const { return live_faces_ - live_hole_faces_; }
  std::size_t num_corners() const { return live_corners_; }
  bool empty() const { return live_vertices_ == 0; }

  /// One past the largest handle index ever assigned (live or removed), per element type.
  std::uint32_t vertex_capacity() const { return static_cast<std::uint32_t>(vertex_corner_.size()); }
  std::uint32_t edge_capacity() const { return static_cast<std::uint32_t>(edges_.size()); }
  std::uint32_t face_capacity() const { return static_cast<std::uint32_t>(faces_.size()); }
  std::uint32_t corner_capacity() const { return static_cast<std::uint32_t>(corners_.size()); }
  /// The capacity of one element kind.
  std::uint32_t capacity(ElementKind kind) const;

  /// Reserve room for this many elements of each type in total (live plus removed), to avoid regrowth; the
  /// named attributes reserve as much.
  void reserve(std::size_t vertices, std::size_t edges, std::size_t faces, std::size_t corners);

  // ---- liveness
  // ----------------------------------------------------------------------------------------------

  /// True for a handle that was assigned and whose element has not been removed. Safe on any handle.
  bool is_alive(VertexId v) const {
    return v.index() < vertex_capacity() && vertex_corner_[v.index()].valid();
  }
  bool is_alive(EdgeId e) const { return e.index() < edge_capacity() && edges_[e.index()].corner[0].valid(); }
  bool is_alive(FaceId f) const { return f.index() < face_capacity() && faces_[f.index()].alive; }
  bool is_alive(CornerId c) const {
    return c.index() < corner_capacity() && corners_[c.index()].vertex.valid();
  }
  /// The same for the element of one kind at slot `index`, for code that names elements by kind (logs,
  /// bindings). Safe on any index.
  bool is_alive(ElementKind kind, std::uint32_t index) const;

  // ---- element data
  // ------------------------------------------------------------------------------------------

  const glm::dvec3& position(VertexId v) const { return positions_[v.index()]; }
  /// A representative corner of the vertex (its only corner for a point sphere). Rotation starts here.
  CornerId corner(VertexId v) const { return vertex_corner_[v.index()]; }

  VertexId vertex(CornerId c) const { return corners_[c.index()].vertex; }
  FaceId face(CornerId c) const { return corners_[c.index()].face; }
  /// The next corner along the face (counter-clockwise seen from outside).
  CornerId next(CornerId c) const { return corners_[c.index()].next; }
  CornerId prev(CornerId c) const { return corners_[c.index()].prev; }
  /// The edge that leaves the corner along its face, from vertex(c) to vertex(next(c)). Invalid for the
  /// corner of a point sphere.
  EdgeId edge(CornerId c) const { return corners_[c.index()].edge; }

  /// The corner of edge `e` on side 0 or 1: the corner where the edge starts on that side. Side 0 runs from
  /// vertex A to vertex B, side 1 from B to A.
  CornerId corner(EdgeId e, int side) const { return edges_[e.index()].corner[side]; }

  /// The face's first corner: iteration around the face starts here.
  CornerId first_corner(FaceId f) const { return faces_[f.index()].corner; }
  /// Number of corners of the face (1 for a point sphere, 2 for a 2-gon).
  std::uint32_t size(FaceId f) const { return faces_[f.index()].size; }
  /// Hole faces stand for the boundary loops of an open mesh; writers omit them.
  bool is_hole(FaceId f) const { return faces_[f.index()].hole; }

  // ---- navigation, O(1) per step
  // ----------------------------------------------------------------------------

  /// The corner on the other side of edge(c): it starts at vertex(next(c)) and ends at vertex(c).
  CornerId opposite(CornerId c) const {
    const auto& e = edges_[edge(c).index()];
    return e.corner[0] == c ? e.corner[1] : e.corner[0];
  }
  /// The next corner around vertex(c), turning clockwise seen from outside (towards the face across edge(c)).
  CornerId next_around_vertex(CornerId c) const { return edge(c).valid() ? next(opposite(c)) : c; }
  /// The previous corner around vertex(c), turning counter-clockwise (towards the face across edge(prev(c))).
  CornerId prev_around_vertex(CornerId c) const { return edge(c).valid() ? opposite(prev(c)) : c; }

  /// The two end vertices of an edge: `from(e)` = vertex(corner(e,0)), `to(e)` = vertex(corner(e,1)).
  VertexId from(EdgeId e) const { return vertex(corner(e, 0)); }
  VertexId to(EdgeId e) const { return vertex(corner(e, 1)); }
  /// The faces on side 0 and side 1 of an edge (equal when the edge has the same face on both sides).
  FaceId face(EdgeId e, int side) const { return face(corner(e, side)); }

  /// Number of edges at the vertex, counting an edge twice if both its ends are here (never, as self-loops
  /// are not allowed). 0 for a point sphere. O(valence).
  std::uint32_t valence(VertexId v) const;
  /// A vertex with no edge: its only face has one corner.
  bool is_point_sphere(VertexId v) const { return !edge(corner(v)).valid(); }

  // ---- iteration
  // ---------------------------------------------------------------------------------------------

  template <class H>
  class LiveRange;
  using FaceCorners = CornerCycle<detail::AlongFace>;
  using VertexCorners = CornerCycle<detail::AroundVertex>;

  /// Live handles in increasing order.
  LiveRange<VertexId> vertices() const;
  LiveRange<EdgeId> edges() const;
  LiveRange<FaceId> faces() const;
  LiveRange<CornerId> corners() const;
  /// The live handles of one kind: `elements<FaceId>()` is `faces()`.
  template <class H>
  LiveRange<H> elements() const {
    return {this, capacity(element_kind_v<H>)};
  }
  /// The corners of a face, from its first corner along `next`.
  FaceCorners corners(FaceId f) const;
  /// The corners at a vertex, from its representative corner along `next_around_vertex`.
  VertexCorners corners(VertexId v) const;
  // More in dlfl/navigation.h: neighbours, the vertices and faces around a face or a vertex, find_edge.

  // ---- Euler operators
  // ---------------------------------------------------------------------------------------

  /// CREATEVERTEX (MVFS): a new point sphere, one vertex with one face of one corner and no edge. The vertex,
  /// face and corner are appended, in that order. Throws InvalidArgument on a non-finite position.
  VertexId create_vertex(const glm::dvec3& position) { return create_vertex(position, detail::no_reuse); }

  /// Inverse of `create_vertex`: removes a point sphere (vertex, face, corner). Throws TopologyError if the
  /// vertex has edges.
  void delete_vertex(VertexId v) { delete_vertex(v, detail::no_reuse); }

  /// INSERTEDGE: a new edge from vertex(c1) to vertex(c2), drawn inside the angle of corner c1 and the angle
  /// of corner c2.
  ///
  /// - Same face: the face is split in two. The part that contains c1 is c1, next(c1), ..., up to the corner
  ///   before c2, plus a new corner at vertex(c2); the other part contains c2.
  /// - Different faces (a point sphere counts as a face): the two faces become one, and the topology changes
  ///   (two components join, or the genus grows by one).
  ///
  /// Conventions that schemes rely on:
  /// - c1 and c2 stay at their vertices with their outgoing edges. The new edge leaves vertex(c1) from a new
  ///   corner n1 = corner(e,0), placed just before c2 along the face; and vertex(c2) from a new corner
  ///   n2 = corner(e,1), placed just before c1. A point sphere's corner is not duplicated: if c1 (c2) is the
  ///   corner of a point sphere, n1 = c1 (n2 = c2).
  /// - Split: the larger part keeps the face handle, the smaller part gets a new face (on a tie the part of
  /// c1
  ///   keeps it). The new face copies the hole flag. Merge: the larger face survives (on a tie the face of
  ///   c1) and the other is removed. A face's first corner stays unless it moved to the other part; then it
  ///   becomes c1 or c2, whichever lies in the face.
  /// - New handles are appended in the order n1, n2, edge, face.
  ///
  /// Cost O(1) plus the size of the smaller face involved. Throws InvalidArgument for a removed corner, and
  /// TopologyError if both corners are at the same vertex (a self-loop).
  InsertEdgeResult insert_edge(CornerId c1, CornerId c2) { return insert_edge(c1, c2, detail::no_reuse); }

  /// DELETEEDGE, the inverse of `insert_edge`. If the edge has different faces on its two sides they merge
  /// into one (the larger survives; on a tie face(corner(e,1))). If it has the same face on both sides that
  /// face splits in two (the larger part keeps the handle; on a tie the part continuing at from(e)), which
  /// may separate a component or lower the genus; an end vertex left with no edge becomes a point sphere,
  /// keeping its corner. Cost O(1) plus the size of the smaller face involved.
  DeleteEdgeResult delete_edge(EdgeId e) { return delete_edge(e, detail::no_reuse); }

  /// Puts a new vertex at `position` on edge e. Edge e keeps running from from(e) to the new vertex, a new
  /// edge runs from the new vertex to the old to(e); both faces grow by one corner. Appends, in order: the
  /// vertex, corner on side 0, corner on side 1, edge. O(1). Returns the new vertex.
  VertexId subdivide_edge(EdgeId e, const glm::dvec3& position) {
    return subdivide_edge(e, position, detail::no_reuse);
  }

  /// Inverse of `subdivide_edge`: removes a vertex of valence 2 and joins its two edges into one. The two
  /// edges must continue each other the way `subdivide_edge` leaves them: one arrives at v on its side 0 (it
  /// is kept, now running to the far end of the other), the other leaves v on its side 0 (it is removed).
  /// Throws TopologyError otherwise, or if both neighbours are the same vertex (the result would be a
  /// self-loop).
  void unsubdivide_edge(VertexId v) { unsubdivide_edge(v, detail::no_reuse); }

  /// Moves a vertex. Throws InvalidArgument on a non-finite position.
  void set_position(VertexId v, const glm::dvec3& position);

  /// Runs one operator given as a value and returns its exact inverse (`apply(apply(s))` restores the mesh).
  /// The step's `reuse` brings back removed elements under their old handles, which is how inverses restore
  /// a mesh exactly; named attributes and attached containers are not touched (a revived element finds the
  /// values it had).
  Step apply(const Step& step);

  // ---- anchors and flags (no effect on topology)
  // -------------------------------------------------------------

  /// Makes c the corner where iteration around its face starts.
  void set_first_corner(FaceId f, CornerId c);
  /// Makes c the vertex's representative corner (where rotation starts).
  void set_vertex_corner(VertexId v, CornerId c);
  /// Flags a face as a hole (a boundary loop) or as a surface face. Throws InvalidArgument for a removed
  /// face.
  void set_hole(FaceId f, bool hole);

  // ---- named attributes
  // --------------------------------------------------------------------------------------
  //
  // Values of type bool, int, double or glm::dvec3 per vertex, edge, face or corner, under a name (unique per
  // element kind). Every element reads the attribute's default until given a value; storage grows only when
  // a value is written, so the operators never pay for attributes. A removed element keeps its value, so an
  // inverse step that brings it back brings the value back. `compact()` moves values with their elements,
  // copying a mesh copies them, `operator==` and `mesh_hash` compare them. Schemes build new meshes without
  // the input's attributes. Reading (const access) is safe from many threads; writing is not.

  /// Adds an attribute of values T on the elements H (VertexId, EdgeId, FaceId or CornerId) and returns it.
  /// If one of that name and kind exists with type T it is returned unchanged (default included). Throws
  /// InvalidArgument for an empty name or if the name exists with another type.
  template <class H, class T>
  Attribute<H, T> add_attribute(std::string_view name, const T& default_value = T());
  /// The attribute of that name on the elements H. Throws InvalidArgument naming the name and type if there
  /// is none or it has another type.
  template <class H, class T>
  Attribute<H, T> attribute(std::string_view name);
  template <class H, class T>
  ConstAttribute<H, T> attribute(std::string_view name) const;
  /// As `attribute`, but `std::nullopt` if there is none; still throws if it has another type.
  template <class H, class T>
  std::optional<Attribute<H, T>> find_attribute(std::string_view name);
  template <class H, class T>
  std::optional<ConstAttribute<H, T>> find_attribute(std::string_view name) const;
  /// True if the elements H have an attribute of that name (of any type).
  template <class H>
  bool has_attribute(std::string_view name) const {
    return has_attribute(element_kind_v<H>, name);
  }
  /// Removes the attribute (its handles dangle). Throws InvalidArgument if there is none.
  template <class H>
  void remove_attribute(std::string_view name) {
    remove_attribute(element_kind_v<H>, name);
  }

  // The same per element kind, KIND one of vertex, edge, face, corner: add_KIND_attribute<T>(name, default),
  // KIND_attribute<T>(name) (const and not), has_KIND_attribute(name), remove_KIND_attribute(name), as in
  // `auto w = mesh.add_vertex_attribute<double>("weight", 0.0); w[v] = 2;`. Written once, for every kind.
#define DLFL_ATTRIBUTES_OF_KIND(KIND, H)                                                        \
  template <class T>                                                                            \
  Attribute<H, T> add_##KIND##_attribute(std::string_view name, const T& default_value = T()) { \
    return add_attribute<H, T>(name, default_value);                                            \
  }                                                                                             \
  template <class T>                                                                            \
  Attribute<H, T> KIND##_attribute(std::string_view name) {                                     \
    return attribute<H, T>(name);                                                               \
  }                                                                                             \
  template <class T>                                                                            \
  ConstAttribute<H, T> KIND##_attribute(std::string_view name) const {                          \
    return attribute<H, T>(name);                                                               \
  }                                                                                             \
  bool has_##KIND##_attribute(std::string_view name) const {                                    \
    return has_attribute(element_kind_v<H>, name);                                              \
  }                                                                                             \
  void remove_##KIND##_attribute(std::string_view name) { remove_attribute(element_kind_v<H>, name); }
  DLFL_ATTRIBUTES_OF_KIND(vertex, VertexId)
  DLFL_ATTRIBUTES_OF_KIND(edge, EdgeId)
  DLFL_ATTRIBUTES_OF_KIND(face, FaceId)
  DLFL_ATTRIBUTES_OF_KIND(corner, CornerId)
#undef DLFL_ATTRIBUTES_OF_KIND

  // Type-erased access, for code that handles attributes it does not know (undo, file formats). Element
  // indices are handle indices: any slot below `capacity(kind)`, live or removed.

  /// Every attribute, sorted by (kind, name).
  std::vector<AttributeInfo> attributes() const;
  /// True if elements of `kind` have an attribute of that name.
  bool has_attribute(ElementKind kind, std::string_view name) const;
  /// Adds an attribute whose type is that of `default_value`. Nothing happens if it exists with that type;
  /// throws InvalidArgument for an empty name or if it exists with another type.
  void add_attribute(ElementKind kind, std::string_view name, const AttributeValue& default_value);
  /// Throws InvalidArgument if there is no such attribute.
  void remove_attribute(ElementKind kind, std::string_view name);
  /// The value of slot `index`. Throws InvalidArgument for a missing attribute or an index not below
  /// `capacity(kind)`.
  AttributeValue attribute_value(ElementKind kind, std::string_view name, std::uint32_t index) const;
  /// Sets the value of slot `index`. Throws InvalidArgument for a missing attribute, an index not below
  /// `capacity(kind)`, or a value of another type than the attribute's.
  void set_attribute_value(ElementKind kind, std::string_view name, std::uint32_t index,
                           const AttributeValue& value);

  // ---- maintenance
  // -------------------------------------------------------------------------------------------

  /// Old-to-new handle maps returned by `compact` (invalid for removed elements).
  using CompactMap = dlfl::CompactMap;
  /// Drops removed elements and renumbers the live ones densely, keeping their relative order. Named
  /// attributes and attached containers move their values along. O(size).
  CompactMap compact();

  /// Element-by-element equality: the same live handles, and for each the same data (positions bit for bit,
  /// links, anchors, face sizes and hole flags); the same attributes (names, kinds, types and defaults) with
  /// the same values on live elements (bit for bit, any NaN equal to any NaN). Removed elements are ignored.
  friend bool operator==(const Mesh& a, const Mesh& b);

 private:
  struct CornerRecord {
    VertexId vertex;  // invalid for a removed corner
    FaceId face;
    CornerId next;
    CornerId prev;
    EdgeId edge;
  };
  struct EdgeRecord {
    std::array<CornerId, 2> corner;  // corner[0] invalid for a removed edge
  };
  struct FaceRecord {
    CornerId corner;  // kept while removed, so that bringing the face back restores it
    std::uint32_t size = 0;
    bool alive = false;
    bool hole = false;
  };

  friend class MeshBuilder;
  friend struct MeshArrays;
  friend class MeshAssembler;
  friend struct MeshTestAccess;  // lets the test suite corrupt a mesh to prove the validator catches it
  template <class, class>
  friend class MeshData;

  // The operators with the handles to bring back (see detail::Reuse); `apply` runs inverses through these.
  VertexId create_vertex(const glm::dvec3& position, const detail::Reuse& reuse);
  void delete_vertex(VertexId v, const detail::Reuse& reuse);
  InsertEdgeResult insert_edge(CornerId c1, CornerId c2, const detail::Reuse& reuse);
  DeleteEdgeResult delete_edge(EdgeId e, const detail::Reuse& reuse);
  VertexId subdivide_edge(EdgeId e, const glm::dvec3& position, const detail::Reuse& reuse);
  void unsubdivide_edge(VertexId v, const detail::Reuse& reuse);

  // Precondition checks: inline fast path, out-of-line throw.
  template <class H>
  void require(H h, const char* op) const {
    if (!is_alive(h)) [[unlikely]]
      missing(h, op);
  }
  [[noreturn]] static void missing(VertexId v, const char* op);
  [[noreturn]] static void missing(EdgeId e, const char* op);
  [[noreturn]] static void missing(FaceId f, const char* op);
  [[noreturn]] static void missing(CornerId c, const char* op);

  // Allocation: append, or bring back the removed element a Reuse names. Inline: they are on every operator's
  // hot path (a honeycomb step runs millions of them).
  CornerId new_corner(CornerId reuse) {
    ++live_corners_;
    if (reuse.valid()) return reuse;
    corners_.emplace_back();
    return CornerId(static_cast<std::uint32_t>(corners_.size() - 1));
  }
  EdgeId new_edge(EdgeId reuse) {
    ++live_edges_;
    if (reuse.valid()) return reuse;
    edges_.emplace_back();
    return EdgeId(static_cast<std::uint32_t>(edges_.size() - 1));
  }
  // A revived face keeps its hole flag; a new one gets `hole`.
  FaceId new_face(FaceId reuse, bool hole) {
    ++live_faces_;
    if (reuse.valid()) {
      faces_[reuse.index()].alive = true;
      live_hole_faces_ += faces_[reuse.index()].hole;
      return reuse;
    }
    faces_.push_back({CornerId(), 0, true, hole});
    live_hole_faces_ += hole;
    return FaceId(static_cast<std::uint32_t>(faces_.size() - 1));
  }
  VertexId new_vertex(VertexId reuse) {
    ++live_vertices_;
    if (reuse.valid()) return reuse;
    positions_.emplace_back(0.0);
    vertex_corner_.emplace_back();
    return VertexId(static_cast<std::uint32_t>(vertex_corner_.size() - 1));
  }
  void kill(CornerId c) {
    corners_[c.index()].vertex = VertexId();
    --live_corners_;
  }
  void kill(EdgeId e) {
    edges_[e.index()].corner[0] = CornerId();
    --live_edges_;
  }
  void kill(FaceId f) {
    faces_[f.index()].alive = false;  // corner and hole flag stay, for a later revival
    --live_faces_;
    live_hole_faces_ -= faces_[f.index()].hole;
  }
  void kill(VertexId v) {
    vertex_corner_[v.index()] = CornerId();
    --live_vertices_;
  }
  void apply_anchors(const detail::Reuse& reuse) {
    if (reuse.face_anchors[0].face.valid() || reuse.face_anchors[1].face.valid() ||
        reuse.vertex_anchors[0].vertex.valid() || reuse.vertex_anchors[1].vertex.valid()) [[unlikely]] {
      set_anchors(reuse);
    }
  }
  void set_anchors(const detail::Reuse& reuse);
  void link(CornerId a, CornerId b) {
    corners_[a.index()].next = b;
    corners_[b.index()].prev = a;
  }
  // Moves the corner cycle from `start` into face g, as a split does, telling whether it passed the corners
  // `f_anchor` and `g_anchor` (the first corners of the faces, which may have to move).
  struct MovedCycle {
    bool passed_f_anchor = false;
    bool passed_g_anchor = false;
  };
  MovedCycle move_cycle(CornerId start, FaceId g, CornerId f_anchor, CornerId g_anchor) {
    MovedCycle moved;
    CornerId c = start;
    do {
      corners_[c.index()].face = g;
      moved.passed_f_anchor |= c == f_anchor;
      moved.passed_g_anchor |= c == g_anchor;
      c = next(c);
    } while (c != start);
    return moved;
  }
  // Steps x and y along their face together until x reaches `x_stop` or y reaches `y_stop`: how a split
  // measures its two parts in O(the smaller one). `x_first` tells which got there, after `steps` steps.
  struct FirstArrival {
    std::uint32_t steps = 0;
    bool x_first = false;
  };
  FirstArrival first_arrival(CornerId x, CornerId x_stop, CornerId y, CornerId y_stop) const {
    for (std::uint32_t k = 1;; ++k) {
      x = next(x);
      y = next(y);
      if (x == x_stop) return {k, true};
      if (y == y_stop) return {k, false};
    }
  }
  // Attribute lookup shared by the typed and the type-erased API. `find_column` gives null for a missing
  // attribute and throws InvalidArgument for one of another type; `add_column` adds or returns it.
  detail::AttributeColumn* find_column(ElementKind kind, std::string_view name, AttributeType type) const;
  detail::AttributeColumn& column(ElementKind kind, std::string_view name, AttributeType type) const;
  detail::AttributeColumn& add_column(ElementKind kind, std::string_view name, const AttributeValue& value);
  static bool same_attributes(const Mesh& a, const Mesh& b);  // for operator==, once the elements agree

  // The registry of attached containers, created on first use (see detail/mesh_listeners.h).
  const std::shared_ptr<detail::MeshListeners>& listeners() const;

  detail::LargeVector<glm::dvec3> positions_;
  detail::LargeVector<CornerId> vertex_corner_;  // invalid for a removed vertex
  detail::LargeVector<CornerRecord> corners_;
  detail::LargeVector<EdgeRecord> edges_;
  detail::LargeVector<FaceRecord> faces_;
  std::size_t live_vertices_ = 0;
  std::size_t live_edges_ = 0;
  std::size_t live_faces_ = 0;
  std::size_t live_hole_faces_ = 0;
  std::size_t live_corners_ = 0;
  detail::AttributeSet attributes_;
  mutable detail::ListenerSlot listeners_;
  // (The move assignment in mesh.cpp lists every member: add new ones there too.)
};

// ---- ranges
// --------------------------------------------------------------------------------------------------

namespace detail {
struct IsAlive {
  template <class H>
  static bool keep(const Mesh& mesh, H h) {
    return mesh.is_alive(h);
  }
};
}  // namespace detail

/// The live elements of kind H, in increasing handle order.
template <class H>
class Mesh::LiveRange : public detail::FilteredHandles<H, detail::IsAlive> {
 public:
  using detail::FilteredHandles<H, detail::IsAlive>::FilteredHandles;
};

/// The corners met by stepping from a first corner until it comes round again: the corners of a face
/// (`detail::AlongFace`, along `next`) or around a vertex (`detail::AroundVertex`, along
/// `next_around_vertex`). An invalid first corner gives an empty cycle.
template <class Advance>
class CornerCycle {
 public:
  class iterator : public detail::ForwardIterator<iterator, CornerId> {
   public:
    iterator() = default;
    /// At corner `c` of the cycle from `c`; `done` makes it the end.
    iterator(const Mesh* mesh, CornerId c, bool done) : mesh_(mesh), first_(c), c_(c), done_(done) {}
    /// The corner.
    CornerId operator*() const { return c_; }
    /// Both at the end, or at the same corner.
    bool operator==(const iterator& o) const { return done_ == o.done_ && (done_ || c_ == o.c_); }

   private:
    friend detail::ForwardIterator<iterator, CornerId>;
    void advance() {
      c_ = Advance::step(*mesh_, c_);
      done_ = c_ == first_;
    }
    const Mesh* mesh_ = nullptr;
    CornerId first_, c_;
    bool done_ = true;
  };
  CornerCycle(const Mesh* mesh, CornerId first) : mesh_(mesh), first_(first) {}
  iterator begin() const { return iterator(mesh_, first_, !first_.valid()); }
  iterator end() const { return iterator(mesh_, first_, true); }

 private:
  const Mesh* mesh_;
  CornerId first_;
};

namespace detail {
struct AlongFace {
  static CornerId step(const Mesh& mesh, CornerId c) { return mesh.next(c); }
};
struct AroundVertex {
  static CornerId step(const Mesh& mesh, CornerId c) { return mesh.next_around_vertex(c); }
};
}  // namespace detail

inline Mesh::LiveRange<VertexId> Mesh::vertices() const { return {this, vertex_capacity()}; }
inline Mesh::LiveRange<EdgeId> Mesh::edges() const { return {this, edge_capacity()}; }
inline Mesh::LiveRange<FaceId> Mesh::faces() const { return {this, face_capacity()}; }
inline Mesh::LiveRange<CornerId> Mesh::corners() const { return {this, corner_capacity()}; }
inline Mesh::FaceCorners Mesh::corners(FaceId f) const { return {this, first_corner(f)}; }
inline Mesh::VertexCorners Mesh::corners(VertexId v) const { return {this, corner(v)}; }

// ---- attribute templates
// -----------------------------------------------------------------------------------------

template <class H, class T>
Attribute<H, T> Mesh::add_attribute(std::string_view name, const T& default_value) {
  static_assert(is_handle_v<H> && is_attribute_type_v<T>,
                "attributes: H a handle type, T bool/int/double/dvec3");
  return Attribute<H, T>(static_cast<detail::TypedColumn<H, T>*>(
      &add_column(element_kind_v<H>, name, AttributeValue(default_value))));
}

template <class H, class T>
Attribute<H, T> Mesh::attribute(std::string_view name) {
  static_assert(is_handle_v<H> && is_attribute_type_v<T>,
                "attributes: H a handle type, T bool/int/double/dvec3");
  return Attribute<H, T>(
      static_cast<detail::TypedColumn<H, T>*>(&column(element_kind_v<H>, name, attribute_type_v<T>)));
}

template <class H, class T>
ConstAttribute<H, T> Mesh::attribute(std::string_view name) const {
  static_assert(is_handle_v<H> && is_attribute_type_v<T>,
                "attributes: H a handle type, T bool/int/double/dvec3");
  return ConstAttribute<H, T>(
      static_cast<const detail::TypedColumn<H, T>*>(&column(element_kind_v<H>, name, attribute_type_v<T>)));
}

template <class H, class T>
std::optional<Attribute<H, T>> Mesh::find_attribute(std::string_view name) {
  static_assert(is_handle_v<H> && is_attribute_type_v<T>,
                "attributes: H a handle type, T bool/int/double/dvec3");
  auto* c = find_column(element_kind_v<H>, name, attribute_type_v<T>);
  if (!c) return std::nullopt;
  return Attribute<H, T>(static_cast<detail::TypedColumn<H, T>*>(c));
}

template <class H, class T>
std::optional<ConstAttribute<H, T>> Mesh::find_attribute(std::string_view name) const {
  static_assert(is_handle_v<H> && is_attribute_type_v<T>,
                "attributes: H a handle type, T bool/int/double/dvec3");
  const auto* c = find_column(element_kind_v<H>, name, attribute_type_v<T>);
  if (!c) return std::nullopt;
  return ConstAttribute<H, T>(static_cast<const detail::TypedColumn<H, T>*>(c));
}

}  // namespace dlfl
