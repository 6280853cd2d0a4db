#pragma once
// The description of a mesh that `dlfl info` prints and `dlfl.info` returns in Python: counts of the open
// surface, components and genus, validity, histograms, bounding box and hash, as one JSON object. One home,
// so that the tool and the binding cannot drift apart.

#include <string>

#include <dlfl/mesh.h>

namespace dlfl {

struct MeshInfoOptions {
  /// Add "angles": max and mean edge, vertex and face angles in degrees (Meng-Prautzsch definition 2.3) and
  /// whether the mesh is a strictly convex polyhedron around its vertex centroid ("convex", and
  /// "not_convex_because" when it is not).
  bool angles = false;
  /// Add, for a closed mesh (no hole), "concave_edges" and "worst_concave_degrees" (see `concave_edges`, the
  /// lateral-artifact measure of docs/lateral_artifacts.md).
  bool shape = false;
  /// As nlohmann::json::dump takes it: -1 for one line, else the spaces per level.
  int indent = 2;
};

/// A JSON object, keys in this order: "vertices", "edges", "faces", "corners", "holes", "point_spheres" (the
/// open surface's counts, see `statistics`), "components", "euler_characteristic" (V - E + F of the open
/// surface), "genus" (one per component, see `validate`), "valid", "face_sizes" and "valences" (histograms,
/// keys as strings), "bbox" ([[min], [max]]), "hash" (`mesh_hash`), "angles" when asked for, and
/// "concave_edges" and "worst_concave_degrees" when the shape is asked for and the mesh is closed. O(size)
/// (with angles, as `polyhedron_angles`).
std::string mesh_info_json(const Mesh& mesh, const MeshInfoOptions& options = {});

}  // namespace dlfl
