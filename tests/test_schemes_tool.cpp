// dlfl schemes [NAME] [--json]: the scheme table as the tool shows it, and subdivide reading typed
// parameters.

#include <doctest/doctest.h>

#ifdef DLFL_TOOL
#include <algorithm>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include <dlfl/schemes/scheme_registry.h>
#include "tool_runner.h"

using namespace dlfl::test;

namespace {

const nlohmann::json* find_named(const nlohmann::json& list, const std::string& name) {
  for (const auto& item : list) {
    if (item["name"] == name) return &item;
  }
  return nullptr;
}

}  // namespace

TEST_CASE("schemes tool: the listing shows every scheme with its doc and each parameter") {
  Run r = run("schemes");
  REQUIRE(r.exit_code == 0);
  CHECK(r.err.empty());
  for (const dlfl::SchemeSpec& s : dlfl::schemes()) {
    CAPTURE(s.name);
    CHECK(r.out.find(s.name + ": " + s.doc + "\n") != std::string::npos);
  }
  // One line per parameter: name, type, default, range or keywords, doc.
  CHECK(r.out.find("  t              number   default 0.5") != std::string::npos);
  CHECK(r.out.find("in [0, 1]               where each edge's point lies") != std::string::npos);
  CHECK(r.out.find("optional: a0 + a1/N for an N-sided face  in (0, 1)") != std::string::npos);
  CHECK(r.out.find("default 'symmetric'") != std::string::npos);
  CHECK(r.out.find("in [0, 1] or 'symmetric'") != std::string::npos);
  CHECK(r.out.find("x,y,z or 'centroid'") != std::string::npos);
  CHECK(r.out.find("random   boolean  default false") != std::string::npos);
  CHECK(r.out.find("seed     integer  default 1           in [0, 9007199254740992]") != std::string::npos);
}

TEST_CASE("schemes tool: NAME shows that scheme only") {
  Run r = run("schemes honeycomb");
  REQUIRE(r.exit_code == 0);
  CHECK(r.out.rfind("honeycomb: Akleman-Srinivasan honeycomb", 0) == 0);
  CHECK(r.out.find("  a1             number   default 1.25") != std::string::npos);
  CHECK(r.out.find("catmull-clark") == std::string::npos);
  CHECK(r.out.find("honeycomb-zw") == std::string::npos);
  Run none = run("schemes mlca");
  REQUIRE(none.exit_code == 0);
  CHECK(none.out == "mlca: " + dlfl::find_scheme("mlca").doc + "\n  (no parameters)\n");
}

TEST_CASE("schemes tool: an unknown name is a usage error with a suggestion and the known names") {
  Run r = run("schemes honeycom");
  CHECK(r.exit_code == 2);
  CHECK(r.out.empty());
  std::string known;
  for (const std::string& n : dlfl::scheme_names()) known += (known.empty() ? "" : ", ") + n;
  CHECK(r.err == "error: unknown scheme 'honeycom' (did you mean 'honeycomb'?; known: " + known + ")\n");
  Run far = run("schemes frobnicate --json");
  CHECK(far.exit_code == 2);
  CHECK(far.err == "error: unknown scheme 'frobnicate' (known: " + known + ")\n");
}

