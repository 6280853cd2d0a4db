// The scheme table: every scheme declared once with its parameters; generic checks before any work; the
// parameter sets that operation logs of the old registry hold resolve to the same steps.

#include <doctest/doctest.h>

#include <fstream>
#include <nlohmann/json.hpp>
#include <set>
#include <string>

#include <dlfl/errors.h>
#include <dlfl/io/json_mesh.h>
#include <dlfl/schemes/honeycomb.h>
#include <dlfl/schemes/meng_prautzsch_honeycomb.h>
#include <dlfl/schemes/meng_prautzsch_mixed.h>
#include <dlfl/schemes/meng_prautzsch_pushing.h>
#include <dlfl/schemes/scheme_registry.h>
#include <dlfl/schemes/zhang_wang_honeycomb.h>
#include "scheme_meshes.h"
#include "test_meshes.h"

using namespace dlfl;

namespace {

// The message and parameter of the ParameterError a call throws (empty if none).
template <class F>
std::pair<std::string, std::string> parameter_error(F&& f) {
  try {
    f();
  } catch (const ParameterError& e) {
    return {e.what(), e.parameter()};
  }
  return {};
}

// An old log's parameters as the old oplog reader read them: numbers as doubles, everything else as text.
Params old_log_params(const nlohmann::json& j) {
  Params p;
  for (const auto& [key, value] : j.items()) {
    if (value.is_number()) {
      p[key] = value.get<double>();
    } else {
      p[key] = value.get<std::string>();
    }
  }
  return p;
}

nlohmann::json read_json(const std::string& name) {
  std::ifstream in(std::string(DLFL_SOURCE_DIR) + "/tests/data/oplog_v1/" + name);
  REQUIRE(in);
  return nlohmann::json::parse(in);
}

}  // namespace

TEST_CASE("scheme registry: the twelve schemes, sorted, each documented with its parameters") {
  const std::vector<std::string> expected = {
      "catmull-clark", "doo-sabin", "dual", "dual-honeycomb-dual", "honeycomb",  "honeycomb-zw",
      "loop",          "mhp",       "mlca", "mp-honeycomb",        "mp-pushing", "sqrt3"};
  CHECK(scheme_names() == expected);
  REQUIRE(schemes().size() == expected.size());
  for (const SchemeSpec& s : schemes()) {
    CAPTURE(s.name);
    CHECK_FALSE(s.doc.empty());
    CHECK(s.apply);
    std::set<std::string> names;
    for (const ParamSpec& p : s.params) {
      CAPTURE(p.name);
      CHECK_FALSE(p.doc.empty());
      CHECK(names.insert(p.name).second);  // declared once
      // Every parameter has a default or is optional: a scheme runs with no parameters given.
      CHECK((!p.default_value.empty() || p.is_optional));
    }
    // Defaults pass their own checks, and resolving is idempotent (a logged set resolves to itself).
    const Params full = resolve_scheme_params(s.name, {});
    CHECK(resolve_scheme_params(s.name, full) == full);
    CHECK(&find_scheme(s.name) == &s);
  }
}

TEST_CASE("scheme registry: the declared types") {
  auto type_of = [](const char* scheme, const char* name) {
    for (const ParamSpec& p : find_scheme(scheme).params) {
      if (p.name == name) return p.type;
    }
    FAIL("no parameter ", name, " in ", scheme);
    return ParamType::mesh;
  };
  CHECK(type_of("honeycomb", "t") == ParamType::number);
  CHECK(type_of("honeycomb-zw", "a") == ParamType::number);
  for (const char* mp : {"mp-honeycomb", "mp-pushing", "mhp"}) {
    CAPTURE(mp);
    CHECK(type_of(mp, "center") == ParamType::point);
    CHECK(type_of(mp, "random") == ParamType::boolean);
    CHECK(type_of(mp, "seed") == ParamType::integer);
  }
  CHECK(type_of("mhp", "pattern") == ParamType::text);
  const Params h = resolve_scheme_params("honeycomb", {});
  CHECK(h == Params{{"t", 0.5},
                    {"a0", 0.45},
                    {"a1", 1.25},
                    {"boundary", "curve"},
                    {"sharp_corners", true},
                    {"planarize", std::int64_t{0}}});
  const Params m = resolve_scheme_params("mhp", {{"center", "1,2,3"}, {"random", "true"}, {"seed", "9"}});
  CHECK(m.point("center") == glm::dvec3(1, 2, 3));
  CHECK(m.boolean("random"));
  CHECK(m.integer("seed") == 9);
  CHECK(m.text("pattern") == "HP");
}

TEST_CASE("scheme registry: an unknown scheme suggests the closest name") {
  try {
    find_scheme("honeycom");
    FAIL("accepted");
  } catch (const UnknownNameError& e) {
    CHECK(e.suggestion() == "honeycomb");
    CHECK(std::string(e.what()).rfind("unknown scheme 'honeycom' (did you mean 'honeycomb'?; known: ", 0) ==
          0);
  }
  CHECK_THROWS_AS(apply_scheme(test::cube(), "frobnicate"), UnknownNameError);
}

