#include <dlfl/operations/detail/refusal.h>

#include <cmath>

#include <dlfl/errors.h>

namespace dlfl::detail {

void refuse(std::string_view op, std::string_view param, const std::string& why) {
  refuse_worded(op, param, ": " + why);
}

void refuse_worded(std::string_view op, std::string_view param, const std::string& tail) {
  throw ParameterError(std::string(op) + ": parameter " + std::string(param) + tail, std::string(param));
}

std::string count_of(std::size_t n, const char* noun) {
  return std::to_string(n) + " " + noun + (n == 1 ? "" : "s");
}

void require_finite(std::string_view op, std::string_view param, const glm::dvec3& p) {
  if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) refuse(op, param, "is not finite");
}

}  // namespace dlfl::detail
