#pragma once
// Lateral artifacts (Akleman and Srinivasan, "Honeycomb subdivision", section 5) made countable: the concave
// edges of a surface that should be convex, and how smooth it is. See docs/lateral_artifacts.md.

#include <cstddef>
#include <vector>

#include <dlfl/mesh.h>

namespace dlfl {

/// How many edges bend the wrong way, by how much, and how much the surface bends on average.
struct ConcaveEdges {
  /// Edges measured: between two distinct faces, neither a hole, both of nonzero area.
  std::size_t measured = 0;
  /// Measured edges that are concave: the centroid of either face lies above the plane of the other by more
  /// than the tolerance (a face's plane: its Newell normal, outward, through its centroid).
  std::size_t concave = 0;
  /// The largest bend of a concave edge, in degrees: the angle between the normals of its two faces (0 when
  /// no edge is concave).
  double worst_concave_degrees = 0.0;
  /// The mean bend over the measured edges, in degrees (0 when none is): the smoothness measure, smaller is
  /// smoother.
  double mean_dihedral_degrees = 0.0;
};

/// Measures every edge of the mesh as above. The tolerance is `relative_tolerance` times the diagonal of the
/// bounding box of the live vertices, so the count does not depend on the mesh's scale. Meant for closed,
/// consistently oriented surfaces (edges beside a hole are skipped, so an open mesh gets its interior
/// measured). When `concave` is given it is set to one flag per edge handle (edge_capacity() entries), true
/// for the concave edges. Throws InvalidArgument unless relative_tolerance is finite and >= 0. O(size).
ConcaveEdges concave_edges(const Mesh& mesh, double relative_tolerance = 1e-9,
                           std::vector<bool>* concave = nullptr);

}  // namespace dlfl
