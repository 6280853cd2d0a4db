#include <dlfl/history/editor.h>

#include <cmath>

#include <dlfl/errors.h>
#include <dlfl/io/json_mesh.h>
#include <dlfl/io/mesh_io.h>
#include <dlfl/schemes/zhang_wang_honeycomb.h>

namespace dlfl {
namespace {
nlohmann::json point(const glm::dvec3& p) { return {p.x, p.y, p.z}; }

nlohmann::json params_json(const SchemeParams& params) {
  nlohmann::json j = nlohmann::json::object();
  for (const auto& [name, value] : params) {
    if (const double* d = std::get_if<double>(&value)) {
      j[name] = *d;
    } else {
      j[name] = std::get<std::string>(value);
    }
  }
  return j;
}
}  // namespace

void Editor::push(Entry entry, nlohmann::json op) {
  undo_.push_back(std::move(entry));
  if (options_.undo_limit != 0 && undo_.size() > options_.undo_limit) undo_.pop_front();
  redo_.clear();
  ops_.push_back(std::move(op));
}

Step Editor::run(const Step& step, nlohmann::json op) {
  Step inverse = mesh_.apply(step);  // throws with the mesh unchanged
  push(Entry{{inverse}, std::nullopt}, std::move(op));
  return inverse;
}

void Editor::flip(Mesh& mesh, Entry& entry) {
  if (entry.mesh) {
    std::swap(mesh, *entry.mesh);
    return;
  }
  // Apply back to front; the steps returned, in the order applied, are the entry's opposite.
  std::vector<Step> opposite;
  opposite.reserve(entry.steps.size());
  for (auto it = entry.steps.rbegin(); it != entry.steps.rend(); ++it) opposite.push_back(mesh.apply(*it));
  entry.steps = std::move(opposite);
}

bool Editor::undo() {
  if (undo_.empty()) return false;
  Entry entry = std::move(undo_.back());
  undo_.pop_back();
  flip(mesh_, entry);
  redo_.push_back(std::move(entry));
  ops_.push_back({{"op", "undo"}});
  return true;
}

bool Editor::redo() {
  if (redo_.empty()) return false;
  Entry entry = std::move(redo_.back());
  redo_.pop_back();
  flip(mesh_, entry);
  undo_.push_back(std::move(entry));
  if (options_.undo_limit != 0 && undo_.size() > options_.undo_limit) undo_.pop_front();
  ops_.push_back({{"op", "redo"}});
  return true;
}

void Editor::load(const std::filesystem::path& path) {
  Mesh loaded = read_mesh(path);
  nlohmann::json op = {{"op", "load"}, {"path", std::filesystem::absolute(path).lexically_normal().string()}};
  if (options_.embed_meshes) op["mesh"] = mesh_to_json(loaded);
  std::swap(mesh_, loaded);
  push(Entry{{}, std::move(loaded)}, std::move(op));
}

void Editor::set_mesh(Mesh mesh) {
  nlohmann::json op = {{"op", "mesh"}, {"mesh", mesh_to_json(mesh)}};
  std::swap(mesh_, mesh);
  push(Entry{{}, std::move(mesh)}, std::move(op));
}

void Editor::subdivide(const std::string& scheme, const SchemeParams& params, int iterations) {
  if (iterations < 0)
    throw InvalidArgument("subdivide: iterations must be >= 0, got " + std::to_string(iterations));
  const SchemeParams full = resolve_scheme_params(scheme, params);
  // Each iteration reads the previous mesh and builds a new one; M_n itself is never copied or touched.
  Mesh next = iterations == 0 ? mesh_ : apply_scheme(mesh_, scheme, full);
  for (int i = 1; i < iterations; ++i) next = apply_scheme(next, scheme, full);
  nlohmann::json op = {
      {"op", "subdivide"}, {"scheme", scheme}, {"iterations", iterations}, {"params", params_json(full)}};
  std::swap(mesh_, next);
  push(Entry{{}, std::move(next)}, std::move(op));
}

VertexId Editor::create_vertex(const glm::dvec3& position) {
  Step s{Step::Kind::create_vertex};
  s.position = position;
  return run(s, {{"op", "create_vertex"}, {"position", point(position)}}).vertex;
}

void Editor::delete_vertex(VertexId v) {
  Step s{Step::Kind::delete_vertex};
  s.vertex = v;
  run(s, {{"op", "delete_vertex"}, {"vertex", v.index()}});
}

InsertEdgeResult Editor::insert_edge(CornerId c1, CornerId c2) {
  InsertEdgeResult r = mesh_.insert_edge(c1, c2);
  push(Entry{{r.inverse}, std::nullopt},
       {{"op", "insert_edge"}, {"corner1", c1.index()}, {"corner2", c2.index()}});
  return r;
}

DeleteEdgeResult Editor::delete_edge(EdgeId e) {
  DeleteEdgeResult r = mesh_.delete_edge(e);
  push(Entry{{r.inverse}, std::nullopt}, {{"op", "delete_edge"}, {"edge", e.index()}});
  return r;
}

VertexId Editor::subdivide_edge(EdgeId e, const glm::dvec3& position) {
  Step s{Step::Kind::subdivide_edge};
  s.edge = e;
  s.position = position;
  return run(s, {{"op", "subdivide_edge"}, {"edge", e.index()}, {"position", point(position)}}).vertex;
}

void Editor::unsubdivide_edge(VertexId v) {
  Step s{Step::Kind::unsubdivide_edge};
  s.vertex = v;
  run(s, {{"op", "unsubdivide_edge"}, {"vertex", v.index()}});
}

void Editor::set_position(VertexId v, const glm::dvec3& position) {
  Step s{Step::Kind::set_position};
  s.vertex = v;
  s.position = position;
  run(s, {{"op", "set_position"}, {"vertex", v.index()}, {"position", point(position)}});
}

void Editor::set_face_point(FaceId f, const std::optional<glm::dvec3>& control) {
  // A whole-mesh entry: the control point is an attribute now, which no Step sets.
  Mesh next = mesh_;
  dlfl::set_face_point(next, f, control);  // throws with the current mesh unchanged
  std::swap(mesh_, next);
  push(Entry{{}, std::move(next)}, {{"op", "set_face_point"},
                                    {"face", f.index()},
                                    {"position", control ? point(*control) : nlohmann::json()}});
}

FaceManifold Editor::create_face_manifold(std::span<const glm::dvec3> positions, std::span<VertexId> vertices,
                                          std::span<CornerId> front_corners,
                                          std::span<CornerId> back_corners) {
  // create_face_manifold checks all its input before it changes anything, so it runs on the mesh itself; the
  // entry records the inverse of each primitive (the N edges deleted in reverse, then the N point spheres).
  const std::uint32_t first_vertex = mesh_.vertex_capacity();
  const std::uint32_t first_edge = mesh_.edge_capacity();
  FaceManifold fm = dlfl::create_face_manifold(mesh_, positions, vertices, front_corners, back_corners);
  Entry entry;
  const auto n = static_cast<std::uint32_t>(positions.size());
  // The entry's steps run back to front on undo: vertices' deletions first in the list, edges' after them.
  for (std::uint32_t i = 0; i < n; ++i) {
    Step s{Step::Kind::delete_vertex};
    s.vertex = VertexId(first_vertex + i);
    entry.steps.push_back(s);
  }
  for (std::uint32_t i = 0; i < n; ++i) {
    Step s{Step::Kind::delete_edge};
    s.edge = EdgeId(first_edge + i);
    entry.steps.push_back(s);
  }
  nlohmann::json pts = nlohmann::json::array();
  for (const auto& p : positions) pts.push_back(point(p));
  push(std::move(entry), {{"op", "create_face_manifold"}, {"positions", std::move(pts)}});
  return fm;
}

nlohmann::json Editor::log() const {
  return {{"format", "dlfl-oplog"}, {"version", 1}, {"undo_limit", options_.undo_limit}, {"ops", ops_}};
}

}  // namespace dlfl
