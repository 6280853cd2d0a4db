// dlfl.Mesh: construction from arrays, NumPy views of the storage, counts, navigation, geometry, named
// attributes; and the functions that read a whole mesh: validate, info, hash.

#include <pybind11/stl.h>

#include <array>
#include <cstring>
#include <string>
#include <tuple>
#include <utility>
#include <variant>

#include <dlfl/analysis/mesh_info.h>
#include <dlfl/build_mesh.h>
#include <dlfl/geometry.h>
#include <dlfl/mesh_hash.h>
#include <dlfl/navigation.h>
#include <dlfl/validate.h>
#include "binding.h"

namespace dlfl::python {
namespace {

using Index = std::int64_t;

// What keeps a view of a mesh's storage valid: a capsule sharing the mesh (one of its own: a live mesh's
// storage moves with the editor's operations, so its arrays are copies).
py::object view_owner(const MeshRef& self) {
  auto* keep = new std::shared_ptr<const Mesh>(self.owned());
  return py::capsule(keep, [](void* p) { delete static_cast<std::shared_ptr<const Mesh>*>(p); });
}

py::tuple point(const glm::dvec3& p) { return py::make_tuple(p.x, p.y, p.z); }

// The handles a range gives.
template <class Range>
std::vector<std::uint32_t> handles(const Range& range) {
  std::vector<std::uint32_t> out;
  for (auto h : range) out.push_back(h.index());
  return out;
}

// What a method found under the mesh's lock, as Python: handles as a uint32 array, a point as (x, y, z), the
// rest as pybind11 converts it. Python objects are made only after the lock is released, so that no Python
// code (a finalizer run by the garbage collector) runs while the lock is held.
template <class T>
auto to_py(T value) {
  if constexpr (std::is_same_v<T, std::vector<std::uint32_t>>) {
    return owned_array(std::move(value));
  } else if constexpr (std::is_same_v<T, glm::dvec3>) {
    return point(value);
  } else {
    return value;
  }
}

ElementKind kind_of(const std::string& kind) {
  for (ElementKind k : {ElementKind::vertex, ElementKind::edge, ElementKind::face, ElementKind::corner}) {
    if (kind == to_string(k)) return k;
  }
  throw InvalidArgument("element kind must be vertex, edge, face or corner, not '" + kind + "'");
}

// A method on one element of kind H: the handle is checked, then f(mesh, handle) runs under the mesh's lock.
template <class H, class F>
auto on(std::string what, F f) {
  return [what, f](const MeshRef& self, Index i) {
    return to_py(self.read([&](const Mesh& m) { return f(m, live_handle<H>(m, i, what.c_str())); }));
  };
}

// The polygons (live faces that are neither holes nor point spheres' faces) in face handle order, as lists
// of vertex handles: offsets (one more than the polygons) or indices.
std::vector<std::uint32_t> polygon_lists(const Mesh& m, bool offsets) {
  std::vector<std::uint32_t> out(offsets ? 1 : 0, 0);
  std::uint32_t end = 0;
  for (FaceId f : m.faces()) {
    if (m.is_hole(f) || m.size(f) < 2) continue;
    end += m.size(f);
    if (offsets) {
      out.push_back(end);
    } else {
      for (CornerId c : m.corners(f)) out.push_back(m.vertex(c).index());
    }
  }
  return out;
}

// The values of an attribute by handle, copied under the lock; made into an array after it (bool as uint8).
using AttributeCopy =
    std::variant<std::vector<std::uint8_t>, std::vector<int>, std::vector<double>, std::vector<glm::dvec3>>;

template <class H, class T>
AttributeCopy attribute_values(const Mesh& m, const std::string& name) {
  const auto values = m.attribute<H, T>(name);
  std::vector<std::conditional_t<std::is_same_v<T, bool>, std::uint8_t, T>> out(
      m.capacity(element_kind_v<H>));
  for (std::size_t i = 0; i < out.size(); ++i) out[i] = values[H(std::uint32_t(i))];
  return out;
}

template <class H>
AttributeCopy attribute_of_kind(const Mesh& m, const std::string& name, AttributeType type) {
  switch (type) {
    case AttributeType::boolean:
      return attribute_values<H, bool>(m, name);
    case AttributeType::integer:
      return attribute_values<H, int>(m, name);
    case AttributeType::number:
      return attribute_values<H, double>(m, name);
    case AttributeType::point:
      break;
  }
  return attribute_values<H, glm::dvec3>(m, name);
}

AttributeCopy attribute(const Mesh& m, const std::string& kind_name, const std::string& name) {
  const ElementKind kind = kind_of(kind_name);
  for (const AttributeInfo& a : m.attributes()) {
    if (a.kind != kind || a.name != name) continue;
    switch (kind) {
      case ElementKind::vertex:
        return attribute_of_kind<VertexId>(m, name, a.type);
      case ElementKind::edge:
        return attribute_of_kind<EdgeId>(m, name, a.type);
      case ElementKind::face:
        return attribute_of_kind<FaceId>(m, name, a.type);
      case ElementKind::corner:
        break;
    }
    return attribute_of_kind<CornerId>(m, name, a.type);
  }
  throw InvalidArgument("attribute: the " + kind_name + "s have no attribute '" + name + "'");
}

py::array attribute_array(AttributeCopy values) {
  return std::visit(
      [](auto& v) -> py::array {
        using T = typename std::decay_t<decltype(v)>::value_type;
        if constexpr (std::is_same_v<T, glm::dvec3>) {
          return owned_points(std::move(v));
        } else {
          py::array_t<std::conditional_t<std::is_same_v<T, std::uint8_t>, bool, T>> out(
              py::ssize_t(v.size()));
          if (!v.empty()) std::memcpy(out.mutable_data(), v.data(), v.size() * sizeof(T));
          return out;
        }
      },
      values);
}

py::object attribute_value(const AttributeValue& v) {
  return std::visit(
      [](const auto& x) -> py::object {
        if constexpr (std::is_same_v<std::decay_t<decltype(x)>, glm::dvec3>) {
          return point(x);
        } else {
          return py::cast(x);
        }
      },
      v);
}

py::list attributes(const std::vector<AttributeInfo>& infos) {
  py::list out;
  for (const AttributeInfo& a : infos) {
    py::dict d;
    d["name"] = a.name;
    d["kind"] = to_string(a.kind);
    d["type"] = to_string(a.type);
    d["default"] = attribute_value(a.default_value);
    out.append(d);
  }
  return out;
}

py::dict report(const ValidationReport& r) {
  using namespace pybind11::literals;
  py::list violations, components;
  for (const Violation& v : r.violations) {
    violations.append(
        py::dict("code"_a = to_string(v.code), "element"_a = v.element, "message"_a = v.message));
  }
  for (const ComponentInfo& c : r.components) {
    components.append(py::dict("vertices"_a = c.vertices, "edges"_a = c.edges, "faces"_a = c.faces,
                               "holes"_a = c.holes, "euler_characteristic"_a = c.euler_characteristic,
                               "genus"_a = c.genus));
  }
  return py::dict("valid"_a = r.valid(), "violation_count"_a = r.violation_count, "violations"_a = violations,
                  "components"_a = components);
}

// The argument's name in signatures: v, e, f or c.
template <class H>
const char* argument_name() {
  constexpr const char* names[] = {"v", "e", "f", "c"};
  return names[std::size_t(element_kind_v<H>)];
}

// A method on one element of kind H: mesh.NAME(h) runs `f` on the checked handle.
template <class H, class R>
struct ElementMethod {
  const char* name;
  R (*f)(const Mesh&, H);
  const char* doc;
};

template <class H, class R, std::size_t N>
void bind_methods(py::class_<MeshRef>& c, const ElementMethod<H, R> (&methods)[N]) {
  for (const ElementMethod<H, R>& m : methods)
    c.def(m.name, on<H>(m.name, m.f), m.doc, py::arg(argument_name<H>()));
}

std::uint32_t opposite_corner(const Mesh& m, CornerId k) {
  if (!m.edge(k).valid()) {
    throw InvalidArgument("opposite: " + to_string(k) + " is a point sphere's corner, which has no edge");
  }
  return m.opposite(k).index();
}

// Navigation and geometry, by the kind of element they start from and what they give.
const ElementMethod<CornerId, std::uint32_t> corner_steps[] = {
    {"vertex", [](const Mesh& m, CornerId k) { return m.vertex(k).index(); }, "The vertex of corner c."},
    {"face", [](const Mesh& m, CornerId k) { return m.face(k).index(); }, "The face of corner c."},
    {"next", [](const Mesh& m, CornerId k) { return m.next(k).index(); },
     "The next corner along the face (counter-clockwise seen from outside)."},
    {"prev", [](const Mesh& m, CornerId k) { return m.prev(k).index(); },
     "The previous corner along the face."},
    {"opposite", opposite_corner, "The corner on the other side of edge(c): it starts at vertex(next(c))."},
    {"next_around_vertex", [](const Mesh& m, CornerId k) { return m.next_around_vertex(k).index(); },
     "The next corner around vertex(c), turning clockwise seen from outside."},
    {"prev_around_vertex", [](const Mesh& m, CornerId k) { return m.prev_around_vertex(k).index(); },
     "The previous corner around vertex(c), turning counter-clockwise."},
};
const ElementMethod<VertexId, std::uint32_t> vertex_numbers[] = {
    {"corner", [](const Mesh& m, VertexId v) { return m.corner(v).index(); },
     "The representative corner of vertex v, where rotation around it starts."},
    {"valence", [](const Mesh& m, VertexId v) { return m.valence(v); },
     "The number of edges at vertex v (0 for a point sphere)."},
};
const ElementMethod<FaceId, std::uint32_t> face_numbers[] = {
    {"first_corner", [](const Mesh& m, FaceId f) { return m.first_corner(f).index(); },
     "The corner where iteration around face f starts."},
    {"face_size", [](const Mesh& m, FaceId f) { return m.size(f); },
     "The number of corners of face f (1 for a point sphere, 2 for a 2-gon)."},
};
// The ranges around a vertex or a face (mesh.h, navigation.h) as handle arrays: KIND_corners,
// KIND_neighbours, KIND_edges, and vertex_faces or face_vertices.
template <class H>
void bind_ranges(py::class_<MeshRef>& c, const std::array<const char*, 4>& docs) {
  constexpr bool vertex = std::is_same_v<H, VertexId>;
  using Range = std::vector<std::uint32_t> (*)(const Mesh&, H);
  const Range ranges[] = {
      [](const Mesh& m, H h) { return handles(m.corners(h)); },
      [](const Mesh& m, H h) { return handles(neighbours(m, h)); },
      [](const Mesh& m, H h) { return handles(edges(m, h)); },
      [](const Mesh& m, H h) {
        if constexpr (vertex) return handles(faces(m, h));
        if constexpr (!vertex) return handles(vertices(m, h));
      },
  };
  const char* kinds[] = {"corners", "neighbours", "edges", vertex ? "faces" : "vertices"};
  for (std::size_t i = 0; i < 4; ++i) {
    const std::string name = std::string(to_string(element_kind_v<H>)) + "_" + kinds[i];
    c.def(name.c_str(), on<H>(name, ranges[i]), docs[i], py::arg(argument_name<H>()));
  }
}

const ElementMethod<VertexId, glm::dvec3> vertex_points[] = {
    {"position", [](const Mesh& m, VertexId v) { return m.position(v); },
     "The position of vertex v, (x, y, z)."},
    {"vertex_normal", [](const Mesh& m, VertexId v) { return vertex_normal(m, v); },
     "The area-weighted average normal of the faces around v that are not holes (zero if none)."},
};
const ElementMethod<FaceId, glm::dvec3> face_points[] = {
    {"face_normal", [](const Mesh& m, FaceId f) { return face_normal(m, f); },
     "The unit normal of face f (Newell's method); zero for a degenerate face."},
    {"face_centroid", [](const Mesh& m, FaceId f) { return face_centroid(m, f); },
     "The average of the positions of the corners of face f."},
};
const ElementMethod<VertexId, bool> vertex_tests[] = {
    {"is_point_sphere", [](const Mesh& m, VertexId v) { return m.is_point_sphere(v); },
     "True for a vertex without edges."},
    {"is_boundary_vertex", [](const Mesh& m, VertexId v) { return is_boundary(m, v); },
     "True if a hole face is around vertex v."},
};
const ElementMethod<EdgeId, bool> edge_tests[] = {
    {"is_boundary_edge", [](const Mesh& m, EdgeId e) { return is_boundary(m, e); },
     "True if a hole face is on either side of edge e."},
};
const ElementMethod<FaceId, bool> face_tests[] = {
    {"is_hole", [](const Mesh& m, FaceId f) { return m.is_hole(f); },
     "True for a hole face (a boundary loop of an open mesh)."},
};
const ElementMethod<CornerId, std::optional<std::uint32_t>> corner_edges[] = {
    {"edge", [](const Mesh& m, CornerId k) { return handle_or_none(m.edge(k)); },
     "The edge leaving corner c along its face, from vertex(c) to vertex(next(c)); None for a point sphere's "
     "corner."},
};
const ElementMethod<EdgeId, std::pair<std::uint32_t, std::uint32_t>> edge_ends[] = {
    {"edge_vertices", [](const Mesh& m, EdgeId e) { return std::pair(m.from(e).index(), m.to(e).index()); },
     "The two vertices of edge e, (from, to): side 0 runs from the first to the second."},
};
const ElementMethod<FaceId, double> face_areas[] = {
    {"face_area", [](const Mesh& m, FaceId f) { return face_area(m, f); },
     "The area of face f (half the length of its Newell vector)."},
};

// A method on two elements: mesh.NAME(a, b) runs `f` on the checked handles; None for the invalid handle.
template <class A, class B, class F>
auto between(const char* what, F f) {
  return [what, f](const MeshRef& self, Index a, Index b) {
    return self.read([&](const Mesh& m) {
      return handle_or_none(f(m, live_handle<A>(m, a, what), live_handle<B>(m, b, what)));
    });
  };
}

// What an edge has on side 0 or 1: its corner or its face.
template <class F>
auto on_side(const char* what, F f) {
  return [what, f](const MeshRef& self, Index e, Index side) {
    return self.read([&](const Mesh& m) {
      const EdgeId h = live_handle<EdgeId>(m, e, what);
      if (side != 0 && side != 1) throw InvalidArgument(std::string(what) + ": side must be 0 or 1");
      return f(m, h, int(side));
    });
  };
}

void bind_navigation(py::class_<MeshRef>& c) {
  bind_methods(c, corner_steps);
  bind_methods(c, corner_edges);
  bind_methods(c, vertex_numbers);
  bind_methods(c, face_numbers);
  bind_ranges<VertexId>(
      c, {"The corners at vertex v, from its representative corner, turning clockwise seen from outside.",
          "The vertices joined to v by an edge, one per edge, in the order of vertex_corners.",
          "The edges at vertex v, in the order of vertex_neighbours.",
          "The faces around vertex v, one per corner, in the order of vertex_corners."});
  bind_ranges<FaceId>(c, {"The corners of face f, from its first corner along next.",
                          "The faces across the edges of face f, in the order of face_edges.",
                          "The edges of face f; edge i runs from vertex i to vertex i + 1 of face_vertices.",
                          "The vertices of face f, counter-clockwise seen from outside."});
  bind_methods(c, vertex_points);
  bind_methods(c, face_points);
  bind_methods(c, vertex_tests);
  bind_methods(c, edge_tests);
  bind_methods(c, face_tests);
  bind_methods(c, edge_ends);
  bind_methods(c, face_areas);
  c.def("edge_corner",
        on_side("edge_corner", [](const Mesh& m, EdgeId e, int side) { return m.corner(e, side).index(); }),
        "The corner where edge e starts on side 0 (from its first vertex) or side 1.", py::arg("e"),
        py::arg("side"));
  c.def("edge_face",
        on_side("edge_face", [](const Mesh& m, EdgeId e, int side) { return m.face(e, side).index(); }),
        "The face on side 0 or 1 of edge e.", py::arg("e"), py::arg("side"));
  c.def("find_edge", between<VertexId, VertexId>("find_edge", find_edge),
        "An edge between vertices u and v, or None.", py::arg("u"), py::arg("v"));
  c.def("corner_in_face", between<VertexId, FaceId>("corner_in_face", corner_in_face),
        "The corner of vertex v in face f, or None if f does not visit v.", py::arg("v"), py::arg("f"));
}

}  // namespace

void bind_mesh(py::module_& m) {
  py::class_<MeshRef> c(
      m, "Mesh",
      R"doc(A closed orientable 2-manifold in DLFL form (open meshes have a hole face per boundary loop).

A Mesh made by from_arrays, read_mesh, subdivide or copy never changes, so its arrays (positions) view its
storage without copying. An editor's current mesh (Editor.mesh) is live: it follows the editor's
operations, and its arrays are copies. Handles are ints: a vertex, edge, face or corner is named by its index,
stable until the mesh is compacted; arrays indexed by handle have a row per slot ever assigned (capacity),
removed ones included.)doc");
  c.def(py::init([] { return MeshRef(Mesh()); }), "An empty mesh.");
  c.def_static(
      "from_arrays",
      [](py::handle positions, py::handle faces) {
        PolygonSoup soup;
        read_indexed_lists(
            soup, positions, faces, "Mesh.from_arrays", [](std::size_t f, const std::string& why) {
              throw PolygonError(PolygonError::Element::face, f, "face " + std::to_string(f) + ": " + why);
            });
        py::gil_scoped_release no_gil;
        return MeshRef(build_mesh(soup));
      },
      R"doc(The mesh of a polygon list: positions an (n, 3) array; faces a list of index lists, an (F, k) integer
array of k-gons, or a tuple (offsets, indices) with face i = indices[offsets[i]:offsets[i + 1]]. Faces are
counter-clockwise seen from outside. Vertex i is handle i, face i is handle i, and the corner of the j-th
vertex of face i is handle offsets[i] + j; each boundary loop becomes a hole face, each unused vertex a point
sphere. Raises PolygonError (element, index) for a face or vertex that is not a 2-manifold's.)doc",
      py::arg("positions"), py::arg("faces"));
  c.def(
      "copy", [](const MeshRef& self) { return MeshRef(self.snapshot()); },
      "A mesh of its own with the same content (of a live mesh: as it is now).");
  c.def(
      "compacted",
      [](const MeshRef& self) {
        Mesh copy = *self.snapshot();
        copy.compact();
        return MeshRef(std::move(copy));
      },
      "A copy without removed elements, the live ones renumbered densely in the same order.");
  c.def_property_readonly("live", &MeshRef::live,
                          "True for an editor's current mesh, which follows the editor's operations.");

  const auto count = [](std::size_t (Mesh::*f)() const) {
    return [f](const MeshRef& self) { return self.read([f](const Mesh& mesh) { return (mesh.*f)(); }); };
  };
  c.def_property_readonly("num_vertices", count(&Mesh::num_vertices), "Live vertices.");
  c.def_property_readonly("num_edges", count(&Mesh::num_edges), "Live edges.");
  c.def_property_readonly("num_faces", count(&Mesh::num_faces),
                          "Live faces: surface faces, hole faces and point spheres' faces.");
  c.def_property_readonly("num_hole_faces", count(&Mesh::num_hole_faces), "Live hole faces.");
  c.def_property_readonly("num_surface_faces", count(&Mesh::num_surface_faces),
                          "Live faces that are not holes.");
  c.def_property_readonly("num_corners", count(&Mesh::num_corners), "Live corners.");
  c.def(
      "capacity",
      [](const MeshRef& self, const std::string& kind) {
        return self.read([&](const Mesh& mesh) { return mesh.capacity(kind_of(kind)); });
      },
      "One past the largest handle ever assigned to a 'vertex', 'edge', 'face' or 'corner'.",
      py::arg("kind"));
  c.def(
      "is_alive",
      [](const MeshRef& self, const std::string& kind, Index i) {
        return self.read([&](const Mesh& mesh) {
          return i >= 0 && i < std::int64_t(VertexId::invalid_index) &&
                 mesh.is_alive(kind_of(kind), std::uint32_t(i));
        });
      },
      "True if handle is a live element of that kind ('vertex', 'edge', 'face', 'corner').", py::arg("kind"),
      py::arg("handle"));

  c.def_property_readonly(
      "positions",
      [](const MeshRef& self) {
        const auto first = [](const Mesh& mesh) {
          return mesh.vertex_capacity() ? &mesh.position(VertexId(0)) : nullptr;
        };
        if (!self.live()) {  // nothing changes this mesh: a view of its storage
          return point_view(first(*self.owned()), self.owned()->vertex_capacity(), view_owner(self));
        }
        return owned_points(self.read([&](const Mesh& mesh) {
          return std::vector<glm::dvec3>(first(mesh), first(mesh) + mesh.vertex_capacity());
        }));
      },
      "The vertex positions, an (capacity, 3) float64 array indexed by vertex handle (rows of removed "
      "vertices are stale). A read-only view of the mesh's storage, no copy; a copy for a live mesh.");
  // The polygons (live faces but holes and point spheres' faces, in handle order), as offsets and indices.
  for (const bool offsets : {true, false}) {
    c.def_property_readonly(
        offsets ? "faces_offsets" : "faces_indices",
        [offsets](const MeshRef& self) {
          return to_py(self.read([offsets](const Mesh& mesh) { return polygon_lists(mesh, offsets); }));
        },
        offsets ? "The polygons (live faces but holes and point spheres' faces, in handle order): polygon i "
                  "is faces_indices[faces_offsets[i]:faces_offsets[i + 1]]. uint32."
                : "The vertex handles of the polygons, one per corner (see faces_offsets). uint32.");
  }
  c.def(
      "to_arrays",
      [](const MeshRef& self) {
        PolygonSoup soup = self.read_without_gil([](const Mesh& mesh) { return to_polygons(mesh); });
        return py::make_tuple(
            owned_points(std::move(soup.positions)),
            py::make_tuple(owned_array(std::move(soup.offsets)), owned_array(std::move(soup.indices))));
      },
      "(positions, (offsets, indices)): the polygons as a polygon file holds them, vertices renumbered "
      "densely (Mesh.from_arrays(*mesh.to_arrays()) rebuilds the mesh). Raises TopologyError for a 2-gon or "
      "a double edge, which a polygon list cannot hold.");

  using AllOfKind = std::vector<std::uint32_t> (*)(const Mesh&);
  const std::tuple<const char*, AllOfKind, const char*> all_of_kind[] = {
      {"vertices", [](const Mesh& m) { return handles(m.vertices()); },
       "The live vertex handles, in increasing order."},
      {"edges", [](const Mesh& m) { return handles(m.edges()); },
       "The live edge handles, in increasing order."},
      {"faces", [](const Mesh& m) { return handles(m.faces()); },
       "The live face handles (holes included), in increasing order."},
      {"surface_faces", [](const Mesh& m) { return handles(surface_faces(m)); },
       "The live faces that are not holes, in increasing order."},
  };
  for (const auto& [name, all, doc] : all_of_kind) {
    c.def(
        name, [all](const MeshRef& self) { return to_py(self.read(all)); }, doc);
  }
  c.def(
      "corners",
      [](const MeshRef& self, std::optional<Index> face) {
        return to_py(self.read([&](const Mesh& mesh) {
          return face ? handles(mesh.corners(live_handle<FaceId>(mesh, *face, "corners")))
                      : handles(mesh.corners());
        }));
      },
      "The corners of a face, from its first corner along next; without a face, every live corner.",
      py::arg("face") = py::none());
  bind_navigation(c);

  c.def(
      "attributes",
      [](const MeshRef& self) {
        return attributes(self.read([](const Mesh& mesh) { return mesh.attributes(); }));
      },
      "The named attributes: a list of {'name', 'kind', 'type', 'default'}, sorted by kind and name.");
  c.def(
      "attribute",
      [](const MeshRef& self, const std::string& kind, const std::string& name) {
        return attribute_array(self.read([&](const Mesh& mesh) { return attribute(mesh, kind, name); }));
      },
      "The values of a named attribute on the 'vertex', 'edge', 'face' or 'corner' elements, indexed by "
      "handle (capacity rows): bool, int32, float64, or (capacity, 3) float64 for points. A copy.",
      py::arg("kind"), py::arg("name"));
  c.def(
      "hash",
      [](const MeshRef& self) {
        return self.read_without_gil([](const Mesh& mesh) { return mesh_hash(mesh); });
      },
      "The mesh's digest (32 hex digits): equal meshes have equal hashes; it covers handles, links, "
      "positions bit for bit and attributes.");
  c.def(
      "__eq__",
      [](const MeshRef& self, const MeshRef& other) {
        const auto a = self.snapshot(), b = other.snapshot();
        return *a == *b;
      },
      py::is_operator());
  c.def("__repr__", [](const MeshRef& self) {
    return self.read([&](const Mesh& mesh) {
      return std::string(self.live() ? "<dlfl.Mesh (live) " : "<dlfl.Mesh ") +
             std::to_string(mesh.num_vertices()) + " vertices, " + std::to_string(mesh.num_edges()) +
             " edges, " + std::to_string(mesh.num_faces()) + " faces>";
    });
  });

  m.def(
      "validate",
      [](const MeshRef& mesh, std::size_t max_violations) {
        return report(mesh.read_without_gil([&](const Mesh& x) { return validate(x, max_violations); }));
      },
      R"doc(The consistency checker's report: {'valid', 'violation_count', 'violations': [{'code', 'element',
'message'}] (at most max_violations), 'components': [{'vertices', 'edges', 'faces', 'holes',
'euler_characteristic', 'genus'}]} (components only when the structure is sound; faces count holes).)doc",
      py::arg("mesh"), py::arg("max_violations") = 100);
  m.def(
      "info",
      [](const MeshRef& mesh, bool angles, bool shape) {
        return from_json(mesh.read_without_gil([&](const Mesh& x) {
          return mesh_info_json(x, {.angles = angles, .shape = shape, .indent = -1});
        }));
      },
      R"doc(What `dlfl info` prints, as a dict: counts of the open surface (vertices, edges, faces, corners, holes,
point_spheres), components, euler_characteristic, genus (a list, per component), valid, face_sizes and
valences (histograms keyed by strings), bbox, hash; with angles=True also 'angles' (degrees) and convexity;
with shape=True, for a closed mesh, 'concave_edges' and 'worst_concave_degrees' (docs/lateral_artifacts.md).)doc",
      py::arg("mesh"), py::arg("angles") = false, py::arg("shape") = false);
}

}  // namespace dlfl::python
