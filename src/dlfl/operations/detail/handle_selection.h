#pragma once
// Internal to the cutting operations: which elements an operation is given. Each takes one element (`vertex`)
// or a list (`vertices`), both declared optional, exactly one given, as extrusion_faces.h does for faces.

#include <span>
#include <string>
#include <string_view>
#include <vector>

#include <dlfl/mesh.h>
#include <dlfl/operations/detail/refusal.h>
#include <dlfl/parameters.h>

namespace dlfl::detail {

/// Throws ParameterError: "OP: parameter P is empty: it needs at least one element".
[[noreturn]] void refuse_empty(std::string_view op, std::string_view parameter);

/// The handles an operation is given, and the name of the parameter that gave them.
template <class H>
struct HandleSelection {
  std::vector<H> handles;
  std::string parameter;
};

/// Throws ParameterError naming `one` unless exactly one of `one` and `many` is given.
void require_one_of(std::string_view op, const Params& params, std::string_view one, std::string_view many);

/// The handles of `params`: `one` (a handle) or `many` (a list), exactly one of the two.
template <class H>
HandleSelection<H> selected_handles(std::string_view op, const Params& params, std::string_view one,
                                    std::string_view many) {
  require_one_of(op, params, one, many);
  if (params.has(one)) return {{params.handle<H>(one)}, std::string(one)};
  return {params.handles<H>(many), std::string(many)};
}

/// Refuses `parameter` for an empty list or a removed element.
template <class H>
void require_live_list(const Mesh& mesh, std::string_view op, std::string_view parameter,
                       std::span<const H> hs) {
  if (hs.empty()) refuse_empty(op, parameter);
  for (H h : hs) require_live(mesh, op, parameter, h);
}

}  // namespace dlfl::detail
