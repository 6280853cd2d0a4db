#include <dlfl/history/oplog.h>

#include <cstdint>
#include <fstream>
#include <sstream>

#include <dlfl/io/atomic_file.h>
#include <dlfl/io/json_mesh.h>

namespace dlfl {
namespace {

std::string where(std::size_t op, const std::string& field) {
  if (op == LogError::npos) return "field '" + field + "'";
  return "op " + std::to_string(op) + ", field '" + field + "'";
}

// Typed access to one op's fields; every failure names the op index and the field.
class OpReader {
 public:
  OpReader(const nlohmann::json& op, std::size_t index, const std::string& name, const Mesh& mesh)
      : op_(op), index_(index), name_(name), mesh_(mesh) {}

  [[noreturn]] void fail(const std::string& field, const std::string& what) const {
    throw LogError(name_, index_, field, what);
  }

  const nlohmann::json& get(const char* field) const {
    auto it = op_.find(field);
    if (it == op_.end()) fail(field, "missing");
    return *it;
  }

  std::string text(const char* field) const {
    const auto& v = get(field);
    if (!v.is_string()) fail(field, "expected a string");
    return v.get<std::string>();
  }

  long long integer(const char* field) const {
    const auto& v = get(field);
    if (!v.is_number_integer()) fail(field, "expected an integer");
    return v.get<long long>();
  }

  glm::dvec3 point(const nlohmann::json& v, const std::string& field) const {
    if (!v.is_array() || v.size() != 3 || !v[0].is_number() || !v[1].is_number() || !v[2].is_number()) {
      fail(field, "expected [x, y, z]");
    }
    return {v[0].get<double>(), v[1].get<double>(), v[2].get<double>()};
  }
  glm::dvec3 point(const char* field) const { return point(get(field), field); }

  // A handle that must name a live element of the current mesh.
  template <class H>
  H handle(const char* field, const char* kind) const {
    const auto& v = get(field);
    // Integers written by hand in C++ are signed in nlohmann::json; parsed ones are unsigned: accept both.
    if (!v.is_number_integer() || v.get<long long>() < 0 || v.get<long long>() >= H::invalid_index) {
      fail(field, std::string("expected a ") + kind + " handle");
    }
    H h(static_cast<std::uint32_t>(v.get<long long>()));
    if (!mesh_.is_alive(h))
      fail(field, std::string(kind) + " " + to_string(h) + " does not exist at this point");
    return h;
  }

