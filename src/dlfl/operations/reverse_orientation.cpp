// reverse_orientation: see reverse_orientation.h.
//
// A mesh is its rotation system: the cyclic order of the edges around each vertex, whose orbits are the
// faces. insert_edge(c1, c2) puts the new edge into the angle of c1 and that of c2, just before their
// outgoing edges in the turn around their vertices, and delete_edge takes it out again. So deleting every
// edge and inserting them back in the reverse order, each just before the edge that followed it in the
// mirrored (reversed) rotation among the edges present at that time, builds the mirrored mesh; each step of
// the rebuild is the mirror image of a step of the teardown, so it costs the same. The edge a deleted edge
// must be inserted beside is its neighbour in the rotation when it is deleted, which a linked list per
// vertex of the edge ends still present gives in O(1).

#include <dlfl/operations/reverse_orientation.h>

#include <limits>
#include <string>
#include <vector>

#include <dlfl/operations/detail/edge_ends.h>
#include <dlfl/operations/detail/operation_table.h>

namespace dlfl {
namespace {

constexpr std::uint32_t none = detail::no_edge_end;
using detail::corner_at;
using detail::end_of;

// One edge deleted: its ends, and at each the end turning just before it around that vertex (in the
// original, clockwise rotation) among those still present, or `none` if it was the last one there.
struct Deletion {
  EdgeId edge;
  VertexId ends[2];
  std::uint32_t before[2];
};

// An element whose named values go to another: a face to its reversed face, a corner to its counterpart.
// Both are found after the rebuild from a new edge and a vertex at one of its ends.
struct Counterpart {
  std::uint32_t old_index;
  EdgeId edge;  // old edge
  VertexId at;
};

class Reversal {
 public:
  explicit Reversal(Transaction& tx) : tx_(tx), m_(tx.mesh()) {}

  void run() {
    const std::uint32_t edge_capacity = m_.edge_capacity();
    if (m_.num_edges() == 0) return;  // point spheres only: each is its own mirror image
    record_rotations();
    const std::vector<Counterpart> faces = face_counterparts();
    const std::vector<bool> holes = hole_flags(faces);
    const std::vector<Counterpart> corners = corner_counterparts();
    tear_down(edge_capacity);
    rebuild(edge_capacity);
    for (std::size_t i = 0; i < faces.size(); ++i) {
      const FaceId f = m_.face(new_corner(faces[i]));
      if (m_.is_hole(f) != holes[i]) tx_.set_hole(f, holes[i]);
    }
    carry_attributes(faces, corners);
  }

 private:
  void record_rotations() {
    const std::uint32_t ends = 2 * m_.edge_capacity();
    turn_next_.assign(ends, none);
    turn_prev_.assign(ends, none);
    valence_.assign(m_.vertex_capacity(), 0);
    for (CornerId c : m_.corners()) {
      if (!m_.edge(c).valid()) continue;
      const std::uint32_t from = end_of(m_, c), to = end_of(m_, m_.next_around_vertex(c));
      turn_next_[from] = to;
      turn_prev_[to] = from;
      ++valence_[m_.vertex(c).index()];
    }
  }

  // Each face with an edge, by its first corner's edge and that edge's far end along the face: the reversed
  // face runs along the edge from there.
  std::vector<Counterpart> face_counterparts() const {
    std::vector<Counterpart> out;
    for (FaceId f : m_.faces()) {
      const CornerId c = m_.first_corner(f);
      if (m_.edge(c).valid()) out.push_back({f.index(), m_.edge(c), m_.vertex(m_.next(c))});
    }
    return out;
  }

  std::vector<bool> hole_flags(const std::vector<Counterpart>& faces) const {
    std::vector<bool> out;
    out.reserve(faces.size());
    for (const Counterpart& f : faces) out.push_back(m_.is_hole(FaceId(f.old_index)));
    return out;
  }

  // A corner is the angle between the edge arriving at its vertex along its face and the one leaving; in
  // the reversed face the arriving one leaves. Only needed for corner attributes.
  std::vector<Counterpart> corner_counterparts() const {
    std::vector<Counterpart> out;
    bool needed = false;
    for (const AttributeInfo& a : m_.attributes()) needed |= a.kind == ElementKind::corner;
    if (!needed) return out;
    for (CornerId c : m_.corners()) {
      if (m_.edge(c).valid()) out.push_back({c.index(), m_.edge(m_.prev(c)), m_.vertex(c)});
    }
    return out;
  }

