#include <dlfl/history/editor.h>

#include <algorithm>

#include <dlfl/errors.h>
#include <dlfl/mesh_hash.h>
#include <dlfl/operations/operation.h>

namespace dlfl {

void Editor::require_no_group(const char* what) const {
  if (!groups_.empty()) {
    throw InvalidArgument(std::string(what) + ": not allowed inside the open group '" + groups_.back().label +
                          "' (end_group first)");
  }
}

void Editor::push(Entry entry) {
  undo_.push_back(std::move(entry));
  if (options_.undo_limit != 0 && undo_.size() > options_.undo_limit) undo_.pop_front();
}

void Editor::record(std::string label, Part part) {
  redo_.clear();
  if (!options_.keep_history) {  // the part (a replaced mesh, a change record) is dropped here
    if (!groups_.empty()) ++groups_.front().entry.operations;
    return;
  }
  if (!groups_.empty()) {
    Entry& group = groups_.front().entry;  // inner groups merge into the outermost one
    ++group.operations;
    // Consecutive edit records merge, so a group of many small operations stays one record.
    if (auto* later = std::get_if<ChangeRecord>(&part);
        later && !group.parts.empty() && std::holds_alternative<ChangeRecord>(group.parts.back())) {
      std::get<ChangeRecord>(group.parts.back()).append(std::move(*later));
    } else {
      group.parts.push_back(std::move(part));
    }
    return;
  }
  Entry entry{std::move(label), 1, {}};
  entry.parts.push_back(std::move(part));
  push(std::move(entry));
}

void Editor::flip(Mesh& mesh, Entry& entry) {
  // Parts are undone last to first; reversing their order afterwards makes the entry's opposite.
  for (auto it = entry.parts.rbegin(); it != entry.parts.rend(); ++it) {
    if (auto* other = std::get_if<Mesh>(&*it)) {
      std::swap(mesh, *other);
    } else {
      std::get<ChangeRecord>(*it).revert(mesh);
    }
  }
  std::reverse(entry.parts.begin(), entry.parts.end());
}

Params Editor::apply(std::string_view name, const Params& params) {
  const OperationSpec& op = find_operation(name);
  if (op.kind == OperationSpec::Kind::history) {
    const Params full = resolve_params(op.name, op.params, params);
    if (op.name == "undo") {
      if (!undo()) throw InvalidArgument("undo: there is nothing to undo");
    } else if (op.name == "redo") {
      if (!redo()) throw InvalidArgument("redo: there is nothing to redo");
    } else if (op.name == "begin_group") {
      begin_group(full.text("label"));
    } else if (op.name == "end_group") {
      end_group();
    } else if (op.name == "clear_history") {
      clear_history();
    } else {
      throw InvalidArgument(op.name + ": the editor does not know this history operation");
    }
    return {};
  }
  Params full = resolve_operation_params(op, params, mesh_);
  Params outputs;
  if (op.kind == OperationSpec::Kind::edit) {
    Transaction tx(mesh_);
    outputs = op.edit(tx, full);  // on a throw, the transaction puts the mesh back
    record(op.name, tx.commit());
  } else {
    Mesh next = op.replace(mesh_, full);
    std::swap(mesh_, next);
    record(op.name, std::move(next));
  }
  log_.push_back({op.name, std::move(full)});
  return outputs;
}

void Editor::set_mesh(Mesh mesh, const std::optional<std::filesystem::path>& source) {
  Params params;
  if (source) {
    params["path"] = std::filesystem::absolute(*source).lexically_normal().string();
    if (options_.embed_meshes) params["mesh"] = std::make_shared<const Mesh>(mesh);
    params["hash"] = mesh_hash(mesh);  // a replay that reads the file again checks it is the same mesh
    log_.push_back({"load", std::move(params)});
  } else {
    params["mesh"] = std::make_shared<const Mesh>(mesh);
    log_.push_back({"mesh", std::move(params)});
  }
  std::swap(mesh_, mesh);
  record(log_.back().name, std::move(mesh));
}

void Editor::subdivide(std::string_view scheme, const Params& params, int iterations) {
  apply("subdivide", {{"scheme", std::string(scheme)}, {"iterations", iterations}, {"params", params}});
}

VertexId Editor::create_vertex(const glm::dvec3& position) {
  return apply("create_vertex", {{"position", position}}).handle<VertexId>("vertex");
}

void Editor::delete_vertex(VertexId v) { apply("delete_vertex", {{"vertex", v}}); }

namespace {
template <class H>
H output(const Params& out, const char* name) {
  return out.has(name) ? out.handle<H>(name) : H();
}
}  // namespace

InsertEdgeResult Editor::insert_edge(CornerId c1, CornerId c2) {
  const Params out = apply("insert_edge", {{"corner1", c1}, {"corner2", c2}});
  return {output<EdgeId>(out, "edge"), output<FaceId>(out, "created_face"),
          output<FaceId>(out, "removed_face"), Step{}};
}

DeleteEdgeResult Editor::delete_edge(EdgeId e) {
  const Params out = apply("delete_edge", {{"edge", e}});
  return {output<FaceId>(out, "created_face"), output<FaceId>(out, "removed_face"), Step{}};
}

VertexId Editor::subdivide_edge(EdgeId e, const glm::dvec3& position) {
  return apply("subdivide_edge", {{"edge", e}, {"position", position}}).handle<VertexId>("vertex");
}

void Editor::unsubdivide_edge(VertexId v) { apply("unsubdivide_edge", {{"vertex", v}}); }

void Editor::set_position(VertexId v, const glm::dvec3& position) {
  apply("set_position", {{"vertex", v}, {"position", position}});
}

void Editor::set_face_point(FaceId f, const std::optional<glm::dvec3>& point) {
  Params params{{"face", f}};
  if (point) params["position"] = *point;
  apply("set_face_point", params);
}

FaceManifold Editor::create_face_manifold(std::span<const glm::dvec3> positions) {
  const Params out = apply("create_face_manifold",
                           {{"positions", std::vector<glm::dvec3>(positions.begin(), positions.end())}});
  return {out.handle<FaceId>("front"), out.handle<FaceId>("back")};
}

void Editor::begin_group(std::string label) {
  groups_.push_back({label, Entry{std::move(label), 0, {}}});
  log_.push_back({"begin_group", {{"label", groups_.back().label}}});
}

void Editor::end_group() {
  if (groups_.empty()) throw InvalidArgument("end_group: no group is open");
  OpenGroup group = std::move(groups_.back());
  groups_.pop_back();
  log_.push_back({"end_group", {}});
  if (!groups_.empty()) return;  // an inner group: its operations are already in the outer one
  if (!group.entry.parts.empty()) push(std::move(group.entry));
}

template <class Entries, class Keep>
bool Editor::flip_latest(const char* op, Entries& from, const Keep& keep) {
  require_no_group(op);
  if (from.empty()) return false;
  Entry entry = std::move(from.back());
  from.pop_back();
  flip(mesh_, entry);
  keep(std::move(entry));
  log_.push_back({op, {}});
  return true;
}

bool Editor::undo() {
  return flip_latest("undo", undo_, [this](Entry entry) { redo_.push_back(std::move(entry)); });
}

bool Editor::redo() {
  return flip_latest("redo", redo_, [this](Entry entry) { push(std::move(entry)); });
}

namespace {
template <class Entries>
std::vector<Editor::HistoryEntry> report(const Entries& entries) {
  std::vector<Editor::HistoryEntry> out;
  for (const auto& e : entries) out.push_back({e.label, e.operations});
  return out;
}
}  // namespace

std::vector<Editor::HistoryEntry> Editor::undo_history() const { return report(undo_); }

std::vector<Editor::HistoryEntry> Editor::redo_history() const { return report(redo_); }

void Editor::clear_history() {
  require_no_group("clear_history");
  undo_.clear();
  redo_.clear();
  log_.push_back({"clear_history", {}});
}

}  // namespace dlfl
