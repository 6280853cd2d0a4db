#pragma once
// inset_face: a smaller copy of a face inside it, joined to it by a ring of quads (docs/modeling.md,
// "Extrusions"). V+n, E+2n, F+n for a face of n sides; the Euler characteristic, hole flags and orientation
// are kept.

#include <span>
#include <string_view>
#include <vector>

#include <dlfl/mesh.h>
#include <dlfl/operations/transaction.h>

namespace dlfl {

struct InsetFaceOptions {
  /// How far each corner moves towards the centroid c, as a share of the way: the copy's corner is
  /// c + (1 - amount)(p - c). In (0, 1): 0 would leave the copy on the face, 1 would shrink it to a point.
  double amount = 0.25;
  /// How far the copy then moves along the face's unit normal (negative: inwards). A face with no normal
  /// (a zero Newell vector) takes only 0.
  double depth = 0.0;
};

/// Insets `face`: the face becomes n quads (p_i, p_{i+1}, q_{i+1}, q_i) around the copy q_0 ... q_{n-1},
/// which is returned (it turns as the face did). V+n, E+2n, F+n. Checks everything first
/// (the refusals of inset_faces) and throws ParameterError naming "face", "amount" or "depth", with the mesh
/// unchanged. O(n).
FaceId inset_face(Transaction& tx, FaceId face, const InsetFaceOptions& options = {});

/// Insets each face on its own, as inset_face would one after the other (the counts add up). The copies are
/// in the order of `faces`. Refused before any change, with a ParameterError naming `face_parameter`: an
/// empty list, a face listed twice, a removed, hole or point-sphere face, a face with no normal when depth
/// is not 0; naming the option: an amount outside (0, 1), a number not finite, new positions that would not
/// be finite.
std::vector<FaceId> inset_faces(Transaction& tx, std::span<const FaceId> faces,
                                const InsetFaceOptions& options = {},
                                std::string_view face_parameter = "faces");

}  // namespace dlfl
