#pragma once
// dissolve_coplanar: the edges between faces that lie in one plane deleted, so that each flat region becomes
// as few simple faces as it can. See docs/modeling.md.

#include <cstddef>

#include <dlfl/mesh.h>
#include <dlfl/operations/transaction.h>

namespace dlfl {

struct DissolveCoplanarOptions {
  /// Faces whose normals differ by less than this (in degrees, in (0, 180]) count as coplanar.
  double angle_degrees = 0.01;
};

struct DissolveCoplanarResult {
  /// Edges deleted between two faces (merges), k.
  std::size_t edges_merged = 0;
  /// Edges left dangling inside a merged face and deleted with their free end, d.
  std::size_t edges_peeled = 0;
  /// Vertices of valence 2 joined away afterwards, j.
  std::size_t vertices_joined = 0;
};

/// Throws ParameterError naming "angle_degrees" unless it is a finite number in (0, 180].
void check_dissolve_coplanar(const DissolveCoplanarOptions& options);

/// Deletes every edge between two different surface faces whose normals (Newell's vectors) differ by less
/// than the angle, when the merged face stays simple: the two faces must meet along one chain of edges and
/// nowhere else, and neither may be a hole or have a zero normal. A merged face's normal is the sum of the
/// two Newell vectors (exact for the merged polygon), so a region is judged by its average plane, and the
/// edges are looked at again, in handle order, until no more can go. The rest of a chain that the merge
/// leaves dangling inside the face is deleted with its free ends (delete_edge, delete_vertex), and every
/// vertex this leaves with valence 2 is joined away (unsubdivide_edge) unless remove_valence2 would leave it.
/// Never deletes an edge with the same face on both sides or beside a hole.
///
/// Counts: V-(d+j), E-(k+d+j), F-k. A cube whose faces were each cut into four quads by subdivide_face gives
/// the cube back (6 quads, 8 vertices). A flat region with holes in it (the top of the genus slabs) cannot
/// be one simple face: it ends as several, which ones depending on the order of the edges.
///
/// Validates the options first. O(size) per pass, with each merge costing the size of the smaller face
/// times the valence of its vertices.
DissolveCoplanarResult dissolve_coplanar(Transaction& tx, const DissolveCoplanarOptions& options = {});

}  // namespace dlfl
