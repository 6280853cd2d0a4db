#pragma once
// A digest of a mesh's full structure and exact positions.

#include <string>

#include <dlfl/mesh.h>

namespace dlfl {

/// 128-bit digest as 32 lowercase hex digits. Covers every live element with its handle: positions bit for
/// bit, all links, anchors, face sizes and hole flags. Meshes equal under `operator==` have equal digests; it
/// is not cryptographic. O(size).
std::string mesh_hash(const Mesh& mesh);

}  // namespace dlfl
