#include <dlfl/io/json_mesh.h>

#include <dlfl/errors.h>
#include <dlfl/mesh_arrays.h>

namespace dlfl {
namespace {

constexpr const char* format_name = "dlfl-mesh";
constexpr int format_version = 1;

// Handles are written as integers, an invalid handle as -1.
template <class H>
nlohmann::json handle(H h) {
  return h.valid() ? nlohmann::json(h.index()) : nlohmann::json(-1);
}

class Reader {
 public:
  Reader(const nlohmann::json& doc, const std::string& name) : doc_(doc), name_(name) {}

  [[noreturn]] void fail(const std::string& field, const std::string& what) const {
    throw IoError("field '" + field + "': " + what, name_);
  }

  const nlohmann::json& array(const char* key) const {
    auto it = doc_.find(key);
    if (it == doc_.end()) fail(key, "missing");
    if (!it->is_array()) fail(key, "expected an array");
    return *it;
  }

  // Element `i` of array `key`: null (a removed slot) or an array of `n` numbers.
  const nlohmann::json* slot(const nlohmann::json& a, const char* key, std::size_t i, std::size_t n) const {
    const nlohmann::json& e = a[i];
    if (e.is_null()) return nullptr;
    if (!e.is_array() || e.size() != n) {
      fail(std::string(key) + "[" + std::to_string(i) + "]",
           "expected null or an array of " + std::to_string(n));
    }
    for (std::size_t k = 0; k < n; ++k) {
      if (!e[k].is_number()) {
        fail(std::string(key) + "[" + std::to_string(i) + "][" + std::to_string(k) + "]",
             "expected a number");
      }
    }
    return &e;
  }

  template <class H>
  H handle_at(const nlohmann::json& e, std::size_t k, const char* key, std::size_t i) const {
    const nlohmann::json& x = e[k];
    if (x.is_number_integer() && x.get<long long>() == -1) return H();
    // Signed or unsigned integers alike (nlohmann::json keeps the two apart).
    if (!x.is_number_integer() || x.get<long long>() < 0 || x.get<long long>() >= H::invalid_index) {
      fail(std::string(key) + "[" + std::to_string(i) + "][" + std::to_string(k) + "]",
           "expected a handle or -1");
    }
    return H(static_cast<std::uint32_t>(x.get<long long>()));
  }

