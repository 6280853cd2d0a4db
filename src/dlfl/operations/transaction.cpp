#include <dlfl/operations/transaction.h>

namespace dlfl {

namespace {

// Applies one inverse and returns its own inverse.
struct Reverter {
  Mesh& mesh;
  Change operator()(const Step& step) const { return mesh.apply(step); }
  Change operator()(const AttributeWrite& w) const {
    AttributeWrite back{w.kind, w.name, w.index, mesh.attribute_value(w.kind, w.name, w.index)};
    mesh.set_attribute_value(w.kind, w.name, w.index, w.value);
    return back;
  }
  Change operator()(const AttributeCreation& c) const {
    if (c.present) {
      mesh.add_attribute(c.kind, c.name, c.default_value);
    } else {
      mesh.remove_attribute(c.kind, c.name);
    }
    return AttributeCreation{c.kind, c.name, c.default_value, !c.present};
  }
};

// The step of `kind` on vertex v (delete_vertex, unsubdivide_edge).
Step vertex_step(Step::Kind kind, VertexId v) {
  Step step{kind};
  step.vertex = v;
  return step;
}

}  // namespace

void ChangeRecord::revert(Mesh& mesh) {
  // Each inverse applied returns its own inverse; in the order applied they redo the changes.
  std::vector<Change> opposite;
  opposite.reserve(inverses_.size());
  for (auto it = inverses_.rbegin(); it != inverses_.rend(); ++it)
    opposite.push_back(std::visit(Reverter{mesh}, *it));
  inverses_ = std::move(opposite);
}

void ChangeRecord::append(ChangeRecord&& later) {
  if (inverses_.empty()) {
    inverses_ = std::move(later.inverses_);
    return;
  }
  inverses_.insert(inverses_.end(), later.inverses_.begin(), later.inverses_.end());
}

Transaction::~Transaction() {
  if (!committed_ && !record_.empty()) {
    // Reverting a record of successful operators on the mesh they left cannot fail, so this does not throw.
    record_.revert(mesh_);
  }
}

VertexId Transaction::create_vertex(const glm::dvec3& position) {
  const VertexId v = mesh_.create_vertex(position);
  record_.inverses_.push_back(vertex_step(Step::Kind::delete_vertex, v));
  return v;
}

void Transaction::delete_vertex(VertexId v) { apply(vertex_step(Step::Kind::delete_vertex, v)); }

InsertEdgeResult Transaction::insert_edge(CornerId c1, CornerId c2) {
  return recorded(mesh_.insert_edge(c1, c2));
}

DeleteEdgeResult Transaction::delete_edge(EdgeId e) { return recorded(mesh_.delete_edge(e)); }

VertexId Transaction::subdivide_edge(EdgeId e, const glm::dvec3& position) {
  const VertexId v = mesh_.subdivide_edge(e, position);
  record_.inverses_.push_back(vertex_step(Step::Kind::unsubdivide_edge, v));
  return v;
}

void Transaction::unsubdivide_edge(VertexId v) { apply(vertex_step(Step::Kind::unsubdivide_edge, v)); }

void Transaction::set_position(VertexId v, const glm::dvec3& position) {
  Step step{Step::Kind::set_position};
  step.vertex = v;
  step.position = position;
  apply(step);
}

void Transaction::set_hole(FaceId f, bool hole) {
  Step step{Step::Kind::set_hole};
  step.face = f;
  step.hole = hole;
  apply(step);
}

FaceManifold Transaction::create_face_manifold(std::span<const glm::dvec3> positions,
                                               std::span<VertexId> vertices,
                                               std::span<CornerId> front_corners,
                                               std::span<CornerId> back_corners) {
  // The free function checks all its input before it changes anything, then appends N vertices and N edges.
  const std::uint32_t first_vertex = mesh_.vertex_capacity();
  const std::uint32_t first_edge = mesh_.edge_capacity();
  const FaceManifold fm = dlfl::create_face_manifold(mesh_, positions, vertices, front_corners, back_corners);
  const auto n = static_cast<std::uint32_t>(positions.size());
  // Inverses in the order of the primitives (N create_vertex, then N insert_edge): reverting deletes the
  // edges last to first, then the point spheres.
  for (std::uint32_t i = 0; i < n; ++i)
    record_.inverses_.push_back(vertex_step(Step::Kind::delete_vertex, VertexId(first_vertex + i)));
  for (std::uint32_t i = 0; i < n; ++i) {
    Step s{Step::Kind::delete_edge};
    s.edge = EdgeId(first_edge + i);
    record_.inverses_.push_back(s);
  }
  return fm;
}

void Transaction::apply(const Step& step) { record_.inverses_.push_back(mesh_.apply(step)); }

void Transaction::add_attribute(ElementKind kind, std::string_view name,
                                const AttributeValue& default_value) {
  if (mesh_.has_attribute(kind, name)) {
    mesh_.add_attribute(kind, name, default_value);  // throws for another type, else does nothing
    return;
  }
  mesh_.add_attribute(kind, name, default_value);
  record_.inverses_.push_back(AttributeCreation{kind, std::string(name), default_value, false});
}

void Transaction::set_attribute(ElementKind kind, std::string_view name, std::uint32_t index,
                                const AttributeValue& value) {
  AttributeWrite back{kind, std::string(name), index, mesh_.attribute_value(kind, name, index)};
  mesh_.set_attribute_value(kind, name, index, value);  // throws with nothing changed
  record_.inverses_.push_back(std::move(back));
}

ChangeRecord Transaction::commit() {
  committed_ = true;
  return std::move(record_);
}

void Transaction::rollback() {
  record_.revert(mesh_);
  record_ = ChangeRecord();
}

}  // namespace dlfl
