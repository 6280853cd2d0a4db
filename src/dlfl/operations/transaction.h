#pragma once
// The recorder through which every composite operation changes a mesh. It runs the Euler operators and keeps
// the exact inverse of each one, so an operation gets its undo from the record with no undo code of its own,
// and a failure part-way leaves the mesh exactly as it was.

#include <cstddef>
#include <glm/vec3.hpp>
#include <span>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include <dlfl/create_face_manifold.h>
#include <dlfl/mesh.h>

namespace dlfl {

/// The inverse of writing one named attribute value: the value to put back.
struct AttributeWrite {
  ElementKind kind;
  std::string name;
  std::uint32_t index;
  AttributeValue value;
};

/// The inverse of adding a named attribute (`present` false: remove it) or of removing one that holds only
/// its default (`present` true: add it back).
struct AttributeCreation {
  ElementKind kind;
  std::string name;
  AttributeValue default_value;
  bool present;
};

/// One recorded inverse: an Euler operator, or an attribute change.
using Change = std::variant<Step, AttributeWrite, AttributeCreation>;

/// The inverses of a sequence of changes, in the order the changes were made. `revert` applies them back to
/// front, which restores the mesh exactly (same handles, bit-identical positions, the same attributes), and
/// turns the record into the one that redoes the changes.
class ChangeRecord {
 public:
  ChangeRecord() = default;

  bool empty() const { return slots_.empty(); }
  std::size_t size() const { return slots_.size(); }
  /// The i-th inverse (i < size()), oldest change first.
  Change inverse(std::size_t i) const;

  /// Undoes the recorded changes on `mesh` (which must be the mesh they were made on, as they left it), and
  /// becomes the record of that undo: reverting again redoes them.
  void revert(Mesh& mesh);

  /// Appends the changes of `later`, made after this record's.
  void append(ChangeRecord&& later);

 private:
  friend class Transaction;
  // One inverse. The two that make up nearly every record of a large operation, the delete_vertex of a
  // create_vertex and the delete_edge of an insert_edge, are kept in these 16 bytes (sizeof(Change) is
  // 112): the record would otherwise take more memory than the mesh it was made on. Any other change goes
  // to `others_` whole, the slot holding its index there.
  struct Slot {
    std::uint32_t tag;
    std::uint32_t a, b, c;
  };
  void push(const Step& step);
  void push(Change&& change);
  void reserve(std::size_t changes);

  std::vector<Slot> slots_;
  std::vector<Change> others_;
};

/// Changes a mesh through the Euler operators and records their inverses. Each function has the contract of
/// the `Mesh` operator of the same name; when it throws, the mesh is unchanged by that call.
///
/// A transaction that is destroyed without `commit()` (for instance while an exception propagates out of a
/// composite operation) reverts everything it did, so an operation either completes or changes nothing.
class Transaction {
 public:
  explicit Transaction(Mesh& mesh) : mesh_(mesh) {}
  Transaction(const Transaction&) = delete;
  Transaction& operator=(const Transaction&) = delete;
  ~Transaction();

  /// The mesh, to read. Changes go through the functions below.
  const Mesh& mesh() const { return mesh_; }

  VertexId create_vertex(const glm::dvec3& position);
  void delete_vertex(VertexId v);
  InsertEdgeResult insert_edge(CornerId c1, CornerId c2);
  DeleteEdgeResult delete_edge(EdgeId e);
  VertexId subdivide_edge(EdgeId e, const glm::dvec3& position);
  void unsubdivide_edge(VertexId v);
  void set_position(VertexId v, const glm::dvec3& position);
  /// Flags a face as a hole or as a surface face (no change to the topology).
  void set_hole(FaceId f, bool hole);
  /// CREATEFACEMANIFOLD (N create_vertex, then N insert_edge), as the free function of the same name.
  FaceManifold create_face_manifold(std::span<const glm::dvec3> positions, std::span<VertexId> vertices = {},
                                    std::span<CornerId> front_corners = {},
                                    std::span<CornerId> back_corners = {});
  /// Any operator given as a value.
  void apply(const Step& step);

  /// Adds a named attribute (see `Mesh::add_attribute`); nothing if it exists with the same type. Throws
  /// InvalidArgument if it exists with another type.
  void add_attribute(ElementKind kind, std::string_view name, const AttributeValue& default_value);
  /// Writes one value of an existing named attribute (see `Mesh::set_attribute_value`).
  void set_attribute(ElementKind kind, std::string_view name, std::uint32_t index,
                     const AttributeValue& value);

  /// Makes room for `changes` more recorded changes, and for the mesh to grow to the given capacities (as
  /// `Mesh::reserve`), so that an operation that knows its size fills presized arrays instead of growing
  /// them (copying them, and faulting in fresh memory) over and over. Changes nothing observable.
  void reserve(std::size_t changes, std::size_t vertices, std::size_t edges, std::size_t faces,
               std::size_t corners);

  /// Number of changes recorded so far.
  std::size_t size() const { return record_.size(); }

  /// Ends the transaction and hands over its record; the changes stay.
  ChangeRecord commit();
  /// Undoes every change made so far; the transaction stays open (and empty).
  void rollback();

 private:
  // Records the inverse an operator returned with its result.
  template <class Result>
  Result recorded(Result result) {
    record_.push(result.inverse);
    return result;
  }

  Mesh& mesh_;
  ChangeRecord record_;
  bool committed_ = false;
};

}  // namespace dlfl
