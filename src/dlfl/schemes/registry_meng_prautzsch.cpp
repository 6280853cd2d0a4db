// The registry entries of Meng-Prautzsch H, P and MHP.

#include <charconv>
#include <cmath>
#include <utility>

#include <dlfl/schemes/meng_prautzsch_mixed.h>
#include <dlfl/schemes/meng_prautzsch_honeycomb.h>
#include <dlfl/schemes/meng_prautzsch_pushing.h>
#include <dlfl/schemes/detail/registry_entry.h>

namespace dlfl::detail {
namespace {

// The default centre, recorded in logs by this name.
constexpr const char* centroid_name = "centroid";

// "centroid" or "x,y,z".
std::optional<glm::dvec3> center_param(const SchemeParams& p, const char* scheme) {
  auto it = p.find("center");
  if (it == p.end()) return std::nullopt;
  const std::string bad =
      std::string(scheme) + ": parameter center must be 'centroid' or three numbers x,y,z";
  const auto* text = std::get_if<std::string>(&it->second);
  if (!text) throw InvalidArgument(bad + ", not a single number");
  if (*text == centroid_name) return std::nullopt;
  glm::dvec3 c(0.0);
  const char* pos = text->data();
  const char* end = text->data() + text->size();
  for (int i = 0; i < 3; ++i) {
    auto [ptr, ec] = std::from_chars(pos, end, c[i]);
    if (ec != std::errc() || !std::isfinite(c[i])) throw InvalidArgument(bad + ", not '" + *text + "'");
    pos = ptr;
    if (i < 2) {
      if (pos == end || *pos != ',') throw InvalidArgument(bad + ", not '" + *text + "'");
      ++pos;
    }
  }
  if (pos != end) throw InvalidArgument(bad + ", not '" + *text + "'");
  return c;
}

MpRandomChoice random_param(const SchemeParams& p, const char* scheme) {
  MpRandomChoice r;
  if (p.count("random")) {
    const double on = number(p, scheme, "random");
    if (on != 0.0 && on != 1.0)
      throw InvalidArgument(std::string(scheme) + ": parameter random must be 0 or 1");
    r.enabled = on == 1.0;
  }
  if (p.count("epsilon")) r.epsilon = number(p, scheme, "epsilon");
  if (p.count("seed")) {
    const double seed = number(p, scheme, "seed");
    if (!(seed >= 0.0 && seed <= 0x1.0p53 && seed == std::floor(seed))) {
      throw InvalidArgument(std::string(scheme) + ": parameter seed must be a whole number in [0, 2^53]");
    }
    r.seed = static_cast<std::uint64_t>(seed);
  }
  return r;
}

MpHoneycombParams honeycomb_params(const SchemeParams& p) {
  MpHoneycombParams h;
  if (p.count("tau")) h.tau = number(p, "mp-honeycomb", "tau");
  if (p.count("ratio")) h.ratio = number(p, "mp-honeycomb", "ratio");
  h.center = center_param(p, "mp-honeycomb");
  h.random = random_param(p, "mp-honeycomb");
  check_mp_honeycomb_params(h);
  return h;
}

MpPushingParams pushing_params(const SchemeParams& p) {
  MpPushingParams q;
  if (p.count("tau")) q.tau = number(p, "mp-pushing", "tau");
  if (p.count("ratio")) q.ratio = number(p, "mp-pushing", "ratio");
  q.center = center_param(p, "mp-pushing");
  q.random = random_param(p, "mp-pushing");
  check_mp_pushing_params(q);
  return q;
}

MhpParams mhp_params(const SchemeParams& p) {
  MhpParams m;
  if (auto it = p.find("pattern"); it != p.end()) {
    const auto* text = std::get_if<std::string>(&it->second);
    if (!text) throw InvalidArgument("mhp: parameter pattern must be text such as H4P4, not a number");
    m.pattern = *text;
  }
  if (p.count("tau_h")) m.honeycomb.tau = number(p, "mhp", "tau_h");
  if (p.count("ratio_h")) m.honeycomb.ratio = number(p, "mhp", "ratio_h");
  if (p.count("tau_p")) m.pushing.tau = number(p, "mhp", "tau_p");
  if (p.count("ratio_p")) m.pushing.ratio = number(p, "mhp", "ratio_p");
  m.center = center_param(p, "mhp");
  m.honeycomb.random = m.pushing.random = random_param(p, "mhp");
  // Checked here under their mhp names; check_mhp_params would name them tau and ratio.
  for (auto [name, tau] : {std::pair{"tau_h", m.honeycomb.tau}, std::pair{"tau_p", m.pushing.tau}}) {
    if (!(tau > 0.0 && tau < 1.0)) {
      throw InvalidArgument(std::string("mhp: parameter ") + name + " must be in (0, 1), not " +
                            format_number(tau));
    }
  }
  for (auto [name, ratio] :
       {std::pair{"ratio_h", m.honeycomb.ratio}, std::pair{"ratio_p", m.pushing.ratio}}) {
    if (!(ratio > 0.0 && std::isfinite(ratio))) {
      throw InvalidArgument(std::string("mhp: parameter ") + name + " must be positive and finite, not " +
                            format_number(ratio));
    }
  }
  check_mhp_params(m);
  return m;
}

// The defaults every entry records, then a full parse for the type and range checks.
void random_defaults(SchemeParams& p) {
  const MpRandomChoice defaults;
  p.try_emplace("center", std::string(centroid_name));
  p.try_emplace("random", 0.0);
  p.try_emplace("epsilon", defaults.epsilon);
  p.try_emplace("seed", double(defaults.seed));
}

SchemeParams honeycomb_defaults(SchemeParams p) {
  const MpHoneycombParams defaults;
  p.try_emplace("tau", defaults.tau);
  p.try_emplace("ratio", defaults.ratio);
  random_defaults(p);
  honeycomb_params(p);
  return p;
}

SchemeParams pushing_defaults(SchemeParams p) {
  const MpPushingParams defaults;
  p.try_emplace("tau", defaults.tau);
  p.try_emplace("ratio", defaults.ratio);
  random_defaults(p);
  pushing_params(p);
  return p;
}

SchemeParams mhp_defaults(SchemeParams p) {
  const MhpParams defaults;
  p.try_emplace("pattern", defaults.pattern);
  p.try_emplace("tau_h", defaults.honeycomb.tau);
  p.try_emplace("ratio_h", defaults.honeycomb.ratio);
  p.try_emplace("tau_p", defaults.pushing.tau);
  p.try_emplace("ratio_p", defaults.pushing.ratio);
  random_defaults(p);
  mhp_params(p);
  return p;
}

}  // namespace

std::vector<SchemeEntry> meng_prautzsch_scheme_entries() {
  return {
      {"mp-honeycomb",
       {"tau", "ratio", "center", "random", "epsilon", "seed"},
       honeycomb_defaults,
       [](const Mesh& m, const SchemeParams& p) { return mp_honeycomb(m, honeycomb_params(p)); }},
      {"mp-pushing",
       {"tau", "ratio", "center", "random", "epsilon", "seed"},
       pushing_defaults,
       [](const Mesh& m, const SchemeParams& p) { return mp_pushing(m, pushing_params(p)); }},
      {"mhp",
       {"pattern", "tau_h", "ratio_h", "tau_p", "ratio_p", "center", "random", "epsilon", "seed"},
       mhp_defaults,
       [](const Mesh& m, const SchemeParams& p) { return mhp(m, mhp_params(p)); }},
  };
}

}  // namespace dlfl::detail
