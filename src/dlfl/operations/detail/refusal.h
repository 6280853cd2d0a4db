#pragma once
// Internal to the modeling operations: a refused argument as a ParameterError, worded the one way they all
// word it ("collapse_edge: parameter edge: ..."), and the checks of handle and point arguments that the
// registry makes too, repeated because the library functions are also called directly.

#include <cstddef>
#include <glm/vec3.hpp>
#include <string>
#include <string_view>

#include <dlfl/handles.h>
#include <dlfl/mesh.h>

namespace dlfl::detail {

/// Throws ParameterError("OP: parameter PARAM: WHY", PARAM).
[[noreturn]] void refuse(std::string_view op, std::string_view param, const std::string& why);
/// Throws ParameterError("OP: parameter PARAM" + TAIL, PARAM), for the wordings that go on otherwise than
/// with a colon ("extrude_face: parameter distance = inf is not finite").
[[noreturn]] void refuse_worded(std::string_view op, std::string_view param, const std::string& tail);

/// Refuses `param` unless h is a live element of `mesh`.
template <class H>
void require_live(const Mesh& mesh, std::string_view op, std::string_view param, H h) {
  if (!mesh.is_alive(h)) refuse(op, param, to_string(h) + " does not exist (removed or never created)");
}

/// "1 neighbour", "3 neighbours": a count with its noun, for messages.
std::string count_of(std::size_t n, const char* noun);

/// Refuses `param` unless every coordinate of p is finite.
void require_finite(std::string_view op, std::string_view param, const glm::dvec3& p);

}  // namespace dlfl::detail
