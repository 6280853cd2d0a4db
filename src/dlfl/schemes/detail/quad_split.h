#pragma once
// Internal to the schemes: the connectivity of one Catmull-Clark-style quad split, shared by Catmull-Clark
// and MLCA on polygon meshes (they differ only in positions).

#include <dlfl/mesh.h>
#include <dlfl/mesh_assembler.h>

namespace dlfl::detail {

/// Sets every corner (and the hole flags) of `out` for the split of `m`, which must be dense (handles 0 ..
/// count-1, see `dense_mesh`): corner k of `m` becomes quad k = (vertex point, edge point of the edge leaving
/// k, face point, edge point of the edge arriving), with vertex points at 0..V-1, edge points at V..V+E-1 and
/// face points after them. `out` must have V + E + F vertices and one quad per corner of `m`. Quads of hole
/// faces are holes. Positions are the caller's.
void assemble_quad_split(const Mesh& m, MeshAssembler& out);

}  // namespace dlfl::detail
