// The registry entries of the classic schemes and the honeycomb family.

#include <dlfl/errors.h>
#include <dlfl/schemes/catmull_clark.h>
#include <dlfl/schemes/doo_sabin.h>
#include <dlfl/schemes/dual.h>
#include <dlfl/schemes/dual_honeycomb_dual.h>
#include <dlfl/schemes/honeycomb.h>
#include <dlfl/schemes/loop.h>
#include <dlfl/schemes/detail/registry_entry.h>
#include <dlfl/schemes/sqrt3.h>
#include <dlfl/schemes/zhang_wang_honeycomb.h>

namespace dlfl::detail {
namespace {

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

// The tension a of honeycomb-zw is a number, or "symmetric" for the paper's a_n = (4 - cos(2 pi / n)) / 9.
constexpr const char* zw_symmetric = "symmetric";

ZhangWangParams zhang_wang_params(const SchemeParams& p) {
  ZhangWangParams z;
  if (auto it = p.find("a"); it != p.end()) {
    const auto* text = std::get_if<std::string>(&it->second);
    if (!text) {
      z.a = std::get<double>(it->second);
    } else if (*text != zw_symmetric) {
      throw InvalidArgument("honeycomb-zw: parameter a must be a number or 'symmetric', not '" + *text + "'");
    }
  }
  if (p.count("b")) z.b = number(p, "honeycomb-zw", "b");
  if (p.count("c")) z.c = number(p, "honeycomb-zw", "c");
  if (p.count("alpha")) z.alpha = number(p, "honeycomb-zw", "alpha");
  check_zhang_wang_params(z);
  return z;
}

SchemeParams zhang_wang_defaults(SchemeParams p) {
  const ZhangWangParams defaults;
  p.try_emplace("a", std::string(zw_symmetric));
  p.try_emplace("b", defaults.b);
  p.try_emplace("c", defaults.c);
  p.try_emplace("alpha", defaults.alpha);
  zhang_wang_params(p);  // type and range checks
  return p;
}

}  // namespace

std::vector<SchemeEntry> classic_scheme_entries() {
  // Schemes without parameters accept none.
  const auto no_params = [](SchemeParams p) { return p; };
  return {
      {"catmull-clark", {}, no_params, [](const Mesh& m, const SchemeParams&) { return catmull_clark(m); }},
      {"honeycomb",
       {"t", "a", "a0", "a1"},
       honeycomb_defaults,
       [](const Mesh& m, const SchemeParams& p) { return honeycomb(m, honeycomb_params(p)); }},
      {"honeycomb-zw",
       {"a", "b", "c", "alpha"},
       zhang_wang_defaults,
       [](const Mesh& m, const SchemeParams& p) { return zhang_wang_honeycomb(m, zhang_wang_params(p)); }},
      {"doo-sabin", {}, no_params, [](const Mesh& m, const SchemeParams&) { return doo_sabin(m); }},
      {"loop", {}, no_params, [](const Mesh& m, const SchemeParams&) { return loop(m); }},
      {"sqrt3", {}, no_params, [](const Mesh& m, const SchemeParams&) { return sqrt3(m); }},
      {"dual", {}, no_params, [](const Mesh& m, const SchemeParams&) { return dual(m); }},
      {"dual-honeycomb-dual",
       {"t", "a", "a0", "a1"},
       honeycomb_defaults,
       [](const Mesh& m, const SchemeParams& p) { return dual_honeycomb_dual(m, honeycomb_params(p)); }},
  };
}

}  // namespace dlfl::detail