TEST_CASE("schemes tool: --json is the table, typed") {
  Run r = run("schemes --json");
  REQUIRE(r.exit_code == 0);
  const auto list = nlohmann::json::parse(r.out);
  REQUIRE(list.is_array());
  REQUIRE(list.size() == dlfl::schemes().size());
  // The same schemes and parameters, in the same order, as the library's table.
  for (std::size_t i = 0; i < list.size(); ++i) {
    const dlfl::SchemeSpec& s = dlfl::schemes()[i];
    CAPTURE(s.name);
    CHECK(list[i]["name"] == s.name);
    CHECK(list[i]["doc"] == s.doc);
    REQUIRE(list[i]["params"].size() == s.params.size());
    for (std::size_t k = 0; k < s.params.size(); ++k) {
      const auto& p = list[i]["params"][k];
      CHECK(p["name"] == s.params[k].name);
      CHECK(p["type"] == std::string(to_string(s.params[k].type)));
      CHECK(p["doc"] == s.params[k].doc);
      CHECK(p["optional"] == s.params[k].is_optional);
      CHECK(p["keywords"] == s.params[k].keywords);
      CHECK(p.contains("range") == !s.params[k].range_text().empty());
    }
  }
  const auto& honeycomb = *find_named(list, "honeycomb");
  const auto& t = *find_named(honeycomb["params"], "t");
  CHECK(t["default"] == 0.5);
  CHECK(t["range"] == nlohmann::json({{"min", 0.0}, {"max", 1.0}, {"min_open", false}, {"max_open", false}}));
  const auto& a = *find_named(honeycomb["params"], "a");
  CHECK(a["default"].is_null());
  CHECK(a["optional"] == true);
  CHECK(a["range"] == nlohmann::json({{"min", 0.0}, {"max", 1.0}, {"min_open", true}, {"max_open", true}}));
  const auto& zw_a = *find_named((*find_named(list, "honeycomb-zw"))["params"], "a");
  CHECK(zw_a["default"] == "symmetric");
  CHECK(zw_a["keywords"] == nlohmann::json::array({"symmetric"}));
  const auto& mp = (*find_named(list, "mp-pushing"))["params"];
  CHECK((*find_named(mp, "center"))["type"] == "point");
  CHECK((*find_named(mp, "center"))["default"] == "centroid");
  CHECK((*find_named(mp, "random"))["default"] == false);
  CHECK((*find_named(mp, "seed"))["default"] == 1);
  CHECK((*find_named(mp, "seed"))["default"].is_number_integer());
  CHECK((*find_named(mp, "seed"))["range"]["max"] == 9007199254740992.0);
  // An unbounded end is null and open.
  CHECK((*find_named(mp, "ratio"))["range"] ==
        nlohmann::json({{"min", 0.0}, {"max", nullptr}, {"min_open", true}, {"max_open", true}}));
  CHECK((*find_named(list, "mlca"))["params"] == nlohmann::json::array());
  const auto& boundary = *find_named((*find_named(list, "sqrt3"))["params"], "boundary");
  CHECK(boundary["default"] == "curve");
  CHECK(boundary["keywords"] == nlohmann::json::array({"curve", "hole"}));

  Run one = run("schemes mhp --json");
  REQUIRE(one.exit_code == 0);
  const auto single = nlohmann::json::parse(one.out);
  REQUIRE(single.size() == 1);
  CHECK(single[0] == *find_named(list, "mhp"));
}

TEST_CASE("schemes tool: subdivide's help lists the schemes of the table") {
  Run r = run("subdivide --help");
  REQUIRE(r.exit_code == 0);
  std::string names;
  for (const std::string& n : dlfl::scheme_names()) names += (names.empty() ? "" : ", ") + n;
  CHECK(r.out.find("Scheme: " + names) != std::string::npos);
}

TEST_CASE("schemes tool: subdivide reads --param by the declared type and logs typed values") {
  const auto out = scratch("pushed.json");
  const auto log = scratch("pushed.log.json");
  Run r = run("subdivide " + example("cube.obj") +
              " -s mp-pushing --param random=true --param seed=3 --param center=0.1,0,0 -o '" + out.string() +
              "' --log '" + log.string() + "' --self-contained");
  REQUIRE(r.exit_code == 0);
  std::ifstream in(log);
  const auto doc = nlohmann::json::parse(in);
  const auto& params = doc["ops"][1]["params"];
  CHECK(params["random"] == true);
  CHECK(params["seed"] == 3);
  CHECK(params["seed"].is_number_integer());
  CHECK(params["center"] == nlohmann::json({0.1, 0.0, 0.0}));  // a point, written by its type
  CHECK(params["epsilon"] == 0.25);
  const auto replayed = scratch("pushed.replayed.json");
  REQUIRE(run("replay '" + log.string() + "' -o '" + replayed.string() + "'").exit_code == 0);
  const auto a = nlohmann::json::parse(run("info '" + out.string() + "'").out);
  const auto b = nlohmann::json::parse(run("info '" + replayed.string() + "'").out);
  CHECK(a["hash"] == b["hash"]);
  // Another seed gives another mesh: the seed was read and used.
  const auto other = scratch("pushed.other.json");
  REQUIRE(run("subdivide " + example("cube.obj") +
              " -s mp-pushing --param random=true --param seed=4 --param center=0.1,0,0 -o '" +
              other.string() + "'")
              .exit_code == 0);
  CHECK(nlohmann::json::parse(run("info '" + other.string() + "'").out)["hash"] != a["hash"]);
  // Text that is not of the declared type names the parameter.
  Run bad = run("subdivide " + example("cube.obj") + " -s mp-pushing --param random=maybe -o '" +
                scratch("never.json").string() + "'");
  CHECK(bad.exit_code == 2);  // a usage error
  CHECK(bad.err == "error: mp-pushing: parameter random must be true or false, not 'maybe'\n");
}
#endif