 private:
  const nlohmann::json& doc_;
  const std::string& name_;
};

}  // namespace

nlohmann::json mesh_to_json(const Mesh& mesh) {
  const MeshArrays a = MeshArrays::from(mesh);
  nlohmann::json doc;
  doc["format"] = format_name;
  doc["version"] = format_version;
  auto& vertices = doc["vertices"] = nlohmann::json::array();
  for (const auto& v : a.vertices) {
    vertices.push_back(v.corner.valid()
                           ? nlohmann::json{v.position.x, v.position.y, v.position.z, handle(v.corner)}
                           : nlohmann::json());
  }
  auto& corners = doc["corners"] = nlohmann::json::array();
  for (const auto& c : a.corners) {
    corners.push_back(c.vertex.valid() ? nlohmann::json{handle(c.vertex), handle(c.face), handle(c.next),
                                                        handle(c.prev), handle(c.edge)}
                                       : nlohmann::json());
  }
  auto& edges = doc["edges"] = nlohmann::json::array();
  for (const auto& e : a.edges) {
    edges.push_back(e.corner0.valid() ? nlohmann::json{handle(e.corner0), handle(e.corner1)}
                                      : nlohmann::json());
  }
  auto& faces = doc["faces"] = nlohmann::json::array();
  for (const auto& f : a.faces) {
    faces.push_back(f.alive ? nlohmann::json{handle(f.corner), f.size, f.hole ? 1 : 0} : nlohmann::json());
  }
  // Control points only when the mesh has any, so documents of meshes without them stay as they were.
  if (mesh.has_face_points()) {
    auto& points = doc["face_points"] = nlohmann::json::array();
    for (const auto& f : a.faces) {
      points.push_back(f.alive && f.point ? nlohmann::json{f.point->x, f.point->y, f.point->z}
                                          : nlohmann::json());
    }
  }
  return doc;
}

Mesh mesh_from_json(const nlohmann::json& doc, const std::string& name) {
  Reader r(doc, name);
  if (!doc.is_object()) r.fail("(document)", "expected a JSON object");
  auto format = doc.find("format");
  if (format == doc.end() || !format->is_string() || *format != format_name) {
    r.fail("format", std::string("expected \"") + format_name + "\"");
  }
  auto version = doc.find("version");
  if (version == doc.end() || !version->is_number_integer()) r.fail("version", "missing or not an integer");
  if (*version != format_version) {
    r.fail("version", "unsupported version " + version->dump() + " (this library reads version 1)");
  }
  MeshArrays a;
  const auto& vertices = r.array("vertices");
  a.vertices.resize(vertices.size());
  for (std::size_t i = 0; i < vertices.size(); ++i) {
    if (const auto* e = r.slot(vertices, "vertices", i, 4)) {
      a.vertices[i].position = {(*e)[0].get<double>(), (*e)[1].get<double>(), (*e)[2].get<double>()};
      a.vertices[i].corner = r.handle_at<CornerId>(*e, 3, "vertices", i);
    }
  }
  const auto& corners = r.array("corners");
  a.corners.resize(corners.size());
  for (std::size_t i = 0; i < corners.size(); ++i) {
    if (const auto* e = r.slot(corners, "corners", i, 5)) {
      a.corners[i] = {r.handle_at<VertexId>(*e, 0, "corners", i), r.handle_at<FaceId>(*e, 1, "corners", i),
                      r.handle_at<CornerId>(*e, 2, "corners", i), r.handle_at<CornerId>(*e, 3, "corners", i),
                      r.handle_at<EdgeId>(*e, 4, "corners", i)};
    }
  }
  const auto& edges = r.array("edges");
  a.edges.resize(edges.size());
  for (std::size_t i = 0; i < edges.size(); ++i) {
    if (const auto* e = r.slot(edges, "edges", i, 2)) {
      a.edges[i] = {r.handle_at<CornerId>(*e, 0, "edges", i), r.handle_at<CornerId>(*e, 1, "edges", i)};
    }
  }
  const auto& faces = r.array("faces");
  a.faces.resize(faces.size());
  for (std::size_t i = 0; i < faces.size(); ++i) {
    if (const auto* e = r.slot(faces, "faces", i, 3)) {
      const auto& size = (*e)[1];
      if (!size.is_number_integer() || size.get<long long>() < 0 || size.get<long long>() >= 0xFFFFFFFFll) {
        r.fail("faces[" + std::to_string(i) + "][1]", "expected a face size");
      }
      a.faces[i] = {r.handle_at<CornerId>(*e, 0, "faces", i),
                    static_cast<std::uint32_t>(size.get<long long>()), true, (*e)[2] != 0, std::nullopt};
    }
  }
  if (auto points = doc.find("face_points"); points != doc.end()) {
    if (!points->is_array() || points->size() != faces.size()) {
      r.fail("face_points", "expected an array with one entry per face slot");
    }
    for (std::size_t i = 0; i < points->size(); ++i) {
      const auto& e = (*points)[i];
      if (e.is_null()) continue;
      const std::string field = "face_points[" + std::to_string(i) + "]";
      if (!a.faces[i].alive) r.fail(field, "a removed face has no control point");
      if (!e.is_array() || e.size() != 3 || !e[0].is_number() || !e[1].is_number() || !e[2].is_number()) {
        r.fail(field, "expected [x, y, z] or null");
      }
      a.faces[i].point = glm::dvec3(e[0].get<double>(), e[1].get<double>(), e[2].get<double>());
    }
  }
  try {
    return a.to_mesh();
  } catch (const TopologyError& e) {
    throw IoError(e.what(), name);
  }
}

}  // namespace dlfl
