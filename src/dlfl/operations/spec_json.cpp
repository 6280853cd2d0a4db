#include <dlfl/operations/spec_json.h>

#include <cmath>

#include <dlfl/detail/enum_names.h>
#include <dlfl/io/json_mesh.h>

namespace dlfl {
namespace {

nlohmann::ordered_json bound_json(double x) {
  return std::isinf(x) ? nlohmann::ordered_json() : nlohmann::ordered_json(x);
}

nlohmann::ordered_json param_json(const ParamSpec& p) {
  nlohmann::ordered_json j;
  j["name"] = p.name;
  j["type"] = std::string(to_string(p.type));
  j["default"] = value_to_json(p.default_value);
  if (!p.default_doc.empty()) j["default_doc"] = p.default_doc;
  if (!p.range_text().empty()) {
    j["range"] = {{"min", bound_json(p.min)},
                  {"max", bound_json(p.max)},
                  {"min_open", p.min_open || std::isinf(p.min)},
                  {"max_open", p.max_open || std::isinf(p.max)}};
  }
  j["keywords"] = p.keywords;
  j["doc"] = p.doc;
  j["optional"] = p.is_optional;
  return j;
}

nlohmann::ordered_json params_json(const std::vector<ParamSpec>& specs) {
  nlohmann::ordered_json params = nlohmann::ordered_json::array();
  for (const ParamSpec& p : specs) params.push_back(param_json(p));
  return params;
}

nlohmann::ordered_json op_json(const OperationSpec& op) {
  return {{"name", op.name},
          {"kind", to_string(op.kind)},
          {"doc", op.doc},
          {"counts", op.counts},
          {"params", params_json(op.params)}};
}

nlohmann::ordered_json scheme_json(const SchemeSpec& s) {
  return {{"name", s.name}, {"doc", s.doc}, {"params", params_json(s.params)}};
}

template <class Spec, class ToJson>
std::string listing(std::span<const Spec> specs, const ToJson& to_json, int indent) {
  nlohmann::ordered_json all = nlohmann::ordered_json::array();
  for (const Spec& s : specs) all.push_back(to_json(s));
  return all.dump(indent);
}

}  // namespace

const char* to_string(OperationSpec::Kind kind) {
  static constexpr const char* names[] = {"edit", "replace", "history"};
  static_assert(std::size(names) == std::size_t(OperationSpec::Kind::history) + 1,
                "a name per enumerator, in order");
  return detail::name_at(kind, names, "?");
}

std::string to_json(const OperationSpec& op, int indent) { return op_json(op).dump(indent); }
std::string to_json(const SchemeSpec& scheme, int indent) { return scheme_json(scheme).dump(indent); }
std::string operations_json(int indent) { return listing(operations(), op_json, indent); }
std::string schemes_json(int indent) { return listing(schemes(), scheme_json, indent); }

}  // namespace dlfl
