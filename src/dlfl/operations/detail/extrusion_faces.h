#pragma once
// Internal to the extrusions (extrude_face, inset_face): which faces an operation acts on. The registered
// operations take `face` (one) or `faces` (a list), both declared optional, exactly one given; the library
// functions refuse faces they cannot act on, naming the parameter that gave them.

#include <span>
#include <string>
#include <string_view>
#include <vector>

#include <dlfl/mesh.h>
#include <dlfl/operations/detail/refusal.h>
#include <dlfl/parameters.h>

namespace dlfl::detail {

/// The two declarations: `face` and `faces`, both optional.
ParamSpec face_param(std::string doc);
ParamSpec faces_param(std::string doc);

/// The faces given, and the name of the parameter that gave them.
struct FaceSelection {
  std::vector<FaceId> faces;
  std::string parameter;
};

/// The faces of `params`: exactly one of `face` and `faces` must be there. Throws ParameterError naming
/// "face" otherwise ("OP: give exactly one of parameters face and faces").
FaceSelection selected_faces(std::string_view op, const Params& params);

/// Refuses, with a ParameterError naming `parameter`: an empty list, a face listed twice, a removed face, a
/// hole face, a point sphere's face. O(k log k) for k faces.
void check_surface_faces(std::string_view op, const Mesh& mesh, std::span<const FaceId> faces,
                         std::string_view parameter);

}  // namespace dlfl::detail
