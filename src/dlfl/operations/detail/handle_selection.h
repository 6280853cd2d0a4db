#pragma once
// Internal to the cutting operations: which elements an operation is given. Each takes one element (`vertex`)
// or a list (`vertices`), both declared optional, exactly one given, as extrusion_faces.h does for faces.

#include <span>
#include <string>
#include <string_view>
#include <type_traits>
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

/// The declaration of `one` (a handle of type H; `list` false) or `many` (a list of them; `list` true), both
/// optional, exactly one to be given.
template <class H>
ParamSpec selection_param(std::string_view one, std::string_view many, bool list, std::string doc) {
  constexpr bool vertex = std::is_same_v<H, VertexId>, edge = std::is_same_v<H, EdgeId>;
  static_assert(vertex || edge || std::is_same_v<H, FaceId>, "a selection is of vertices, edges or faces");
  const ParamType type = vertex ? (list ? ParamType::vertices : ParamType::vertex)
                         : edge ? (list ? ParamType::edges : ParamType::edge)
                                : (list ? ParamType::faces : ParamType::face);
  return param(std::string(list ? many : one), type, std::move(doc))
      .optional("exactly one of " + std::string(one) + " and " + std::string(many));
}

/// Refuses `parameter` for an empty list or a removed element.
template <class H>
void require_live_list(const Mesh& mesh, std::string_view op, std::string_view parameter,
                       std::span<const H> hs) {
  if (hs.empty()) refuse_empty(op, parameter);
  for (H h : hs) require_live(mesh, op, parameter, h);
}

}  // namespace dlfl::detail