 private:
  const nlohmann::json& op_;
  std::size_t index_;
  const std::string& name_;
  const Mesh& mesh_;
};

SchemeParams params_from(const OpReader& r) {
  const auto& p = r.get("params");
  if (!p.is_object()) r.fail("params", "expected an object");
  SchemeParams params;
  for (const auto& [key, value] : p.items()) {
    if (value.is_boolean()) {
      params[key] = value.get<bool>();
    } else if (value.is_number_integer() &&
               !(value.is_number_unsigned() && value.get<std::uint64_t>() > std::uint64_t(INT64_MAX))) {
      params[key] = value.get<std::int64_t>();
    } else if (value.is_number()) {
      params[key] = value.get<double>();
    } else if (value.is_string()) {
      params[key] = value.get<std::string>();
    } else {
      r.fail("params." + key, "expected a boolean, a number or a string");
    }
  }
  return params;
}

void replay_op(Editor& editor, const nlohmann::json& op, std::size_t index, const std::string& name) {
  if (!op.is_object()) throw LogError(name, index, "op", "expected an object");
  OpReader r(op, index, name, editor.mesh());
  const std::string kind = r.text("op");
  try {
    if (kind == "load") {
      if (op.contains("mesh")) {
        editor.set_mesh(mesh_from_json(op["mesh"], name + " op " + std::to_string(index)));
      } else {
        editor.load(r.text("path"));
      }
    } else if (kind == "mesh") {
      editor.set_mesh(mesh_from_json(r.get("mesh"), name + " op " + std::to_string(index)));
    } else if (kind == "subdivide") {
      const long long iterations = r.integer("iterations");
      if (iterations < 0 || iterations > 64) r.fail("iterations", "expected 0 to 64");
      editor.subdivide(r.text("scheme"), params_from(r), static_cast<int>(iterations));
    } else if (kind == "create_vertex") {
      editor.create_vertex(r.point("position"));
    } else if (kind == "delete_vertex") {
      editor.delete_vertex(r.handle<VertexId>("vertex", "vertex"));
    } else if (kind == "insert_edge") {
      const CornerId c1 = r.handle<CornerId>("corner1", "corner");  // in field order: arguments have none
      const CornerId c2 = r.handle<CornerId>("corner2", "corner");
      editor.insert_edge(c1, c2);
    } else if (kind == "delete_edge") {
      editor.delete_edge(r.handle<EdgeId>("edge", "edge"));
    } else if (kind == "subdivide_edge") {
      const EdgeId e = r.handle<EdgeId>("edge", "edge");
      editor.subdivide_edge(e, r.point("position"));
    } else if (kind == "unsubdivide_edge") {
      editor.unsubdivide_edge(r.handle<VertexId>("vertex", "vertex"));
    } else if (kind == "set_position") {
      const VertexId v = r.handle<VertexId>("vertex", "vertex");
      editor.set_position(v, r.point("position"));
    } else if (kind == "set_face_point") {
      const FaceId f = r.handle<FaceId>("face", "face");
      if (r.get("position").is_null()) {
        editor.set_face_point(f, std::nullopt);
      } else {
        editor.set_face_point(f, r.point("position"));
      }
    } else if (kind == "create_face_manifold") {
      const auto& pts = r.get("positions");
      if (!pts.is_array()) r.fail("positions", "expected an array of [x, y, z]");
      std::vector<glm::dvec3> positions;
      for (std::size_t i = 0; i < pts.size(); ++i) {
        positions.push_back(r.point(pts[i], "positions[" + std::to_string(i) + "]"));
      }
      editor.create_face_manifold(positions);
    } else if (kind == "undo") {
      if (!editor.undo()) r.fail("op", "undo with nothing to undo");
    } else if (kind == "redo") {
      if (!editor.redo()) r.fail("op", "redo with nothing to redo");
    } else {
      r.fail("op", "unknown op '" + kind + "'");
    }
  } catch (const LogError&) {
    throw;
  } catch (const Error& e) {
    // The operator itself refused (a self-loop, a bad parameter, an unreadable file): name the op.
    throw LogError(name, index, "op", kind + ": " + e.what());
  }
}

}  // namespace

LogError::LogError(const std::string& name, std::size_t op, const std::string& field, const std::string& what)
    : IoError(where(op, field) + ": " + what, name), op_(op), field_(field) {}

Editor replay_log(const nlohmann::json& log, const std::string& name) {
  if (!log.is_object()) throw LogError(name, LogError::npos, "(document)", "expected a JSON object");
  auto format = log.find("format");
  if (format == log.end() || *format != "dlfl-oplog") {
    throw LogError(name, LogError::npos, "format", "expected \"dlfl-oplog\"");
  }
  auto version = log.find("version");
  if (version == log.end() || !version->is_number_integer()) {
    throw LogError(name, LogError::npos, "version", "missing or not an integer");
  }
  if (*version != 1) {
    throw LogError(name, LogError::npos, "version",
                   "unsupported version " + version->dump() + " (this library reads version 1)");
  }
  Editor::Options options;
  if (auto limit = log.find("undo_limit"); limit != log.end()) {
    if (!limit->is_number_integer() || limit->get<long long>() < 0) {
      throw LogError(name, LogError::npos, "undo_limit", "expected an integer >= 0");
    }
    options.undo_limit = static_cast<std::size_t>(limit->get<long long>());
  }
  auto ops = log.find("ops");
  if (ops == log.end() || !ops->is_array())
    throw LogError(name, LogError::npos, "ops", "missing or not an array");
  Editor editor(options);
  for (std::size_t i = 0; i < ops->size(); ++i) replay_op(editor, (*ops)[i], i, name);
  return editor;
}

Editor replay_log_file(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw IoError("cannot open", path.string());
  std::stringstream buffer;
  buffer << in.rdbuf();
  nlohmann::json doc = nlohmann::json::parse(buffer.str(), nullptr, false);
  if (doc.is_discarded()) throw IoError("not valid JSON", path.string());
  return replay_log(doc, path.string());
}

void write_log(const Editor& editor, const std::filesystem::path& path) {
  const std::string text = editor.log().dump(1);
  write_atomically(path, [&](std::ostream& out) { out << text << '\n'; });
}

}  // namespace dlfl
