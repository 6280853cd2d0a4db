#pragma once
// spheralize: every vertex moved onto the bounding sphere about the vertices' centroid. See
// docs/modeling.md.

#include <cstddef>
#include <glm/vec3.hpp>

#include <dlfl/mesh.h>
#include <dlfl/operations/transaction.h>

namespace dlfl {

struct SpheralizeResult {
  /// The centroid of all the vertices (point spheres included) and the largest distance of one from it.
  glm::dvec3 center{0.0};
  double radius = 0.0;
  /// Vertices exactly at the centre, which have no ray to move along and stay where they are.
  std::size_t vertices_at_center = 0;
};

/// Moves every vertex p along the ray from the centre c through it onto the sphere about c whose radius is
/// the largest distance of a vertex from c: p' = c + r (p - c) / |p - c|. A vertex already at distance r
/// (computed) is not written, so a mesh whose vertices are all on that sphere stays exactly as it is; a
/// vertex at the centre is left there (counted in the result). Refuses nothing. Counts: V+0, E+0, F+0.
/// O(V).
SpheralizeResult spheralize(Transaction& tx);

}  // namespace dlfl
