// cut_face: the cap cut (detail/cap_cut.h) of a face's vertices, its sides inner and the face inside.

#include <dlfl/operations/cut_face.h>

#include <algorithm>
#include <vector>

#include <dlfl/navigation.h>
#include <dlfl/operations/detail/cap_cut.h>
#include <dlfl/operations/detail/extrusion_faces.h>
#include <dlfl/operations/detail/operation_table.h>

namespace dlfl {
namespace {

constexpr std::string_view op_name = "cut_face";

std::vector<detail::Cap> caps_of(const Mesh& mesh, std::span<const FaceId> faces,
                                 std::string_view parameter) {
  detail::check_surface_faces(op_name, mesh, faces, parameter);
  std::vector<detail::Cap> caps;
  for (FaceId f : faces) {
    detail::Cap cap{{}, {}, 1, to_string(f)};
    for (CornerId c : mesh.corners(f)) {
      cap.vertices.push_back(mesh.vertex(c));
      cap.inner_edges.push_back(mesh.edge(c));
    }
    std::vector<VertexId> sorted = cap.vertices;
    std::sort(sorted.begin(), sorted.end());
    const auto twice = std::adjacent_find(sorted.begin(), sorted.end());
    if (twice != sorted.end()) {
      detail::refuse(op_name, parameter,
                     to_string(f) + " visits " + to_string(*twice) + " twice, so its cut would meet itself");
    }
    caps.push_back(std::move(cap));
  }
  return caps;
}

CutResult cut_all(Transaction& tx, std::span<const FaceId> faces, const CutFaceOptions& o,
                  std::string_view parameter) {
  const auto caps = caps_of(tx.mesh(), faces, parameter);
  return detail::cut_caps(tx, op_name, parameter, caps, o.offset);
}

}  // namespace

CutResult cut_face(Transaction& tx, FaceId face, const CutFaceOptions& options) {
  return cut_all(tx, std::span<const FaceId>(&face, 1), options, "face");
}

CutResult cut_faces(Transaction& tx, std::span<const FaceId> faces, const CutFaceOptions& options) {
  return cut_all(tx, faces, options, "faces");
}

void check_cut_faces(const Mesh& mesh, std::span<const FaceId> faces, const CutFaceOptions& options,
                     std::string_view parameter) {
  const auto caps = caps_of(mesh, faces, parameter);
  detail::check_caps(mesh, op_name, parameter, caps, options.offset);
}

namespace detail {

std::vector<OperationSpec> cut_face_operation_specs() {
  return {edit_operation(
      "cut_face", "slices a face off with its corners, across the edges that leave it (TopMod's cut by face)",
      {face_param("the face to cut off"), faces_param("faces to cut off together (no two sharing a vertex)"),
       offset_param()},
      "per face of n sides with m = sum (valence - 2) edges leaving it: V+m-n, E+m-n, F+0",
      [](Transaction& tx, const Params& p) {
        const FaceSelection selection = selected_faces(op_name, p);
        const CutResult cut = cut_all(tx, selection.faces, {p.number("offset")}, selection.parameter);
        Params out;
        out["faces"] = cut.faces;
        out["vertices"] = cut.vertices;
        if (selection.parameter == "face") out["face"] = cut.faces.front();
        return out;
      },
      [](const Mesh& mesh, Params& p) {
        const FaceSelection selection = selected_faces(op_name, p);
        check_cut_faces(mesh, selection.faces, {p.number("offset")}, selection.parameter);
      })};
}

}  // namespace detail
}  // namespace dlfl
