#pragma once
// cut_face: TopMod's "cut by face" (docs/modeling.md, "Cutting"): the face is sliced off with its corners,
// the cut running across the edges that leave the face. For a face of n sides whose vertices send out
// m = sum (valence - 2) edges besides the face's own: V+m-n, E+m-n, F+0 (nothing on a prism, where m = n);
// the Euler characteristic, the orientation and the hole faces elsewhere are kept.

#include <span>
#include <string_view>

#include <dlfl/mesh.h>
#include <dlfl/operations/cut_result.h>
#include <dlfl/operations/transaction.h>

namespace dlfl {

struct CutFaceOptions {
  /// Where each edge leaving the face is cut, as a share of its length from the face, in (0, 0.5).
  double offset = 0.25;
};

/// Cuts `face` off: each edge that leaves a corner of the face (not one of its sides) gets a new vertex at
/// `offset` of its length from the face, the new vertices are joined across each face around, and the face
/// with its vertices, sides and the stubs is removed, leaving an m-gon in its place (a hole face if a hole
/// face was around: the cut widens the boundary). Refusals (ParameterError naming "face" or "offset", before
/// any change): a removed, hole or point-sphere face, a face that visits a vertex twice, fewer than 2 edges
/// leaving it, an edge leaving it that comes back to it, an offset outside (0, 0.5), cut points that would
/// not be finite. O(the faces around the face's corners).
CutResult cut_face(Transaction& tx, FaceId face, const CutFaceOptions& options = {});

/// Cuts every face of the list as one operation; the counts add up. Two listed faces that share a vertex are
/// refused (their cuts would meet); an edge joining two listed faces gets two new vertices. Refusals name
/// "faces".
CutResult cut_faces(Transaction& tx, std::span<const FaceId> faces, const CutFaceOptions& options = {});

/// The checks of cut_faces, refusals naming `parameter`.
void check_cut_faces(const Mesh& mesh, std::span<const FaceId> faces, const CutFaceOptions& options,
                     std::string_view parameter = "faces");

}  // namespace dlfl
