#include "schemes/registry.h"

#include <algorithm>
#include <charconv>
#include <functional>

#include "dlfl/errors.h"
#include "schemes/catmull_clark.h"
#include "schemes/honeycomb.h"

namespace dlfl {
namespace {

struct SchemeEntry {
  const char* name;
  std::vector<std::string> params;                          // every parameter name the scheme knows
  std::function<SchemeParams(SchemeParams)> fill_defaults;  // given (names known) -> full set, cross-checked
  std::function<Mesh(const Mesh&, const SchemeParams&)> apply;
};

double number(const SchemeParams& p, const char* scheme, const char* name) {
  auto it = p.find(name);
  if (it == p.end()) throw InvalidArgument(std::string(scheme) + ": parameter " + name + " is missing");
  if (const double* d = std::get_if<double>(&it->second)) return *d;
  throw InvalidArgument(std::string(scheme) + ": parameter " + name + " must be a number, not '" +
                        std::get<std::string>(it->second) + "'");
}

HoneycombParams honeycomb_params(const SchemeParams& p) {
  HoneycombParams h;
  if (p.count("t")) h.t = number(p, "honeycomb", "t");
  if (p.count("a")) h.a = number(p, "honeycomb", "a");
  if (p.count("a0")) h.a0 = number(p, "honeycomb", "a0");
  if (p.count("a1")) h.a1 = number(p, "honeycomb", "a1");
  return h;
}

// The tension is either the constant a or the function a0 + a1/N; the log records whichever is in force.
SchemeParams honeycomb_defaults(SchemeParams p) {
  const HoneycombParams defaults;
  if (p.count("a") && (p.count("a0") || p.count("a1"))) {
    throw InvalidArgument(
        "honeycomb: give either parameter a (constant tension) or a0/a1 (a = a0 + a1/N), not both");
  }
  p.try_emplace("t", defaults.t);
  if (!p.count("a")) {
    p.try_emplace("a0", defaults.a0);
    p.try_emplace("a1", defaults.a1);
  }
  honeycomb_params(p);  // type checks
  return p;
}

const std::vector<SchemeEntry>& registry() {
  // Schemes without parameters accept none.
  const auto no_params = [](SchemeParams p) { return p; };
  static const std::vector<SchemeEntry> entries = {
      {"catmull-clark", {}, no_params, [](const Mesh& m, const SchemeParams&) { return catmull_clark(m); }},
      {"honeycomb",
       {"t", "a", "a0", "a1"},
       honeycomb_defaults,
       [](const Mesh& m, const SchemeParams& p) { return honeycomb(m, honeycomb_params(p)); }},
  };
  return entries;
}

const SchemeEntry& find(const std::string& name) {
  for (const auto& e : registry()) {
    if (name == e.name) return e;
  }
  std::string known;
  for (const auto& n : scheme_names()) known += (known.empty() ? "" : ", ") + n;
  throw InvalidArgument("unknown scheme '" + name + "' (known: " + known + ")");
}

}  // namespace

std::vector<std::string> scheme_names() {
  std::vector<std::string> names;
  for (const auto& e : registry()) names.push_back(e.name);
  std::sort(names.begin(), names.end());
  return names;
}

SchemeParams resolve_scheme_params(const std::string& scheme, const SchemeParams& given) {
  const SchemeEntry& entry = find(scheme);
  for (const auto& [name, value] : given) {
    if (std::find(entry.params.begin(), entry.params.end(), name) == entry.params.end()) {
      std::string list;
      for (const auto& p : entry.params) list += (list.empty() ? "" : ", ") + p;
      throw InvalidArgument(scheme + ": unknown parameter '" + name + "' (" +
                            (list.empty() ? std::string("it takes none") : "known: " + list) + ")");
    }
  }
  return entry.fill_defaults(given);
}

Mesh apply_scheme(const Mesh& mesh, const std::string& scheme, const SchemeParams& params) {
  return find(scheme).apply(mesh, params);
}

std::pair<std::string, ParamValue> parse_param(const std::string& text) {
  const auto eq = text.find('=');
  if (eq == std::string::npos || eq == 0) {
    throw InvalidArgument("parameter '" + text + "' is not of the form name=value");
  }
  std::string name = text.substr(0, eq);
  std::string value = text.substr(eq + 1);
  double d = 0;
  const char* end = value.data() + value.size();
  auto [ptr, ec] = std::from_chars(value.data(), end, d);
  if (!value.empty() && ec == std::errc() && ptr == end) return {name, d};
  return {name, value};
}

}  // namespace dlfl
