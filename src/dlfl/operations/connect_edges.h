#pragma once
// connect_edges: a quad bridge between two edges of two different faces, made of two INSERTEDGEs. The first
// merges the two faces (joining two components, or adding a handle to one), the second splits the merged
// face again, cutting the bridge quad off.

#include <array>

#include <dlfl/mesh.h>
#include <dlfl/operations/transaction.h>

namespace dlfl {

/// What `connect_edges` made.
struct ConnectEdgesResult {
  /// The two new edges: from vertex(corner1) to the end of corner2's edge, and from the end of corner1's
  /// edge to vertex(corner2).
  std::array<EdgeId, 2> edges;
  /// The bridge quad.
  FaceId face;
};

/// Bridges the edge leaving `corner1` (from a to b along its face) and the edge leaving `corner2` (from c to
/// d) with the quad c, d, a, b: insert_edge(corner1, next(corner2)) merges the two faces, then
/// insert_edge(next(corner1), corner2) splits the quad off the merged face.
///
/// Counts: V+0, E+2, F+0 (the two faces become one face and the quad). On one component the genus grows by
/// one (Euler characteristic - 2); two components join into one, of genus g1 + g2.
///
/// Hole faces: two hole faces may be bridged (two boundary loops become one; the quad is a surface face);
/// one hole and one surface face may not (the merged face would be half boundary, half surface).
///
/// Throws ParameterError naming `corner1` or `corner2`, before anything changes, for a removed corner, a
/// point sphere's corner (no edge), the same edge twice, two corners of one face, a hole with a surface face,
/// or a bridge edge that would join a vertex to itself (a == d or b == c).
ConnectEdgesResult connect_edges(Transaction& tx, CornerId corner1, CornerId corner2);

/// The checks of `connect_edges`, without changing anything: throws ParameterError as it does.
void check_connect_edges(const Mesh& mesh, CornerId corner1, CornerId corner2);

}  // namespace dlfl
