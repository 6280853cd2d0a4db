#pragma once
// Light handles to the named attributes a mesh owns (`Mesh::add_vertex_attribute` and friends).
//
// A handle points at the attribute's storage, which lives on the heap: it stays valid when the mesh is moved
// (it then reads the moved-to mesh), and until the attribute is removed or the mesh it came from is
// destroyed or assigned to. Handles of a copied mesh are those of the original; look them up again on the
// copy.

#include <dlfl/attribute_types.h>
#include <dlfl/detail/attribute_column.h>

namespace dlfl {

class Mesh;

/// Read-only access to an attribute of values T on the elements H.
template <class H, class T>
class ConstAttribute {
 public:
  /// An invalid handle: `valid()` is false and it must not be indexed.
  ConstAttribute() = default;

  /// The value of element h: the default if it never got one (new elements, for example). Never allocates.
  const T& operator[](H h) const { return column_->get(h.index()); }
  /// What elements without a value of their own read.
  const T& default_value() const { return column_->default_ref(); }
  bool valid() const { return column_ != nullptr; }

 private:
  friend class Mesh;
  template <class, class>
  friend class Attribute;
  explicit ConstAttribute(const detail::TypedColumn<H, T>* column) : column_(column) {}
  const detail::TypedColumn<H, T>* column_ = nullptr;
};

/// Read-write access to an attribute of values T on the elements H. Like a span, a const handle still writes.
template <class H, class T>
class Attribute {
 public:
  /// An invalid handle: `valid()` is false and it must not be indexed.
  Attribute() = default;

  /// The value of element h, for reading and writing. Storage grows lazily, so this may first extend it up to
  /// h (filling the default); h must be a handle of the mesh (below its capacity), live or removed.
  T& operator[](H h) const { return column_->slot(h.index()); }
  /// The value of element h without growing the storage (the default if it never got one).
  const T& get(H h) const { return column_->get(h.index()); }
  /// What elements without a value of their own read.
  const T& default_value() const { return column_->default_ref(); }
  bool valid() const { return column_ != nullptr; }
  operator ConstAttribute<H, T>() const { return ConstAttribute<H, T>(column_); }

 private:
  friend class Mesh;
  explicit Attribute(detail::TypedColumn<H, T>* column) : column_(column) {}
  detail::TypedColumn<H, T>* column_ = nullptr;
};

template <class T>
using VertexAttribute = Attribute<VertexId, T>;
template <class T>
using EdgeAttribute = Attribute<EdgeId, T>;
template <class T>
using FaceAttribute = Attribute<FaceId, T>;
template <class T>
using CornerAttribute = Attribute<CornerId, T>;

}  // namespace dlfl
