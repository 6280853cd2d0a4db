#pragma once
// A digest of a mesh's full structure and exact positions.

#include <string>

#include <dlfl/mesh.h>

namespace dlfl {

/// 128-bit digest as 32 lowercase hex digits. Covers every live element with its handle: positions bit for
/// bit, all links, anchors, face sizes and hole flags; and the named attributes: kind, name, type, default
/// and the values on live elements (any NaN hashed as one). A mesh without attributes hashes as it did before
/// attributes existed, and the Zhang-Wang "face_point" face attribute (a point) as the kernel field it
/// replaced: its NaN-free values inside the face loop, without name. Meshes equal under `operator==` have
/// equal digests; it is not cryptographic. O(size).
std::string mesh_hash(const Mesh& mesh);

}  // namespace dlfl