TEST_CASE("scheme registry: ranges that need no mesh are refused when resolving, naming the parameter") {
  // Before the registry held ranges, t = 2 failed only when the step ran.
  CHECK(parameter_error([] {
          resolve_scheme_params("honeycomb", {{"t", 2.0}});
        }) == std::pair<std::string, std::string>("honeycomb: parameter t = 2 is outside [0, 1]", "t"));
  CHECK(parameter_error([] { resolve_scheme_params("honeycomb", {{"a", 1.0}}); }).second == "a");
  CHECK(parameter_error([] {
          resolve_scheme_params("honeycomb-zw", {{"b", -0.1}});
        }).first == "honeycomb-zw: parameter b = -0.1 is outside [0, 1]");
  CHECK(parameter_error([] {
          resolve_scheme_params("mp-pushing", {{"seed", 0x1.0p53 + 2}});
        }).second == "seed");
  CHECK(parameter_error([] { resolve_scheme_params("mp-pushing", {{"epsilon", 0.5}}); }).second.empty());
  CHECK(parameter_error([] { resolve_scheme_params("mp-pushing", {{"epsilon", 0.6}}); }).second == "epsilon");
  CHECK(parameter_error([] { resolve_scheme_params("mhp", {{"pattern", "H(P"}}); }).second == "pattern");
  CHECK(parameter_error([] {
          resolve_scheme_params("mlca", {{"t", 0.5}});
        }).first == "mlca: unknown parameter 't' (it takes none)");
  CHECK(parameter_error([] { resolve_scheme_params("loop", {{"boundary", "open"}}); }).second == "boundary");
  // The tension's range depends on the face sizes: that check stays in the step.
  CHECK_NOTHROW(resolve_scheme_params("honeycomb", {{"a0", 0.9}}));
  CHECK_THROWS_WITH_AS(apply_scheme(test::cube(), "honeycomb", {{"a0", 0.9}}),
                       doctest::Contains("tension a0 + a1/N"), InvalidArgument);
}

TEST_CASE("scheme registry: a constant tension excludes a0 and a1, and the resolved set drops them") {
  for (const char* scheme : {"honeycomb", "dual-honeycomb-dual"}) {
    CAPTURE(scheme);
    Params expected{{"t", 0.5}, {"a", 0.6}, {"boundary", "curve"}, {"sharp_corners", true}};
    if (std::string(scheme) == "honeycomb")
      expected["planarize"] = std::int64_t{0};  // dual-honeycomb-dual has none
    CHECK(resolve_scheme_params(scheme, {{"a", 0.6}}) == expected);
    const auto [message, parameter] = parameter_error([&] {
      resolve_scheme_params(scheme, {{"a", 0.6}, {"a1", 1.0}});
    });
    CHECK(parameter == "a");
    CHECK(message.rfind(std::string(scheme) + ": give either parameter a", 0) == 0);
  }
  HoneycombParams constant;
  constant.a = 0.6;
  CHECK(apply_scheme(test::cube(), "honeycomb", {{"a", 0.6}}) == honeycomb(test::cube(), constant));
}

TEST_CASE("scheme registry: the Meng-Prautzsch parameters of an old log resolve to the same steps") {
  // tests/data/oplog_v1/v1_meng_prautzsch.json was written by the registry before parameters had types: the
  // centre as text "0.01,0,0", random as 0.0 or 1.0, the seed as a double. Each step applied from those
  // parameters equals the scheme function called with the values they stand for.
  const nlohmann::json log = read_json("v1_meng_prautzsch.json");
  const auto& ops = log["ops"];
  REQUIRE(ops[1]["scheme"] == "mp-honeycomb");
  REQUIRE(ops[2]["scheme"] == "mhp");
  REQUIRE(ops[3]["scheme"] == "mp-pushing");
  const Mesh m0 = mesh_from_json(ops[0]["mesh"], "v1_meng_prautzsch");

  MpHoneycombParams h;
  h.tau = 0.7;
  h.center = glm::dvec3(0.01, 0, 0);
  const Mesh m1 = apply_scheme(m0, "mp-honeycomb", old_log_params(ops[1]["params"]));
  CHECK(m1 == mp_honeycomb(m0, h));

  MhpParams x;
  x.pattern = "H1P1";
  const Mesh m2 = apply_scheme(m1, "mhp", old_log_params(ops[2]["params"]));
  CHECK(m2 == mhp(m1, x));

  MpPushingParams p;
  p.random.enabled = true;
  p.random.seed = 7;
  const Mesh m3 = apply_scheme(m2, "mp-pushing", old_log_params(ops[3]["params"]));
  CHECK(m3 == mp_pushing(m2, p));
  MpPushingParams other_seed = p;
  other_seed.random.seed = 8;
  CHECK_FALSE(m3 == mp_pushing(m2, other_seed));  // the seed matters: the comparison above could fail
}

TEST_CASE("scheme registry: the honeycomb parameters of old logs resolve to the same steps") {
  const Mesh cube = test::cube();
  HoneycombParams t04;
  t04.t = 0.4;
  CHECK(apply_scheme(cube, "honeycomb", old_log_params({{"t", 0.4}, {"a0", 0.45}, {"a1", 1.25}})) ==
        honeycomb(cube, t04));
  ZhangWangParams b06;
  b06.b = 0.6;
  CHECK(apply_scheme(cube, "honeycomb-zw",
                     old_log_params({{"a", "symmetric"}, {"alpha", 0.5}, {"b", 0.6}, {"c", 0.5}})) ==
        zhang_wang_honeycomb(cube, b06));
  ZhangWangParams a04;
  a04.a = 0.4;
  a04.alpha = 0.05;
  CHECK(apply_scheme(cube, "honeycomb-zw",
                     old_log_params({{"a", 0.4}, {"alpha", 0.05}, {"b", 2.0 / 3.0}, {"c", 0.5}})) ==
        zhang_wang_honeycomb(cube, a04));
}
