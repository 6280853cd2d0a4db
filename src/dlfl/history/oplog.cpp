#include <dlfl/history/oplog.h>

#include <nlohmann/json.hpp>

#include <dlfl/io/atomic_file.h>
#include <dlfl/io/detail/text_io.h>
#include <dlfl/io/json_mesh.h>
#include <dlfl/mesh_hash.h>
#include <dlfl/operations/operation.h>
#include <dlfl/schemes/scheme_registry.h>

namespace dlfl {
namespace {

using nlohmann::json;

std::string where(std::size_t op, const std::string& field) {
  if (op == LogError::npos) return "field '" + field + "'";
  return "op " + std::to_string(op) + ", field '" + field + "'";
}

// ---- reading: a field by its declared type ----------------------------------------------------------------

class FieldReader {
 public:
  FieldReader(const std::string& name, std::size_t op) : name_(name), op_(op) {}

  [[noreturn]] void fail(const std::string& field, const std::string& what) const {
    throw LogError(name_, op_, field, what);
  }

  // Any JSON value as the closest Value; the declaration decides later what it may be.
  Value generic(const json& j, const std::string& field) const {
    if (j.is_boolean()) return j.get<bool>();
    if (j.is_number_integer()) {
      if (j.is_number_unsigned() && j.get<std::uint64_t>() > std::uint64_t(INT64_MAX)) {
        fail(field, "integer out of range");
      }
      return j.get<std::int64_t>();
    }
    if (j.is_number()) return j.get<double>();
    if (j.is_string()) return j.get<std::string>();
    if (j.is_object()) return params(j, field + ".");
    if (j.is_array()) {
      bool integers = true;
      bool numbers = true;
      bool points = !j.empty();
      for (const auto& e : j) {
        integers = integers && e.is_number_integer();
        numbers = numbers && e.is_number();
        points = points && e.is_array() && e.size() == 3 && e[0].is_number() && e[1].is_number() &&
                 e[2].is_number();
      }
      if (integers) {
        std::vector<std::int64_t> out;
        for (const auto& e : j) out.push_back(e.get<std::int64_t>());
        return out;
      }
      if (numbers) return j.get<std::vector<double>>();
      if (points) {
        std::vector<glm::dvec3> out;
        for (const auto& e : j) out.emplace_back(e[0].get<double>(), e[1].get<double>(), e[2].get<double>());
        return out;
      }
      fail(field, "expected a list of numbers or of [x, y, z]");
    }
    fail(field, "expected a value, not " + j.dump());
  }

  Params params(const json& j, const std::string& prefix) const {
    Params out;
    for (const auto& [key, value] : j.items()) out[key] = generic(value, prefix + key);
    return out;
  }

  Value typed(const json& j, const ParamSpec& spec) const {
    switch (spec.type) {
      case ParamType::mesh:
        if (!j.is_object()) fail(spec.name, "expected a native mesh object");
        try {
          return std::make_shared<const Mesh>(mesh_from_json(j, name_ + " op " + std::to_string(op_)));
        } catch (const IoError& e) {
          fail(spec.name, e.what());
        }
      case ParamType::params:
        if (!j.is_object()) fail(spec.name, "expected an object");
        return params(j, spec.name + ".");
      case ParamType::point:
        if (j.is_array() && (j.size() != 3 || !j[0].is_number() || !j[1].is_number() || !j[2].is_number())) {
          fail(spec.name, "expected [x, y, z]");
        }
        return generic(j, spec.name);
      case ParamType::points:
        if (!j.is_array()) fail(spec.name, "expected a list of [x, y, z]");
        for (std::size_t i = 0; i < j.size(); ++i) {
          const auto& e = j[i];
          if (!e.is_array() || e.size() != 3 || !e[0].is_number() || !e[1].is_number() || !e[2].is_number()) {
            fail(spec.name + "[" + std::to_string(i) + "]", "expected [x, y, z]");
          }
        }
        if (j.empty()) return std::vector<glm::dvec3>{};
        return generic(j, spec.name);
      default:
        return generic(j, spec.name);
    }
  }

