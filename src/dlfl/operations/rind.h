#pragma once
// rind: a crust with holes punched through it at the given faces, each joined to its inner twin by a tube
// of quads (docs/modeling.md, "Shells and frames").

#include <span>
#include <vector>

#include <dlfl/mesh.h>
#include <dlfl/operations/transaction.h>

namespace dlfl {

struct RindOptions {
  /// As CrustOptions::thickness. > 0.
  double thickness = 0.1;
};

/// The crust (see `crust`), then each of `faces` (of n sides) joined to its twin by a tube of n quads
/// (connect_faces, corner i of the face to its copy): per face V+0, E+n, F+n-2. With k >= 1 faces on a
/// closed component of Euler characteristic chi, one component of Euler characteristic 2 chi - 2k; applying
/// rind to that again follows the same rule. Hole faces are joined to their twins as crust joins them.
/// Returns the copies of the vertices, in the order of their handles. Refuses (ParameterError, nothing
/// changed): an empty list, a face listed twice, a removed, hole or point-sphere face (naming "faces"); a
/// thickness as crust refuses it. O(size), plus the size of a component per handle of it.
std::vector<VertexId> rind(Transaction& tx, std::span<const FaceId> faces, const RindOptions& options = {});

/// The checks of rind, without changing anything. (The registered operation takes `faces` or, for one face,
/// `face`; its refusals name the one given.)
void check_rind(const Mesh& mesh, std::span<const FaceId> faces, const RindOptions& options);

}  // namespace dlfl
