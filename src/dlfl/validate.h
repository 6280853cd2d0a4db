#pragma once
// The consistency checker: proves that a mesh is a valid closed orientable 2-manifold in DLFL form, and
// reports the topology of each connected component.

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include <dlfl/mesh.h>

namespace dlfl {

/// What kind of rule a violation breaks.
enum class ViolationCode : std::uint8_t {
  removed_reference,  ///< a live element refers to a removed or never-created one
  next_prev,          ///< next(prev(c)) != c or prev(next(c)) != c
  corner_face,     ///< consecutive corners of a cycle belong to different faces, or a face's first corner is
                   ///< not its own
  face_size,       ///< the cycle from a face's first corner does not have size(f) corners
  edge_corner,     ///< an edge and its side corners disagree (edge(c) != e, or the other side does not start
                   ///< at the next vertex)
  edge_sides,      ///< an edge does not have exactly two distinct sides, or is a self-loop
  vertex_corner,   ///< a vertex's representative corner is not at that vertex
  pinched_vertex,  ///< the corners at a vertex form more than one rotation cycle (a non-manifold vertex)
  point_sphere,    ///< a corner without an edge that is not a well-formed point sphere
  counts,          ///< the live counts the mesh keeps differ from the elements actually present
  euler_characteristic,  ///< a component has odd or greater-than-2 Euler characteristic
};

/// Name of a code, e.g. "pinched_vertex".
const char* to_string(ViolationCode code);

/// One broken rule: the element it concerns (as "v12", "e3", "f7", "c40", or "mesh") and a message.
struct Violation {
  ViolationCode code;
  std::string element;
  std::string message;
};

/// Topology of one connected component. Hole faces count as faces (they close the surface), so `genus` is the
/// genus of the open surface too.
struct ComponentInfo {
  std::size_t vertices = 0;
  std::size_t edges = 0;
  std::size_t faces = 0;  ///< including holes
  std::size_t holes = 0;
  long euler_characteristic = 0;  ///< V - E + F
  long genus = 0;                 ///< (2 - chi) / 2
};

struct ValidationReport {
  std::vector<Violation> violations;  ///< at most the requested number; `violation_count` has the total
  std::size_t violation_count = 0;
  /// Components ordered by their smallest vertex handle. Computed only when the structure is sound.
  std::vector<ComponentInfo> components;
  bool valid() const { return violation_count == 0; }
};

/// Checks every DLFL rule: next/prev symmetry, corner-face membership and face sizes, edge-corner agreement,
/// exactly two sides per edge, one rotation cycle per vertex, point-sphere rules, no reference to removed
/// elements, and the live counts; then the Euler characteristic and genus of each component. Never throws and
/// never reads out of bounds, whatever the mesh holds. O(size).
ValidationReport validate(const Mesh& mesh, std::size_t max_violations = 100);

}  // namespace dlfl
