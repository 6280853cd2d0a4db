#pragma once
// Reading a mesh by dense handles: schemes that number their output from their input's handles (vertex point
// v, edge point nv + e, ...) need every handle index below the element count, that is, no tombstones.

#include <cstdint>
#include <optional>

#include <dlfl/mesh.h>

namespace dlfl {

/// `mesh` itself when it has no removed elements (handles are dense: 0 .. count-1), else a compacted copy
/// held in `storage`. Schemes that number their output from input handles read their input through this.
const Mesh& dense_mesh(const Mesh& mesh, std::optional<Mesh>& storage);

/// The element counts of a mesh as 32-bit indices (every handle index fits 32 bits), for the loops of a
/// scheme over the handles of a dense mesh: `const auto [nv, ne, nf, nc] = dense_counts(m);`.
struct DenseCounts {
  std::uint32_t vertices, edges, faces, corners;
};
DenseCounts dense_counts(const Mesh& mesh);

/// The handle of `mesh` that `dense_mesh` numbers `dense_index`: its live element of kind H of that rank
/// (compacting keeps the order); invalid past the last. O(capacity): for messages that name the input's own
/// handles, not for loops.
template <class H>
H original_handle(const Mesh& mesh, std::uint32_t dense_index) {
  for (H h : mesh.elements<H>()) {
    if (dense_index-- == 0) return h;
  }
  return H();
}

}  // namespace dlfl
