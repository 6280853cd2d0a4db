// TEMPORARY adapter over the old registry (registry.h) until every scheme declares its SchemeSpec.
#include <dlfl/schemes/scheme_registry.h>

#include <dlfl/errors.h>
#include <dlfl/format.h>
#include <dlfl/schemes/registry.h>

namespace dlfl {
namespace {
SchemeParams to_old(const Params& p) {
  SchemeParams out;
  for (const auto& [k, v] : p) {
    switch (v.kind()) {
      case Value::Kind::text: out[k] = v.as_text(); break;
      case Value::Kind::boolean: out[k] = v.as_bool() ? 1.0 : 0.0; break;
      case Value::Kind::point: out[k] = v.to_text(); break;
      default: out[k] = v.as_number();
    }
  }
  return out;
}
Params from_old(const SchemeParams& p) {
  Params out;
  for (const auto& [k, v] : p) {
    if (const double* d = std::get_if<double>(&v)) {
      out[k] = *d;
    } else {
      out[k] = std::get<std::string>(v);
    }
  }
  return out;
}
void known(std::string_view name) {
  const auto names = scheme_names();
  for (const auto& n : names) {
    if (n == name) return;
  }
  const std::string s = closest_name(name, names);
  throw UnknownNameError(unknown_name_message("scheme", name, names, s), s);
}
}  // namespace

Params resolve_scheme_params(std::string_view scheme, const Params& given) {
  known(scheme);
  return from_old(resolve_scheme_params(std::string(scheme), to_old(given)));
}

Mesh apply_scheme(const Mesh& mesh, std::string_view scheme, const Params& params, Origins*) {
  known(scheme);
  const std::string s(scheme);
  return apply_scheme(mesh, s, resolve_scheme_params(s, to_old(params)));
}

}  // namespace dlfl
