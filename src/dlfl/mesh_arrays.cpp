#include <dlfl/mesh_arrays.h>

#include <dlfl/errors.h>
#include <dlfl/validate.h>

namespace dlfl {

MeshArrays MeshArrays::from(const Mesh& m) {
  MeshArrays a;
  a.vertices.resize(m.vertex_capacity());
  for (std::uint32_t i = 0; i < m.vertex_capacity(); ++i)
    a.vertices[i] = {m.positions_[i], m.vertex_corner_[i]};
  a.corners.resize(m.corner_capacity());
  for (std::uint32_t i = 0; i < m.corner_capacity(); ++i) {
    const auto& c = m.corners_[i];
    a.corners[i] = {c.vertex, c.face, c.next, c.prev, c.edge};
  }
  a.edges.resize(m.edge_capacity());
  for (std::uint32_t i = 0; i < m.edge_capacity(); ++i)
    a.edges[i] = {m.edges_[i].corner[0], m.edges_[i].corner[1]};
  a.faces.resize(m.face_capacity());
  for (std::uint32_t i = 0; i < m.face_capacity(); ++i) {
    const auto& f = m.faces_[i];
    a.faces[i] = {f.corner, f.size, f.alive, f.hole};
  }
  for (const auto& e : m.attributes_.entries()) {
    const detail::AttributeColumn& column = *e.column;
    Attribute& out = a.attributes.emplace_back();
    out.name = e.name;
    out.kind = column.kind();
    out.default_value = column.default_value();
    const std::uint32_t slots = m.capacity(column.kind());
    out.values.reserve(slots);
    detail::visit_column(column, [&](const auto& typed) {
      for (std::uint32_t i = 0; i < slots; ++i) out.values.emplace_back(typed.get(i));
    });
  }
  return a;
}

Mesh MeshArrays::to_mesh() const {
  Mesh m = unvalidated_mesh();
  const ValidationReport report = dlfl::validate(m, 1);
  if (!report.valid()) {
    const Violation& v = report.violations.front();
    throw TopologyError("mesh arrays: not a valid DLFL: " + v.element + ": " + v.message + " (" +
                        to_string(v.code) + ")");
  }
  return m;
}

ValidationReport MeshArrays::validate(std::size_t max_violations) const {
  return dlfl::validate(unvalidated_mesh(), max_violations);
}

Mesh MeshArrays::unvalidated_mesh() const {
  // Range checks first: the validator relies on live elements pointing at slots that exist.
  auto in_range = [](auto h, std::size_t n) { return !h.valid() || h.index() < n; };
  auto fail = [](const std::string& what) { throw TopologyError("mesh arrays: " + what); };
  const std::size_t nv = vertices.size(), nc = corners.size(), ne = edges.size(), nf = faces.size();
  if (nv >= VertexId::invalid_index || nc >= CornerId::invalid_index || ne >= EdgeId::invalid_index ||
      nf >= FaceId::invalid_index) {
    fail("too many elements for 32-bit handles");
  }
  Mesh m;
  m.positions_.resize(nv);
  m.vertex_corner_.resize(nv);
  for (std::size_t i = 0; i < nv; ++i) {
    if (!in_range(vertices[i].corner, nc))
      fail(to_string(VertexId(std::uint32_t(i))) + " has an out-of-range corner");
    m.positions_[i] = vertices[i].position;
    m.vertex_corner_[i] = vertices[i].corner;
    m.live_vertices_ += vertices[i].corner.valid();
  }
  m.corners_.resize(nc);
  for (std::size_t i = 0; i < nc; ++i) {
    const Corner& c = corners[i];
    if (!c.vertex.valid()) continue;
    if (!in_range(c.vertex, nv) || !in_range(c.face, nf) || !in_range(c.next, nc) || !in_range(c.prev, nc) ||
        !in_range(c.edge, ne) || !c.face.valid() || !c.next.valid() || !c.prev.valid()) {
      fail(to_string(CornerId(std::uint32_t(i))) + " has a missing or out-of-range handle");
    }
    m.corners_[i] = {c.vertex, c.face, c.next, c.prev, c.edge};
    ++m.live_corners_;
  }
  m.edges_.resize(ne);
  for (std::size_t i = 0; i < ne; ++i) {
    const Edge& e = edges[i];
    if (!e.corner0.valid()) continue;
    if (!in_range(e.corner0, nc) || !in_range(e.corner1, nc) || !e.corner1.valid()) {
      fail(to_string(EdgeId(std::uint32_t(i))) + " has a missing or out-of-range corner");
    }
    m.edges_[i].corner = {e.corner0, e.corner1};
    ++m.live_edges_;
  }
  m.faces_.resize(nf);
  for (std::size_t i = 0; i < nf; ++i) {
    const Face& f = faces[i];
    if (!in_range(f.corner, nc) || (f.alive && !f.corner.valid())) {
      fail(to_string(FaceId(std::uint32_t(i))) + " has a missing or out-of-range first corner");
    }
    m.faces_[i] = {f.corner, f.size, f.alive, f.hole};
    m.live_faces_ += f.alive;
    m.live_hole_faces_ += f.alive && f.hole;
  }
  for (const Attribute& at : attributes) {
    const std::string what = std::string(to_string(at.kind)) + " attribute '" + at.name + "'";
    if (at.name.empty()) fail("a " + std::string(to_string(at.kind)) + " attribute has no name");
    if (m.has_attribute(at.kind, at.name)) fail(what + " is given twice");
    const std::uint32_t slots = m.capacity(at.kind);
    if (at.values.size() != slots) {
      fail(what + " has " + std::to_string(at.values.size()) + " values for " + std::to_string(slots) +
           " slots");
    }
    m.add_attribute(at.kind, at.name, at.default_value);
    detail::visit_column(*m.attributes_.find(at.kind, at.name), [&](auto& typed) {
      using T = typename std::decay_t<decltype(typed)>::value_type;
      for (std::uint32_t i = 0; i < slots; ++i) {
        const T* value = std::get_if<T>(&at.values[i]);
        if (!value) {
          fail(what + ": value " + std::to_string(i) + " is not of type " + to_string(attribute_type_v<T>));
        }
        typed.slot(i) = *value;
      }
    });
  }
  return m;
}

}  // namespace dlfl
