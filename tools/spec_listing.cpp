#include "spec_listing.h"

#include <algorithm>

namespace dlfl::tool {
namespace {

// "default 0.5", "default 'centroid'", "optional: a0 + a1/N for an N-sided face", "required".
std::string default_text(const ParamSpec& p) {
  if (p.default_value.empty()) {
    if (!p.is_optional) return "required";
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

}  // namespace

std::string param_lines(std::span<const ParamSpec> specs) {
  if (specs.empty()) return "  (no parameters)\n";
  std::size_t name_w = 0, type_w = 0, default_w = 0, allowed_w = 0;
  for (const ParamSpec& p : specs) {
    name_w = std::max(name_w, p.name.size());
    type_w = std::max(type_w, to_string(p.type).size());
    default_w = std::max(default_w, default_text(p).size());
    allowed_w = std::max(allowed_w, allowed_text(p).size());
  }
  const auto pad = [](std::string text, std::size_t width) {
    text.resize(std::max(text.size(), width), ' ');
    return text;
  };
  std::string out;
  for (const ParamSpec& p : specs) {
    out += "  " + pad(p.name, name_w) + "  " + pad(std::string(to_string(p.type)), type_w) + "  " +
           pad(default_text(p), default_w) + "  ";
    if (allowed_w > 0) out += pad(allowed_text(p), allowed_w) + "  ";  // no empty column
    out += p.doc + "\n";
  }
  return out;
}

}  // namespace dlfl::tool
