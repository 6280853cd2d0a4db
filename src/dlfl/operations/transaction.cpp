#include <dlfl/operations/transaction.h>

#include <cstring>

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

namespace {

enum SlotTag : std::uint32_t {
  vertex_deletion,         // a: the vertex
  edge_deletion,           // a: the edge, b: reuse.face
  edge_deletion_anchored,  // a: the edge, b and c: reuse.face_anchors[0]
  other,                   // a: the index in others_
};

bool same(const Step& x, const Step& y) {
  const auto same_reuse = [](const detail::Reuse& r, const detail::Reuse& q) {
    for (int i = 0; i < 2; ++i) {
      if (r.corners[i] != q.corners[i] || r.face_anchors[i].face != q.face_anchors[i].face ||
          r.face_anchors[i].corner != q.face_anchors[i].corner ||
          r.vertex_anchors[i].vertex != q.vertex_anchors[i].vertex ||
          r.vertex_anchors[i].corner != q.vertex_anchors[i].corner)
        return false;
    }
    return r.edge == q.edge && r.face == q.face && r.vertex == q.vertex;
  };
  // Positions compared bit for bit (-0.0 is not 0.0 here).
  return x.kind == y.kind && x.hole == y.hole && x.vertex == y.vertex && x.edge == y.edge &&
         x.face == y.face && x.corner1 == y.corner1 && x.corner2 == y.corner2 &&
         std::memcmp(&x.position, &y.position, sizeof(x.position)) == 0 && same_reuse(x.reuse, y.reuse);
}

template <class Slot>
Step unpack(const Slot& s) {
  Step step{s.tag == vertex_deletion ? Step::Kind::delete_vertex : Step::Kind::delete_edge};
  if (s.tag == vertex_deletion) {
    step.vertex = VertexId(s.a);
  } else {
    step.edge = EdgeId(s.a);
    if (s.tag == edge_deletion) {
      step.reuse.face = FaceId(s.b);
    } else {
      step.reuse.face_anchors[0] = {FaceId(s.b), CornerId(s.c)};
    }
  }
  return step;
}

}  // namespace

Change ChangeRecord::inverse(std::size_t i) const {
  const Slot& s = slots_[i];
  if (s.tag == other) return others_[s.a];
  return unpack(s);
}

void ChangeRecord::push(const Step& step) {
  Slot s{other, 0, 0, 0};
  if (step.kind == Step::Kind::delete_vertex) {
    s = {vertex_deletion, step.vertex.value, 0, 0};
  } else if (step.kind == Step::Kind::delete_edge) {
    s = step.reuse.face_anchors[0].face.valid()
            ? Slot{edge_deletion_anchored, step.edge.value, step.reuse.face_anchors[0].face.value,
                   step.reuse.face_anchors[0].corner.value}
            : Slot{edge_deletion, step.edge.value, step.reuse.face.value, 0};
  }
  // Kept in the slot only if the slot gives back exactly this step.
  if (s.tag != other && same(unpack(s), step)) {
    slots_.push_back(s);
    return;
  }
  slots_.push_back({other, static_cast<std::uint32_t>(others_.size()), 0, 0});
  others_.push_back(step);
}

void ChangeRecord::push(Change&& change) {
  if (const Step* step = std::get_if<Step>(&change)) {
    push(*step);
    return;
  }
  slots_.push_back({other, static_cast<std::uint32_t>(others_.size()), 0, 0});
  others_.push_back(std::move(change));
}

void ChangeRecord::reserve(std::size_t changes) { slots_.reserve(slots_.size() + changes); }

void ChangeRecord::revert(Mesh& mesh) {
  // Each inverse applied returns its own inverse; in the order applied they redo the changes.
  ChangeRecord opposite;
  opposite.reserve(size());
  for (std::size_t i = slots_.size(); i-- > 0;) {
    const Slot& s = slots_[i];
    opposite.push(s.tag == other ? std::visit(Reverter{mesh}, others_[s.a]) : Change(mesh.apply(unpack(s))));
  }
  *this = std::move(opposite);
}

void ChangeRecord::append(ChangeRecord&& later) {
  if (slots_.empty()) {
    *this = std::move(later);
    return;
  }
  slots_.reserve(slots_.size() + later.slots_.size());
  for (const Slot& s : later.slots_) {
    if (s.tag == other) {
      slots_.push_back({other, static_cast<std::uint32_t>(others_.size()), 0, 0});
      others_.push_back(std::move(later.others_[s.a]));
    } else {
      slots_.push_back(s);
    }
  }
  later = ChangeRecord();
}

Transaction::~Transaction() {
  if (!committed_ && !record_.empty()) {
    // Reverting a record of successful operators on the mesh they left cannot fail, so this does not throw.
    record_.revert(mesh_);
  }
}

void Transaction::reserve(std::size_t changes, std::size_t vertices, std::size_t edges, std::size_t faces,
                          std::size_t corners) {
  record_.reserve(changes);
  mesh_.reserve(vertices, edges, faces, corners);
}

VertexId Transaction::create_vertex(const glm::dvec3& position) {
  const VertexId v = mesh_.create_vertex(position);
  record_.push(vertex_step(Step::Kind::delete_vertex, v));
  return v;
}

void Transaction::delete_vertex(VertexId v) { apply(vertex_step(Step::Kind::delete_vertex, v)); }

InsertEdgeResult Transaction::insert_edge(CornerId c1, CornerId c2) {
  return recorded(mesh_.insert_edge(c1, c2));
}

DeleteEdgeResult Transaction::delete_edge(EdgeId e) { return recorded(mesh_.delete_edge(e)); }

VertexId Transaction::subdivide_edge(EdgeId e, const glm::dvec3& position) {
  const VertexId v = mesh_.subdivide_edge(e, position);
  record_.push(vertex_step(Step::Kind::unsubdivide_edge, v));
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
    record_.push(vertex_step(Step::Kind::delete_vertex, VertexId(first_vertex + i)));
  for (std::uint32_t i = 0; i < n; ++i) {
    Step s{Step::Kind::delete_edge};
    s.edge = EdgeId(first_edge + i);
    record_.push(s);
  }
  return fm;
}

void Transaction::apply(const Step& step) { record_.push(mesh_.apply(step)); }

void Transaction::add_attribute(ElementKind kind, std::string_view name,
                                const AttributeValue& default_value) {
  if (mesh_.has_attribute(kind, name)) {
    mesh_.add_attribute(kind, name, default_value);  // throws for another type, else does nothing
    return;
  }
  mesh_.add_attribute(kind, name, default_value);
  record_.push(AttributeCreation{kind, std::string(name), default_value, false});
}

void Transaction::set_attribute(ElementKind kind, std::string_view name, std::uint32_t index,
                                const AttributeValue& value) {
  AttributeWrite back{kind, std::string(name), index, mesh_.attribute_value(kind, name, index)};
  mesh_.set_attribute_value(kind, name, index, value);  // throws with nothing changed
  record_.push(std::move(back));
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
