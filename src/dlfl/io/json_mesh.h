#pragma once
// The native JSON mesh format: the full DLFL structure (every handle, corner order, hole flags, exact
// positions), so a mesh saves and reloads equal under operator==. Layout documented in docs/formats.md. Also
// the JSON of a parameter value (which may hold a mesh), as operation logs and listings write it.

#include <nlohmann/json.hpp>
#include <string>

#include <dlfl/mesh.h>
#include <dlfl/parameters.h>
#include <dlfl/validate.h>

namespace dlfl {

/// The document {"format": "dlfl-mesh", "version": 1, "vertices": ..., "corners": ..., "edges": ...,
/// "faces": ...}, plus "attributes" when the mesh has named attributes. Removed slots are null, so handles
/// keep their values (removed elements' attribute values are not kept).
nlohmann::json mesh_to_json(const Mesh& mesh);

/// The mesh of a document. Throws IoError naming `name` and the offending field (wrong format or version, a
/// missing or mistyped field, an out-of-range handle, a structure that fails validation). The "face_points"
/// array of older documents becomes the "face_point" face attribute.
Mesh mesh_from_json(const nlohmann::json& doc, const std::string& name);

/// The validator's report on the structure a document describes, which may be any DLFL state: every field
/// is checked as by `mesh_from_json` (IoError), but a structure that fails validation is reported, with up to
/// `max_violations` violations listed, instead of refused.
ValidationReport validate_json_mesh(const nlohmann::json& doc, const std::string& name,
                                    std::size_t max_violations = 100);

/// A parameter value as JSON, typed by its kind: null when empty, true, 1, 0.5, "text", [x, y, z], lists as
/// arrays, a mesh as its document (above), a parameter set as an object. Operation logs write values so,
/// and `dlfl ops` / `dlfl schemes --json` their defaults.
nlohmann::json value_to_json(const Value& value);

}  // namespace dlfl
