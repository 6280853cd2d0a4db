#pragma once
// The native JSON mesh format: the full DLFL structure (every handle, corner order, hole flags, exact
// positions), so a mesh saves and reloads equal under operator==. Layout documented in docs/formats.md.

#include <nlohmann/json.hpp>
#include <string>

#include <dlfl/mesh.h>

namespace dlfl {

/// The document {"format": "dlfl-mesh", "version": 1, "vertices": ..., "corners": ..., "edges": ...,
/// "faces": ...}, plus "attributes" when the mesh has named attributes. Removed slots are null, so handles
/// keep their values (removed elements' attribute values are not kept).
nlohmann::json mesh_to_json(const Mesh& mesh);

/// The mesh of a document. Throws IoError naming `name` and the offending field (wrong format or version, a
/// missing or mistyped field, an out-of-range handle, a structure that fails validation). The "face_points"
/// array of older documents becomes the "face_point" face attribute.
Mesh mesh_from_json(const nlohmann::json& doc, const std::string& name);

}  // namespace dlfl
