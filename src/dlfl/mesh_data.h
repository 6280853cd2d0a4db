#pragma once
// Per-element containers: a value of any type T for each vertex, edge, face or corner of a mesh, indexed by
// handle (`data[v]`), that follow the mesh's `compact()`.
//
//   VertexData<double> weight(mesh, 1.0);  // every vertex reads 1.0
//   weight[v] = 2.5;
//   mesh.compact();                        // weight[map.vertices[v.index()]] is still 2.5
//
// Unlike named attributes (`Mesh::add_vertex_attribute`), a container belongs to its user: the mesh does not
// copy, save, hash or compare it. It is attached to the mesh's data: when the mesh is moved (or swapped), the
// container follows the moved-to mesh; a copy of the mesh starts with no containers attached; assigning to
// the mesh, or destroying it, detaches the container, which keeps its values. Operators do not touch
// containers: a new element reads the default until written, and a removed element keeps its value, so an
// inverse step that brings it back finds it again.
//
// Thread safety: attaching, copying, moving or destroying containers of one mesh (and compacting it) must not
// happen from two threads at once; the mesh keeps one unsynchronised list of them. Reading a container while
// nobody writes it is safe.

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>

#include <dlfl/detail/mesh_listeners.h>
#include <dlfl/detail/value_vector.h>
#include <dlfl/mesh.h>

namespace dlfl {

/// A value of type T per element of kind H (VertexId, EdgeId, FaceId or CornerId) of one mesh.
template <class H, class T>
class MeshData final : private detail::CompactListener {
  static_assert(is_handle_v<H>, "MeshData<H, T>: H must be VertexId, EdgeId, FaceId or CornerId");

 public:
  /// A container attached to no mesh, with no values.
  MeshData() = default;
  /// A container for the elements of `mesh`, sized by its capacity, every element reading `default_value`.
  explicit MeshData(const Mesh& mesh, const T& default_value = T()) : default_(default_value) {
    registry_ = mesh.listeners();
    mesh.listeners()->add(this);
    values_.resize(mesh.capacity(element_kind_v<H>), default_);
  }
  /// The same values, attached to the same mesh (if that mesh still lives).
  MeshData(const MeshData& other)
      : registry_(other.registry_), values_(other.values_), default_(other.default_) {
    if (auto r = registry_.lock()) r->add(this);
  }
  /// Takes over `other`'s values and attachment; `other` is left detached and empty.
  MeshData(MeshData&& other) noexcept
      : registry_(std::move(other.registry_)),
        values_(std::move(other.values_)),
        default_(std::move(other.default_)) {
    if (auto r = registry_.lock()) r->replace(&other, this);
  }
  MeshData& operator=(const MeshData& other) {
    if (this == &other) return *this;
    values_ = other.values_;
    default_ = other.default_;
    detach();
    registry_ = other.registry_;
    if (auto r = registry_.lock()) r->add(this);
    return *this;
  }
  MeshData& operator=(MeshData&& other) noexcept {
    if (this == &other) return *this;
    detach();
    values_ = std::move(other.values_);
    default_ = std::move(other.default_);
    registry_ = std::move(other.registry_);
    if (auto r = registry_.lock()) r->replace(&other, this);
    return *this;
  }
  ~MeshData() { detach(); }

  /// The value of element h, for reading and writing. If the mesh has grown past the stored values, the
  /// storage first grows to the mesh's capacity (filling the default). h must be a handle of the mesh.
  T& operator[](H h) {
    if (h.index() >= values_.size()) [[unlikely]]
      grow(h.index());
    return values_[h.index()];
  }
  /// The value of element h; the default for an element added since the storage last grew.
  const T& operator[](H h) const { return h.index() < values_.size() ? values_[h.index()] : default_; }

  /// The number of stored values (one per handle index below it).
  std::size_t size() const { return values_.size(); }
  /// The stored values by handle index, first grown to the mesh's capacity (while attached).
  std::span<T> raw() {
    if (auto r = registry_.lock(); r && values_.size() < r->mesh->capacity(element_kind_v<H>))
      values_.resize(r->mesh->capacity(element_kind_v<H>), default_);
    return {values_.data(), values_.size()};
  }
  /// The stored values by handle index (elements past `size()` read the default).
  std::span<const T> raw() const { return {values_.data(), values_.size()}; }
  /// What elements read before they are written.
  const T& default_value() const { return default_; }
  /// True while the mesh the container was made for (or the mesh its data moved to) lives.
  bool attached() const { return !registry_.expired(); }

 private:
  void on_compact(const CompactMap& map) override { detail::remap_slots(values_, map.of<H>()); }

  void grow(std::uint32_t index) {
    std::size_t size = std::size_t(index) + 1;
    if (auto r = registry_.lock()) size = std::max<std::size_t>(size, r->mesh->capacity(element_kind_v<H>));
    values_.resize(size, default_);
  }

  void detach() {
    if (auto r = registry_.lock()) r->remove(this);
    registry_.reset();
  }

  std::weak_ptr<detail::MeshListeners> registry_;
  detail::ValueVector<T> values_;
  T default_{};
};

template <class T>
using VertexData = MeshData<VertexId, T>;
template <class T>
using EdgeData = MeshData<EdgeId, T>;
template <class T>
using FaceData = MeshData<FaceId, T>;
template <class T>
using CornerData = MeshData<CornerId, T>;

}  // namespace dlfl
