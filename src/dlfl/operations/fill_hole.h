#pragma once
// fill_hole: a hole face becomes a surface face again, closing the boundary loop it stands for; the inverse
// of make_hole (dlfl/operations/make_hole.h). See docs/modeling.md.

#include <dlfl/mesh.h>
#include <dlfl/operations/transaction.h>

namespace dlfl {

/// Throws ParameterError naming "face" if `fill_hole` would refuse f: a removed face or one that is not a
/// hole.
void check_fill_hole(const Mesh& mesh, FaceId f);

/// Flags f as a surface face (Transaction::set_hole). Counts: V+0, E+0, F+0 (one fewer hole face, one more
/// surface face). O(1).
void fill_hole(Transaction& tx, FaceId f);

}  // namespace dlfl
