#include <dlfl/io/json_mesh.h>

#include <array>
#include <cmath>
#include <limits>
#include <variant>

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

// JSON has no NaN or infinity: a NaN number is null, an infinite one the string "inf" or "-inf".
nlohmann::json number(double x) {
  if (std::isnan(x)) return nullptr;
  if (std::isinf(x)) return x > 0 ? "inf" : "-inf";
  return x;
}

nlohmann::json value_json(const AttributeValue& value) {
  return std::visit(
      [](const auto& x) -> nlohmann::json {
        using T = std::decay_t<decltype(x)>;
        if constexpr (std::is_same_v<T, glm::dvec3>) {
          return nlohmann::json{number(x.x), number(x.y), number(x.z)};
        } else if constexpr (std::is_same_v<T, double>) {
          return number(x);
        } else {
          return x;
        }
      },
      value);
}

// Whether slot i of an element kind holds a live element, from the arrays.
bool slot_alive(const MeshArrays& a, ElementKind kind, std::size_t i) {
  switch (kind) {
    case ElementKind::vertex:
      return a.vertices[i].corner.valid();
    case ElementKind::edge:
      return a.edges[i].corner0.valid();
    case ElementKind::face:
      return a.faces[i].alive;
    case ElementKind::corner:
      break;
  }
  return a.corners[i].vertex.valid();
}

std::size_t slot_count(const MeshArrays& a, ElementKind kind) {
  switch (kind) {
    case ElementKind::vertex:
      return a.vertices.size();
    case ElementKind::edge:
      return a.edges.size();
    case ElementKind::face:
      return a.faces.size();
    case ElementKind::corner:
      break;
  }
  return a.corners.size();
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

  // A double as `number` writes it.
  double number_at(const nlohmann::json& x, const std::string& field) const {
    if (x.is_null()) return std::numeric_limits<double>::quiet_NaN();
    if (x.is_number()) return x.get<double>();
    if (x == "inf") return std::numeric_limits<double>::infinity();
    if (x == "-inf") return -std::numeric_limits<double>::infinity();
    fail(field, "expected a number, null (NaN), \"inf\" or \"-inf\"");
  }

  // A value of type `type` as `value_json` writes it.
  AttributeValue value_at(const nlohmann::json& x, AttributeType type, const std::string& field) const {
    switch (type) {
      case AttributeType::boolean:
        if (!x.is_boolean()) fail(field, "expected true or false");
        return x.get<bool>();
      case AttributeType::integer:
        if (!x.is_number_integer() || x.get<long long>() < std::numeric_limits<int>::min() ||
            x.get<long long>() > std::numeric_limits<int>::max()) {
          fail(field, "expected a 32-bit integer");
        }
        return static_cast<int>(x.get<long long>());
      case AttributeType::number:
        return number_at(x, field);
      case AttributeType::point:
        break;
    }
    if (!x.is_array() || x.size() != 3) fail(field, "expected [x, y, z]");
    return glm::dvec3(number_at(x[0], field + "[0]"), number_at(x[1], field + "[1]"),
                      number_at(x[2], field + "[2]"));
  }

  // A string that names one of `names` (indexed by enum value).
  template <class E, std::size_t N>
  E name_at(const nlohmann::json& entry, const char* key, const std::string& field,
            const std::array<E, N>& values) const {
    auto it = entry.find(key);
    if (it != entry.end() && it->is_string()) {
      for (E e : values) {
        if (*it == to_string(e)) return e;
      }
    }
    std::string expected;
    for (E e : values) expected += std::string(expected.empty() ? "" : ", ") + "\"" + to_string(e) + "\"";
    fail(field + "." + key, "expected one of " + expected);
  }

  MeshArrays::Attribute attribute_at(const nlohmann::json& entry, const std::string& field,
                                     const MeshArrays& a) const {
    if (!entry.is_object()) fail(field, "expected an object");
    MeshArrays::Attribute at;
    auto name = entry.find("name");
    if (name == entry.end() || !name->is_string() || name->get<std::string>().empty())
      fail(field + ".name", "expected a non-empty string");
    at.name = name->get<std::string>();
    at.kind =
        name_at(entry, "element", field,
                std::array{ElementKind::vertex, ElementKind::edge, ElementKind::face, ElementKind::corner});
    const AttributeType type = name_at(entry, "type", field,
                                       std::array{AttributeType::boolean, AttributeType::integer,
                                                  AttributeType::number, AttributeType::point});
    auto default_value = entry.find("default");
    if (default_value == entry.end()) fail(field + ".default", "missing");
    at.default_value = value_at(*default_value, type, field + ".default");
    auto values = entry.find("values");
    const std::size_t slots = slot_count(a, at.kind);
    if (values == entry.end() || !values->is_array() || values->size() != slots) {
      fail(field + ".values", "expected an array with one entry per " + std::string(to_string(at.kind)) +
                                  " slot (" + std::to_string(slots) + ")");
    }
    at.values.reserve(slots);
    for (std::size_t i = 0; i < slots; ++i) {
      const auto& x = (*values)[i];
      const std::string where = field + ".values[" + std::to_string(i) + "]";
      if (!slot_alive(a, at.kind, i)) {
        if (!x.is_null()) fail(where, "a removed element's value must be null");
        at.values.push_back(at.default_value);
      } else {
        at.values.push_back(value_at(x, type, where));
      }
    }
    return at;
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
  // Attributes only when the mesh has any, so documents of meshes without them stay as they were.
  if (!a.attributes.empty()) {
    auto& attributes = doc["attributes"] = nlohmann::json::array();
    for (const auto& at : a.attributes) {
      nlohmann::json values = nlohmann::json::array();
      for (std::size_t i = 0; i < at.values.size(); ++i)
        values.push_back(slot_alive(a, at.kind, i) ? value_json(at.values[i]) : nlohmann::json());
      attributes.push_back({{"name", at.name},
                            {"element", to_string(at.kind)},
                            {"type", to_string(type_of(at.default_value))},
                            {"default", value_json(at.default_value)},
                            {"values", std::move(values)}});
    }
  }
  return doc;
}

namespace {

// The arrays of a document, every field checked but the structure not yet validated.
MeshArrays arrays_from_json(const nlohmann::json& doc, const std::string& name) {
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
                    static_cast<std::uint32_t>(size.get<long long>()), true, (*e)[2] != 0};
    }
  }
  if (auto attributes = doc.find("attributes"); attributes != doc.end()) {
    if (!attributes->is_array()) r.fail("attributes", "expected an array");
    for (std::size_t i = 0; i < attributes->size(); ++i)
      a.attributes.push_back(r.attribute_at((*attributes)[i], "attributes[" + std::to_string(i) + "]", a));
  }
  // The form written before attributes existed: the Zhang-Wang control points, now the "face_point"
  // attribute (a point, NaN when unset).
  if (auto points = doc.find("face_points"); points != doc.end()) {
    if (!points->is_array() || points->size() != faces.size()) {
      r.fail("face_points", "expected an array with one entry per face slot");
    }
    constexpr double nan = std::numeric_limits<double>::quiet_NaN();
    MeshArrays::Attribute at{"face_point", ElementKind::face, glm::dvec3(nan), {}};
    at.values.assign(faces.size(), at.default_value);
    for (std::size_t i = 0; i < points->size(); ++i) {
      const auto& e = (*points)[i];
      if (e.is_null()) continue;
      const std::string field = "face_points[" + std::to_string(i) + "]";
      if (!a.faces[i].alive) r.fail(field, "a removed face has no control point");
      if (!e.is_array() || e.size() != 3 || !e[0].is_number() || !e[1].is_number() || !e[2].is_number()) {
        r.fail(field, "expected [x, y, z] or null");
      }
      at.values[i] = glm::dvec3(e[0].get<double>(), e[1].get<double>(), e[2].get<double>());
    }
    a.attributes.push_back(std::move(at));
  }
  return a;
}

}  // namespace

