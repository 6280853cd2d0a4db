#pragma once
// make_hole: a surface face becomes a hole face (the DLFL keeps a deleted face as a hole, so the surface
// opens there and nothing else changes). fill_hole (dlfl/operations/fill_hole.h) is its inverse. See
// docs/modeling.md.

#include <dlfl/mesh.h>
#include <dlfl/operations/transaction.h>

namespace dlfl {

/// Throws ParameterError naming "face" if `make_hole` would refuse f: a removed face, a face that is already
/// a hole, or a point sphere's face (a lone vertex has no surface to open).
void check_make_hole(const Mesh& mesh, FaceId f);

/// Flags f as a hole (Transaction::set_hole). Counts: V+0, E+0, F+0 (one more hole face, one fewer surface
/// face). O(1).
void make_hole(Transaction& tx, FaceId f);

}  // namespace dlfl
