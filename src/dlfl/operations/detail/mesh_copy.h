#pragma once
// Internal to the operations that add a separately built mesh to the current one (multi_connect's hub): a
// copy of another mesh made through a Transaction, so that undoing it is the transaction's record.

#include <vector>

#include <dlfl/mesh.h>
#include <dlfl/operations/transaction.h>

namespace dlfl::detail {

/// Where the elements of the source went.
struct MeshCopy {
  /// Per source vertex index: its copy (invalid for an index that was not live).
  std::vector<VertexId> vertices;
  /// Per source edge index: its copy (invalid for an index that was not live).
  std::vector<EdgeId> edges;

  /// The copy of a corner of the source that has an edge: the corner at the copy of its vertex that starts
  /// along the copy of its edge.
  CornerId corner(const Mesh& target, const Mesh& source, CornerId c) const;
  /// The copy of a face of the source that has an edge.
  FaceId face(const Mesh& target, const Mesh& source, FaceId f) const {
    return target.face(corner(target, source, source.first_corner(f)));
  }
};

/// Adds a copy of `source` (positions, faces and orientation; hole flags and attributes are not copied) to
/// the transaction's mesh as new components: V, E and F grow by the source's. How: a scratch copy of the
/// source is taken apart edge by edge (remove_surface, detail/shell_copy.h), and the inverses of that
/// teardown, which rebuild it, are run again both on the scratch (to follow its handles) and, with each
/// corner translated to the copy's, through `tx`. O(size of the source), plus the size of a component per
/// handle.
MeshCopy add_mesh_copy(Transaction& tx, const Mesh& source);

}  // namespace dlfl::detail
