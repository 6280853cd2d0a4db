#include <dlfl/operations/detail/handle_selection.h>

#include <dlfl/errors.h>

namespace dlfl::detail {

void refuse_empty(std::string_view op, std::string_view parameter) {
  refuse_worded(op, parameter, " is empty: it needs at least one element");
}

void require_one_of(std::string_view op, const Params& params, std::string_view one, std::string_view many) {
  const bool a = params.has(one), b = params.has(many);
  if (a == b) {
    throw ParameterError(std::string(op) + ": give exactly one of parameters " + std::string(one) + " and " +
                             std::string(many) + (a ? " (both are given)" : " (neither is given)"),
                         std::string(one));
  }
}

}  // namespace dlfl::detail
