#pragma once
// Internal to truncate_vertex, chamfer_edge and cut_face: cutting a "cap" off the mesh. A cap is a set of
// vertices with the edges among them that go with them (none for a vertex, the edge for an edge, the face's
// sides for a face). Every other edge leaving the cap is cut at `offset` of its length from the cap, a
// section edge joins consecutive cut points inside each face around the cap, and the cap (its vertices, its
// edges, the stubs to the cut points and the faces between) is deleted: one new face takes its place.
//
// For a cap of n vertices, i inner edges and m edges leaving it, the cap and the faces inside it form a disk,
// so the counts are V + m - n, E + m - i, F + 1 - (faces inside the cap). The Euler operators do it all
// through the Transaction: m subdivide_edge, one insert_edge per run of the cap along a face, then
// delete_edge and delete_vertex.

#include <span>
#include <string>
#include <string_view>
#include <vector>

#include <dlfl/mesh.h>
#include <dlfl/operations/cut_result.h>
#include <dlfl/operations/transaction.h>
#include <dlfl/parameters.h>

namespace dlfl::detail {

/// One element to cut off: its vertices and the edges that are removed with them.
struct Cap {
  std::vector<VertexId> vertices;
  std::vector<EdgeId> inner_edges;
  /// Faces whose every side is an inner edge (cut_face's face): they go with the cap.
  long inner_faces = 0;
  /// The element as messages name it ("v3", "e5", "f2").
  std::string label;
};

/// What a cut of caps does to the counts: V+vertices, E+edges, F+faces.
struct CapCounts {
  long vertices = 0, edges = 0, faces = 0;
};

/// Refuses, with ParameterError naming "offset", an offset that is not finite or not in (0, 0.5); and,
/// naming `parameter`: an element given twice, two caps sharing a vertex, a cap with fewer than two edges
/// leaving it, an edge leaving a cap that comes back to it, a face around the cap that would get a section
/// edge from a cut point to itself, cut points that would not be finite. Returns the counts of the cut.
/// O(the edges and faces around the caps).
CapCounts check_caps(const Mesh& mesh, std::string_view op, std::string_view parameter,
                     std::span<const Cap> caps, double offset);

/// Checks (as check_caps), then cuts every cap off, as one operation. The new faces are in the order of the
/// caps; a new face is a hole face when a hole face was around its cap (the cut then widens the boundary).
CutResult cut_caps(Transaction& tx, std::string_view op, std::string_view parameter,
                   std::span<const Cap> caps, double offset);

/// The parameter that holds the offset, for the three operations.
ParamSpec offset_param();

}  // namespace dlfl::detail
