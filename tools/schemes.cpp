// dlfl schemes [NAME] [--json]: the registered schemes with their parameters, read from the scheme table (the
// same declarations that `subdivide --param` is checked against).

#include <algorithm>
#include <cmath>
#include <iostream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include <dlfl/errors.h>
#include <dlfl/schemes/scheme_registry.h>
#include "commands.h"

namespace dlfl::tool {
namespace {

// A value as JSON, typed: true, 1, 0.5, "centroid", [x, y, z]; null when there is none.
nlohmann::ordered_json value_json(const Value& v) {
  switch (v.kind()) {
    case Value::Kind::empty:
      return nullptr;
    case Value::Kind::boolean:
      return v.as_bool();
    case Value::Kind::integer:
      return v.as_integer();
    case Value::Kind::number:
      return v.as_number();
    case Value::Kind::point:
      return {v.as_point().x, v.as_point().y, v.as_point().z};
    default:
      return v.to_text();
  }
}

// An infinite end of a range is left open and shown as null (JSON has no infinity).
nlohmann::ordered_json bound_json(double x) {
  return std::isinf(x) ? nlohmann::ordered_json() : nlohmann::ordered_json(x);
}

nlohmann::ordered_json scheme_json(const SchemeSpec& s) {
  nlohmann::ordered_json params = nlohmann::ordered_json::array();
  for (const ParamSpec& p : s.params) {
    nlohmann::ordered_json j;
    j["name"] = p.name;
    j["type"] = std::string(to_string(p.type));
    j["default"] = value_json(p.default_value);
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
    params.push_back(std::move(j));
  }
  return {{"name", s.name}, {"doc", s.doc}, {"params", std::move(params)}};
}

// "default 0.5", "default 'centroid'", "optional: a0 + a1/N for an N-sided face".
std::string default_text(const ParamSpec& p) {
  if (p.default_value.empty()) {
    return p.default_doc.empty() ? std::string("optional") : "optional: " + p.default_doc;
  }
  const std::string text = p.default_value.to_text();
  return "default " + (p.default_value.kind() == Value::Kind::text ? "'" + text + "'" : text);
}

// "in [0, 1]", "in [0, 1] or 'symmetric'", "x,y,z or 'centroid'", "one of 'a', 'b'"; empty if the type alone
// says it.
std::string allowed_text(const ParamSpec& p) {
  std::string s;
  if (!p.range_text().empty()) s = "in " + p.range_text();
  if (p.keywords.empty()) return s;
  std::string words;
  for (const std::string& k : p.keywords) words += (words.empty() ? "'" : ", '") + k + "'";
  if (p.type == ParamType::text) return "one of " + words;
  if (s.empty() && p.type == ParamType::point) s = "x,y,z";
  return s.empty() ? "or " + words : s + " or " + words;
}

void print_scheme(const SchemeSpec& s) {
  std::cout << s.name << ": " << s.doc << "\n";
  if (s.params.empty()) {
    std::cout << "  (no parameters)\n";
    return;
  }
  // Columns sized to this scheme's parameters.
  std::size_t name_w = 0, type_w = 0, default_w = 0, allowed_w = 0;
  for (const ParamSpec& p : s.params) {
    name_w = std::max(name_w, p.name.size());
    type_w = std::max(type_w, to_string(p.type).size());
    default_w = std::max(default_w, default_text(p).size());
    allowed_w = std::max(allowed_w, allowed_text(p).size());
  }
  const auto pad = [](std::string text, std::size_t width) {
    text.resize(std::max(text.size(), width), ' ');
    return text;
  };
  for (const ParamSpec& p : s.params) {
    std::cout << "  " << pad(p.name, name_w) << "  " << pad(std::string(to_string(p.type)), type_w) << "  "
              << pad(default_text(p), default_w) << "  " << pad(allowed_text(p), allowed_w) << "  " << p.doc
              << "\n";
  }
}

}  // namespace

Action add_schemes(CLI::App& app) {
  auto* cmd = app.add_subcommand("schemes", "List the subdivision schemes and their parameters");
  struct Args {
    std::string name;
    bool json = false;
  };
  auto a = std::make_shared<Args>();
  cmd->add_option("NAME", a->name, "Show this scheme only");
  cmd->add_flag("--json", a->json,
                "Print a JSON array [{name, doc, params: [{name, type, default, range, keywords, doc, "
                "optional}]}]");
  return [a]() -> int {
    std::vector<const SchemeSpec*> shown;
    if (a->name.empty()) {
      for (const SchemeSpec& s : schemes()) shown.push_back(&s);
    } else {
      try {
        shown.push_back(&find_scheme(a->name));
      } catch (const UnknownNameError& e) {
        std::cerr << "error: " << e.what() << "\n";  // a name that is not a scheme: a usage error
        return usage;
      }
    }
    if (a->json) {
      nlohmann::ordered_json list = nlohmann::ordered_json::array();
      for (const SchemeSpec* s : shown) list.push_back(scheme_json(*s));
      std::cout << list.dump(2) << "\n";
      return ok;
    }
    for (std::size_t i = 0; i < shown.size(); ++i) {
      if (i > 0) std::cout << "\n";
      print_scheme(*shown[i]);
    }
    return ok;
  };
}

}  // namespace dlfl::tool
