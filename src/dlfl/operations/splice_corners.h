#pragma once
// splice_corners (TopMod's splice): the vertices of two corners become one, by an edge drawn between the two
// corners and its collapse. See docs/modeling.md.

#include <glm/vec3.hpp>
#include <optional>

#include <dlfl/mesh.h>
#include <dlfl/operations/transaction.h>

namespace dlfl {

struct SpliceCornersOptions {
  /// Where the merged vertex goes; the midpoint of the two vertices when not given.
  std::optional<glm::dvec3> position;
};

/// Throws ParameterError, naming "corner1", "corner2" or "position", if `splice_corners` would refuse: a
/// removed corner; two corners at the same vertex; corners of two different faces of which one is a hole and
/// the other not (the merged face would be both); vertices already joined by an edge (it would become a
/// self-loop); or anything for which collapsing the new edge would fail `check_collapse_edge`, predicted on
/// the mesh as it is. O(the valences of the two vertices), plus the size of the corners' face when that face
/// visits one of the vertices more than once.
void check_splice_corners(const Mesh& mesh, CornerId corner1, CornerId corner2,
                          const SpliceCornersOptions& options = {});

/// insert_edge(corner1, corner2), then collapse_edge of that edge: vertex(corner2) is merged into
/// vertex(corner1), which keeps its handle and is returned.
///
/// Counts: corners of one face (the face splits, and is pinched at the merged vertex): V-1, E+0, F+1; of two
/// faces (they merge, joining two components or adding a handle, and the merged vertex is visited twice):
/// V-1, E+0, F-1.
///
/// Validates with `check_splice_corners` before it changes anything.
VertexId splice_corners(Transaction& tx, CornerId corner1, CornerId corner2,
                        const SpliceCornersOptions& options = {});

}  // namespace dlfl
