#pragma once
// Internal to the schemes: the connectivity of one Catmull-Clark-style quad split, shared by Catmull-Clark
// and MLCA on polygon meshes (they differ only in positions).

#include <dlfl/mesh.h>
#include <dlfl/mesh_assembler.h>
#include <dlfl/schemes/detail/scheme_origins.h>

namespace dlfl::detail {

/// Sets every corner (and the hole flags) of `out` for the split of `m`, which must be dense (handles 0 ..
/// count-1, see `dense_mesh`): corner k of `m` becomes quad k = (vertex point, edge point of the edge leaving
/// k, face point, edge point of the edge arriving), with vertex points at 0..V-1, edge points at V..V+E-1 and
/// face points after them. `out` must have V + E + F vertices and one quad per corner of `m`. Quads of hole
/// faces are holes. Positions are the caller's.
void assemble_quad_split(const Mesh& m, MeshAssembler& out);

/// The origins of the split `out` of dense `m` (as assembled above), with `in` naming m's elements in the
/// caller's input: vertex points <- vertices, edge points <- edges, face points <- faces; quad k <- corner k;
/// each half of an old edge <- that edge; the edge from the edge point of edge(c) to the face point of
/// face(c) <- corner c.
void quad_split_origins(const Mesh& m, const Mesh& out, const InputHandles& in, Origins& origins);

/// The origins of the split's corners, by corner handle, for composing the split with a later step: the four
/// corners of quad k <- corner k.
std::vector<Origin> quad_split_corner_origins(const Mesh& m, const InputHandles& in);

}  // namespace dlfl::detail
