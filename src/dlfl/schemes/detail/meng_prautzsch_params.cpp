#include <dlfl/schemes/detail/meng_prautzsch_params.h>

#include <limits>
#include <string>

namespace dlfl::detail {
namespace {
// The default centre, recorded in logs by this name.
constexpr const char* centroid_keyword = "centroid";
}  // namespace

std::vector<ParamSpec> mp_shared_param_specs() {
  const MpRandomChoice d;
  return {
      param("center", ParamType::point, centroid_keyword,
            "the centre (the paper's origin), strictly inside; 'centroid': the input's vertex centroid")
          .one_of({centroid_keyword}),
      param(
          "random", ParamType::boolean, d.enabled,
          "random per-element ratios and taus, uniform in [epsilon, 1 - epsilon], instead of ratio and tau"),
      param("epsilon", ParamType::number, d.epsilon, "the margin of the random choices")
          .range(0, 0.5, true, false),
      param("seed", ParamType::integer, static_cast<std::int64_t>(d.seed),
            "the seed of the random choices (the same seed gives the same mesh on every platform)")
          .in(0, 0x1.0p53),
  };
}

std::optional<glm::dvec3> mp_center_from(const Params& p) {
  const Value& center = p.get("center");
  if (center.kind() == Value::Kind::text) return std::nullopt;  // the keyword
  return center.as_point();
}

MpRandomChoice mp_random_from(const Params& p) {
  MpRandomChoice r;
  r.enabled = p.boolean("random");
  r.epsilon = p.number("epsilon");
  r.seed = static_cast<std::uint64_t>(p.integer("seed"));
  return r;
}

std::vector<ParamSpec> mp_step_param_specs(const char* tau, std::string tau_doc, const char* ratio,
                                           std::string ratio_doc) {
  const MpStepParams d;
  return {
      param(tau, ParamType::number, d.tau, std::move(tau_doc)).in_open(0, 1),
      param(ratio, ParamType::number, d.ratio, std::move(ratio_doc))
          .range(0, std::numeric_limits<double>::infinity(), true, true),
  };
}

MpStepParams mp_step_params_from(const Params& p, const char* tau, const char* ratio) {
  MpStepParams s;
  s.tau = p.number(tau);
  s.ratio = p.number(ratio);
  s.center = mp_center_from(p);
  s.random = mp_random_from(p);
  return s;
}

}  // namespace dlfl::detail