Mesh mesh_from_json(const nlohmann::json& doc, const std::string& name) {
  const MeshArrays a = arrays_from_json(doc, name);
  try {
    return a.to_mesh();
  } catch (const TopologyError& e) {
    throw IoError(e.what(), name);
  }
}

nlohmann::json value_to_json(const Value& v) {
  const auto point = [](const glm::dvec3& p) { return nlohmann::json{p.x, p.y, p.z}; };
  switch (v.kind()) {
    case Value::Kind::empty:
      return nullptr;
    case Value::Kind::boolean:
      return v.as_bool();
    case Value::Kind::integer:
      return v.as_integer();
    case Value::Kind::number:
      return v.as_number();
    case Value::Kind::text:
      return v.as_text();
    case Value::Kind::point:
      return point(v.as_point());
    case Value::Kind::integers:
      return v.as_integers();
    case Value::Kind::numbers:
      return v.as_numbers();
    case Value::Kind::points: {
      nlohmann::json list = nlohmann::json::array();
      for (const auto& p : v.as_points()) list.push_back(point(p));
      return list;
    }
    case Value::Kind::mesh:
      return mesh_to_json(v.as_mesh());
    case Value::Kind::params: {
      nlohmann::json object = nlohmann::json::object();
      for (const auto& [name, value] : v.as_params()) object[name] = value_to_json(value);
      return object;
    }
  }
  return nullptr;
}

ValidationReport validate_json_mesh(const nlohmann::json& doc, const std::string& name,
                                    std::size_t max_violations) {
  const MeshArrays a = arrays_from_json(doc, name);
  try {
    return a.validate(max_violations);
  } catch (const TopologyError& e) {
    throw IoError(e.what(), name);
  }
}

}  // namespace dlfl
