#include <algorithm>

#include <dlfl/errors.h>
#include <dlfl/operations/detail/extrusion_faces.h>

namespace dlfl::detail {

ParamSpec face_param(std::string doc) {
  return param("face", ParamType::face, std::move(doc)).optional("exactly one of face and faces");
}

ParamSpec faces_param(std::string doc) {
  return param("faces", ParamType::faces, std::move(doc)).optional("exactly one of face and faces");
}

FaceSelection selected_faces(std::string_view op, const Params& params) {
  const bool one = params.has("face"), many = params.has("faces");
  if (one == many) {
    throw ParameterError(std::string(op) + ": give exactly one of parameters face and faces" +
                             (one ? " (both are given)" : " (neither is given)"),
                         "face");
  }
  if (one) return {{params.handle<FaceId>("face")}, "face"};
  return {params.handles<FaceId>("faces"), "faces"};
}

void check_surface_faces(std::string_view op, const Mesh& mesh, std::span<const FaceId> faces,
                         std::string_view parameter) {
  if (faces.empty()) refuse_worded(op, parameter, " is empty: it needs at least one face");
  for (FaceId f : faces) {
    if (!mesh.is_alive(f))
      refuse_worded(op, parameter, ": " + to_string(f) + " does not exist (removed or never created)");
    if (mesh.is_hole(f))
      refuse_worded(op, parameter,
                    ": " + to_string(f) + " is a hole face (a boundary loop), not a surface face");
    if (mesh.size(f) < 2)
      refuse_worded(op, parameter, ": " + to_string(f) + " is a point sphere's face (one corner, no edge)");
  }
  std::vector<FaceId> sorted(faces.begin(), faces.end());
  std::sort(sorted.begin(), sorted.end());
  const auto twice = std::adjacent_find(sorted.begin(), sorted.end());
  if (twice != sorted.end()) refuse_worded(op, parameter, ": " + to_string(*twice) + " is listed twice");
}

}  // namespace dlfl::detail
