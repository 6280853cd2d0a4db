#include <algorithm>

#include <dlfl/errors.h>
#include <dlfl/operations/detail/extrusion_faces.h>
#include <dlfl/operations/detail/handle_selection.h>

namespace dlfl::detail {

ParamSpec face_param(std::string doc) {
  return selection_param<FaceId>("face", "faces", false, std::move(doc));
}

ParamSpec faces_param(std::string doc) {
  return selection_param<FaceId>("face", "faces", true, std::move(doc));
}

FaceSelection selected_faces(std::string_view op, const Params& params) {
  HandleSelection<FaceId> s = selected_handles<FaceId>(op, params, "face", "faces");
  return {std::move(s.handles), std::move(s.parameter)};
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