 private:
  const std::string& name_;
  std::size_t op_;
};

// A log of version 1 or 2 predates some parameters: each one it lacks means what the library did then.
void fill_in_old_meanings(std::span<const ParamSpec> specs, Params& given) {
  for (const ParamSpec& spec : specs) {
    if (!spec.in_old_logs.empty() && !given.has(spec.name)) given[spec.name] = spec.in_old_logs;
  }
}

void fill_in_old_meanings(const std::string& op_name, Params& given) {
  if (op_name != "subdivide" || !given.has("scheme") || !given.has("params")) return;
  const Value& scheme = given.at("scheme");
  if (scheme.kind() != Value::Kind::text) return;
  if (given.at("params").kind() != Value::Kind::params) return;  // refused when it runs
  const SchemeSpec* spec = nullptr;
  try {
    spec = &find_scheme(scheme.as_text());
  } catch (const UnknownNameError&) {
    return;  // refused when it runs, with the known names
  }
  Params params = given.at("params").as_params();
  fill_in_old_meanings(spec->params, params);
  given["params"] = std::move(params);
}

void replay_op(Editor& editor, const json& op, std::size_t index, const std::string& name,
               const ReplayOptions& options, int version) {
  const FieldReader reader(name, index);
  if (!op.is_object()) reader.fail("op", "expected an object");
  auto kind = op.find("op");
  if (kind == op.end() || !kind->is_string()) reader.fail("op", "missing or not a string");
  const std::string op_name = kind->get<std::string>();
  const OperationSpec* spec = nullptr;
  try {
    spec = &find_operation(op_name);
  } catch (const UnknownNameError& e) {
    reader.fail("op", e.what());
  }
  Params given;
  for (const auto& [field, value] : op.items()) {
    if (field == "op") continue;
    if (field == "hash" && !options.verify) continue;
    const ParamSpec* declared = nullptr;
    for (const auto& p : spec->params) declared = p.name == field ? &p : declared;
    if (!declared) {
      given[field] = Value(true);  // refused by name below, with the known names
      continue;
    }
    if (value.is_null() && declared->is_optional) continue;  // null: not given (set_face_point clears)
    given[field] = reader.typed(value, *declared);
  }
  if (version < 3) {
    fill_in_old_meanings(spec->params, given);
    fill_in_old_meanings(op_name, given);
  }
  try {
    editor.apply(op_name, given);
  } catch (const ParameterError& e) {
    reader.fail(e.parameter(), e.what());
  } catch (const IoError& e) {
    // Only load reads files: a file that cannot be read is the path's fault.
    reader.fail(op_name == "load" ? "path" : "op", e.what());
  } catch (const Error& e) {
    // The operation itself refused (a self-loop, a scheme that does not apply): name the op.
    reader.fail("op", e.what());
  }
}

}  // namespace

LogError::LogError(const std::string& name, std::size_t op, const std::string& field, const std::string& what)
    : IoError(where(op, field) + ": " + what, name), op_(op), field_(field) {}

std::string log_text(const Editor& editor) {
  json ops = json::array();
  for (const LoggedOperation& logged : editor.log()) {
    json op = {{"op", logged.name}};
    for (const auto& [field, value] : logged.params) op[field] = value_to_json(value);
    ops.push_back(std::move(op));
  }
  const json doc = {{"format", "dlfl-oplog"},
                    {"version", oplog_version},
                    {"undo_limit", editor.options().undo_limit},
                    {"ops", std::move(ops)},
                    {"final_hash", mesh_hash(editor.mesh())}};
  try {
    return doc.dump(1);
  } catch (const json::type_error&) {
    // JSON holds UTF-8 only. Parameters are checked for it; a path given to Editor::set_mesh is not.
    const json& written = doc["ops"];
    std::size_t i = 0;
    for (; i + 1 < written.size(); ++i) {
      try {
        (void)written[i].dump();
      } catch (const json::type_error&) {
        break;
      }
    }
    throw InvalidArgument("the log cannot be written: op " + std::to_string(i) + " (" + editor.log()[i].name +
                          ") has text that is not valid UTF-8, which JSON cannot hold");
  }
}

void write_log(const Editor& editor, const std::filesystem::path& path, FileBatch* batch) {
  const std::string text = log_text(editor);
  const auto write = [&](std::ostream& out) { out << text << '\n'; };
  if (batch) {
    batch->stage(path, write);
  } else {
    write_atomically(path, write);
  }
}

Editor replay_log(std::string_view text, const std::string& name, const ReplayOptions& replay) {
  const json log = json::parse(text, nullptr, false);
  if (log.is_discarded()) throw LogError(name, LogError::npos, "(document)", "not valid JSON");
  if (!log.is_object()) throw LogError(name, LogError::npos, "(document)", "expected a JSON object");
  auto format = log.find("format");
  if (format == log.end() || *format != "dlfl-oplog") {
    throw LogError(name, LogError::npos, "format", "expected \"dlfl-oplog\"");
  }
  auto version = log.find("version");
  if (version == log.end() || !version->is_number_integer()) {
    throw LogError(name, LogError::npos, "version", "missing or not an integer");
  }
  if (*version < 1 || *version > oplog_version) {
    throw LogError(name, LogError::npos, "version",
                   "unsupported version " + version->dump() + " (this library reads versions 1 to " +
                       std::to_string(oplog_version) + ")");
  }
  Editor::Options options;
  if (auto limit = log.find("undo_limit"); limit != log.end()) {
    if (!limit->is_number_integer() || limit->get<long long>() < 0) {
      throw LogError(name, LogError::npos, "undo_limit", "expected an integer >= 0");
    }
    options.undo_limit = static_cast<std::size_t>(limit->get<long long>());
  }
  auto ops = log.find("ops");
  if (ops == log.end() || !ops->is_array()) {
    throw LogError(name, LogError::npos, "ops", "missing or not an array");
  }
  auto final_hash = log.find("final_hash");
  if (final_hash != log.end() && !final_hash->is_string()) {
    throw LogError(name, LogError::npos, "final_hash", "expected a string");
  }
  Editor editor(options);
  for (std::size_t i = 0; i < ops->size(); ++i) {
    replay_op(editor, (*ops)[i], i, name, replay, version->get<int>());
    if (replay.after_op) replay.after_op(editor, i);
  }
  if (replay.verify && final_hash != log.end() && *final_hash != mesh_hash(editor.mesh())) {
    throw LogError(name, LogError::npos, "final_hash",
                   "the replay ends in a mesh of hash " + mesh_hash(editor.mesh()) + ", the log expects " +
                       final_hash->get<std::string>() + " (the log was edited, or an input changed unseen)");
  }
  return editor;
}

Editor replay_log_file(const std::filesystem::path& path, const ReplayOptions& options) {
  const std::string text = io_detail::read_file(path);
  return replay_log(text, path.string(), options);
}

}  // namespace dlfl
