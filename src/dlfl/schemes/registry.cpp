#include <dlfl/schemes/registry.h>

#include <algorithm>
#include <charconv>
#include <functional>

#include <dlfl/errors.h>
#include <dlfl/schemes/detail/registry_entry.h>

namespace dlfl {
namespace {

const std::vector<detail::SchemeEntry>& registry() {
  static const std::vector<detail::SchemeEntry> entries = [] {
    std::vector<detail::SchemeEntry> all;
    for (auto family : {detail::classic_scheme_entries, detail::meng_prautzsch_scheme_entries,
                        detail::mlca_scheme_entries}) {
      auto more = family();
      all.insert(all.end(), std::make_move_iterator(more.begin()), std::make_move_iterator(more.end()));
    }
    return all;
  }();
  return entries;
}

const detail::SchemeEntry& find(const std::string& name) {
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
  const detail::SchemeEntry& entry = find(scheme);
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