  // Deletes every edge. The order only matters for the cost: first the edges between two faces (merges,
  // each relabelling the smaller face), then dangling edges from their free end (O(1) each), then whatever
  // is left (the handles of a component), stripping the dangling edges each deletion makes.
  void tear_down(std::uint32_t edge_capacity) {
    for (std::uint32_t i = 0; i < edge_capacity; ++i) {
      const EdgeId e(i);
      if (m_.is_alive(e) && m_.face(e, 0) != m_.face(e, 1)) remove(e);
    }
    for (VertexId v : m_.vertices()) {
      if (valence_[v.index()] == 1) leaves_.push_back(v);
    }
    strip_leaves();
    for (std::uint32_t i = 0; i < edge_capacity; ++i) {
      if (!m_.is_alive(EdgeId(i))) continue;
      remove(EdgeId(i));
      strip_leaves();
    }
  }

  void remove(EdgeId e) {
    Deletion d{e, {m_.from(e), m_.to(e)}, {none, none}};
    for (int side = 0; side < 2; ++side) {
      const std::uint32_t end = 2 * e.index() + side;
      const std::uint32_t before = turn_prev_[end], after = turn_next_[end];
      if (before == end) continue;  // the vertex's last edge
      d.before[side] = before;
      turn_next_[before] = after;
      turn_prev_[after] = before;
    }
    tx_.delete_edge(e);
    deletions_.push_back(d);
    for (VertexId v : d.ends) {
      if (--valence_[v.index()] == 1) leaves_.push_back(v);
    }
  }

  void strip_leaves() {
    while (!leaves_.empty()) {
      const VertexId v = leaves_.back();
      leaves_.pop_back();
      if (valence_[v.index()] == 1) remove(m_.edge(m_.corner(v)));  // its one corner leaves along its edge
    }
  }

  // Inserts the edges back, last deleted first. The edge that turned just before e around v in the original
  // turns just after it in the mirror image, so e goes into the angle of that edge's corner at v (the angle
  // just before the edge); with no such edge v is a point sphere, whose corner takes it.
  void rebuild(std::uint32_t edge_capacity) {
    renewed_.assign(edge_capacity, EdgeId());
    for (auto d = deletions_.rbegin(); d != deletions_.rend(); ++d) {
      CornerId at[2];
      for (int side = 0; side < 2; ++side) {
        const VertexId v = d->ends[side];
        at[side] = d->before[side] == none ? m_.corner(v) : corner_at(m_, renewed_[d->before[side] / 2], v);
      }
      renewed_[d->edge.index()] = tx_.insert_edge(at[0], at[1]).edge;
    }
  }

  CornerId new_corner(const Counterpart& c) const { return corner_at(m_, renewed_[c.edge.index()], c.at); }

  // Every value is read before any is written: some old handles are alive again for other elements, whose
  // slots still hold the old values.
  void carry_attributes(const std::vector<Counterpart>& faces, const std::vector<Counterpart>& corners) {
    struct Write {
      std::uint32_t index;
      AttributeValue value;
    };
    for (const AttributeInfo& a : m_.attributes()) {
      std::vector<Write> writes;
      switch (a.kind) {
        case ElementKind::vertex:
          continue;  // vertices keep their handles
        case ElementKind::edge:
          for (std::uint32_t i = 0; i < renewed_.size(); ++i) {
            if (renewed_[i].valid()) {
              writes.push_back({renewed_[i].index(), m_.attribute_value(a.kind, a.name, i)});
            }
          }
          break;
        case ElementKind::face:
          for (const Counterpart& f : faces) {
            writes.push_back(
                {m_.face(new_corner(f)).index(), m_.attribute_value(a.kind, a.name, f.old_index)});
          }
          break;
        case ElementKind::corner:
          for (const Counterpart& c : corners) {
            writes.push_back({new_corner(c).index(), m_.attribute_value(a.kind, a.name, c.old_index)});
          }
          break;
      }
      for (const Write& w : writes) {
        if (!(m_.attribute_value(a.kind, a.name, w.index) == w.value)) {
          tx_.set_attribute(a.kind, a.name, w.index, w.value);
        }
      }
    }
  }

  Transaction& tx_;
  const Mesh& m_;
  std::vector<std::uint32_t> turn_next_, turn_prev_;  // per edge end: the next and previous around its vertex
  std::vector<std::uint32_t> valence_;                // per vertex: edges still present
  std::vector<VertexId> leaves_;                      // vertices that may have one edge left
  std::vector<Deletion> deletions_;
  std::vector<EdgeId> renewed_;  // per old edge: the edge inserted for it
};

}  // namespace

void reverse_orientation(Transaction& tx) { Reversal(tx).run(); }

std::vector<OperationSpec> detail::reverse_orientation_operation_specs() {
  return {edit_operation("reverse_orientation",
                         "turns every face the other way round (inside out); hole flags and named values are "
                         "kept",
                         {}, "V+0, E+0, F+0", [](Transaction& tx, const Params&) {
                           reverse_orientation(tx);
                           return Params{};
                         })};
}
}  // namespace dlfl
