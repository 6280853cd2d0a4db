#include "spec_listing.h"

#include <cmath>

namespace dlfl::tool {

nlohmann::json param_json(const ParamSpec& spec) {
  nlohmann::json j = {{"name", spec.name},
                      {"type", std::string(to_string(spec.type))},
                      {"doc", spec.doc},
                      {"optional", spec.is_optional || !spec.default_value.empty()}};
  if (!spec.default_value.empty()) j["default"] = spec.default_value.to_text();
  if (!spec.default_doc.empty()) j["default_doc"] = spec.default_doc;
  if (!std::isinf(spec.min) || !std::isinf(spec.max)) {
    nlohmann::json range = {{"min_open", spec.min_open}, {"max_open", spec.max_open}};
    range["min"] = std::isinf(spec.min) ? nlohmann::json(nullptr) : nlohmann::json(spec.min);
    range["max"] = std::isinf(spec.max) ? nlohmann::json(nullptr) : nlohmann::json(spec.max);
    j["range"] = range;
  }
  if (!spec.keywords.empty()) j["keywords"] = spec.keywords;
  return j;
}

std::string param_lines(std::span<const ParamSpec> specs) {
  std::size_t width = 0;
  for (const auto& s : specs) width = std::max(width, s.name.size());
  std::string out;
  for (const auto& s : specs) {
    std::string line =
        "  " + s.name + std::string(width - s.name.size() + 2, ' ') + std::string(to_string(s.type));
    if (!s.default_value.empty()) {
      const std::string shown = s.default_value.to_text();
      line += s.default_value.kind() == Value::Kind::text ? " = '" + shown + "'" : " = " + shown;
    } else if (s.is_optional) {
      line += " (optional" + (s.default_doc.empty() ? std::string() : ": " + s.default_doc) + ")";
    } else {
      line += " (required)";
    }
    if (const std::string r = s.range_text(); !r.empty()) line += "  in " + r;
    if (!s.keywords.empty()) {
      std::string words;
      for (const auto& k : s.keywords) {
        if (!words.empty()) words += '|';
        words += k;
      }
      line += (s.type == ParamType::text ? "  one of " : "  or ") + words;
    }
    out += line + "  " + s.doc + "\n";
  }
  return out;
}

}  // namespace dlfl::tool
