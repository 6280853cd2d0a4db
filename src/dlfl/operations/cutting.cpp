// truncate_vertex, chamfer_edge and cut_face: the cap cut (detail/cap_cut.h) of a vertex (no inner edge), of
// the two ends of an edge (the edge inner), and of a face's vertices (its sides inner, the face inside). Each
// differs only in how its elements become caps.

#include <dlfl/operations/cutting.h>

#include <algorithm>
#include <vector>

#include <dlfl/operations/detail/cap_cut.h>
#include <dlfl/operations/detail/extrusion_faces.h>
#include <dlfl/operations/detail/operation_table.h>

namespace dlfl {
namespace {

std::vector<detail::Cap> vertex_caps(const Mesh& mesh, std::span<const VertexId> vertices,
                                     std::string_view parameter) {
  detail::require_live_list(mesh, "truncate_vertex", parameter, vertices);
  std::vector<detail::Cap> caps;
  for (VertexId v : vertices) caps.push_back({{v}, {}, 0, to_string(v)});
  return caps;
}

std::vector<detail::Cap> edge_caps(const Mesh& mesh, std::span<const EdgeId> edges,
                                   std::string_view parameter) {
  detail::require_live_list(mesh, "chamfer_edge", parameter, edges);
  std::vector<detail::Cap> caps;
  for (EdgeId e : edges) caps.push_back({{mesh.from(e), mesh.to(e)}, {e}, 0, to_string(e)});
  return caps;
}

std::vector<detail::Cap> face_caps(const Mesh& mesh, std::span<const FaceId> faces,
                                   std::string_view parameter) {
  detail::check_surface_faces("cut_face", mesh, faces, parameter);
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
      detail::refuse("cut_face", parameter,
                     to_string(f) + " visits " + to_string(*twice) + " twice, so its cut would meet itself");
    }
    caps.push_back(std::move(cap));
  }
  return caps;
}

constexpr detail::CapCutter<VertexId> vertex_cutter{"truncate_vertex", "vertex", "vertices", &vertex_caps};
constexpr detail::CapCutter<EdgeId> edge_cutter{"chamfer_edge", "edge", "edges", &edge_caps};
constexpr detail::CapCutter<FaceId> face_cutter{"cut_face", "face", "faces", &face_caps};

}  // namespace

CutResult truncate_vertex(Transaction& tx, VertexId vertex, const TruncateVertexOptions& options) {
  return vertex_cutter.cut(tx, std::span<const VertexId>(&vertex, 1), options.offset, "vertex");
}

CutResult chamfer_edge(Transaction& tx, EdgeId edge, const ChamferEdgeOptions& options) {
  return edge_cutter.cut(tx, std::span<const EdgeId>(&edge, 1), options.offset, "edge");
}

CutResult cut_face(Transaction& tx, FaceId face, const CutFaceOptions& options) {
  return face_cutter.cut(tx, std::span<const FaceId>(&face, 1), options.offset, "face");
}

CutResult truncate_vertices(Transaction& tx, std::span<const VertexId> vertices,
                            const TruncateVertexOptions& options) {
  return vertex_cutter.cut(tx, vertices, options.offset, "vertices");
}

CutResult chamfer_edges(Transaction& tx, std::span<const EdgeId> edges, const ChamferEdgeOptions& options) {
  return edge_cutter.cut(tx, edges, options.offset, "edges");
}

CutResult cut_faces(Transaction& tx, std::span<const FaceId> faces, const CutFaceOptions& options) {
  return face_cutter.cut(tx, faces, options.offset, "faces");
}

void check_truncate_vertices(const Mesh& mesh, std::span<const VertexId> vertices,
                             const TruncateVertexOptions& options, std::string_view parameter) {
  vertex_cutter.check(mesh, vertices, options.offset, parameter);
}

void check_chamfer_edges(const Mesh& mesh, std::span<const EdgeId> edges, const ChamferEdgeOptions& options,
                         std::string_view parameter) {
  edge_cutter.check(mesh, edges, options.offset, parameter);
}

void check_cut_faces(const Mesh& mesh, std::span<const FaceId> faces, const CutFaceOptions& options,
                     std::string_view parameter) {
  face_cutter.check(mesh, faces, options.offset, parameter);
}

std::vector<OperationSpec> detail::cutting_operation_specs() {
  return {
      vertex_cutter.spec("cuts a corner off: a vertex of valence k becomes a k-gon", "the vertex to cut off",
                         "vertices to cut off together", "per vertex of valence k: V+k-1, E+k, F+1"),
      edge_cutter.spec("an edge becomes a new face: it is cut off with its two ends", "the edge to chamfer",
                       "edges to chamfer together (no two sharing an end)",
                       "per edge whose ends have valences a and b: V+a+b-4, E+a+b-3, F+1"),
      face_cutter.spec(
          "slices a face off with its corners, across the edges that leave it (TopMod's cut by face)",
          "the face to cut off", "faces to cut off together (no two sharing a vertex)",
          "per face of n sides with m = sum (valence - 2) edges leaving it: V+m-n, E+m-n, F+0")};
}
}  // namespace dlfl
