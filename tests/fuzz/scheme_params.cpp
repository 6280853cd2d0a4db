// `dlfl subdivide --param NAME=VALUE` values (parse_assignment, resolve_scheme_params): each line of the
// input is one --param; the set is resolved against every scheme. Where it resolves, resolving the result
// again gives the same set, and one step through an Editor on a tiny mesh (the tetrahedron for loop and
// sqrt3, the cube otherwise) either fails with a dlfl::Error or gives a valid mesh whose log replays to an
// equal one. MHP patterns of more than fuzz::max_pattern_steps steps are resolved but not run.

#include <dlfl/errors.h>
#include <dlfl/history/editor.h>
#include <dlfl/history/oplog.h>
#include <dlfl/parameters.h>
#include <dlfl/schemes/meng_prautzsch_mixed.h>
#include <dlfl/schemes/scheme_registry.h>
#include <dlfl/validate.h>

#include "fuzz_common.h"
#include "small_meshes.h"

namespace dlfl::fuzz {
inline constexpr std::size_t max_pattern_steps = 4;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace dlfl;
  if (size > 4096) return 0;
  Params given;
  try {
    for (std::string_view line : fuzz::lines_of(fuzz::text_of(data, size), 32)) {
      auto [name, value] = parse_assignment(line);
      if (given.has(name)) return 0;  // the tool: ParameterError "given twice"
      given[name] = std::move(value);
    }
  } catch (const Error&) {
    return 0;
  }
  for (const SchemeSpec& scheme : schemes()) {
    Params resolved;
    try {
      resolved = resolve_scheme_params(scheme.name, given);
    } catch (const Error&) {
      continue;
    }
    try {
      fuzz::check(resolve_scheme_params(scheme.name, resolved) == resolved,
                  "resolving the resolved parameters of " + scheme.name + " changes them");
    } catch (const Error& e) {
      fuzz::finding("the resolved parameters of " + scheme.name + " do not resolve again: " + e.what());
    }
    if (scheme.name == "mhp") {
      std::size_t steps = 0;
      try {
        steps = expand_mhp_pattern(resolved.text("pattern")).size();
      } catch (const Error& e) {
        fuzz::finding(std::string("mhp resolved a pattern that does not expand: ") + e.what());
      }
      if (steps > fuzz::max_pattern_steps) continue;
    }
    const bool triangles = scheme.name == "loop" || scheme.name == "sqrt3";
    Editor editor;
    editor.set_mesh(triangles ? fuzz::tetrahedron() : fuzz::cube());
    try {
      editor.subdivide(scheme.name, given, 1);
    } catch (const Error&) {
      continue;  // the scheme refuses the mesh or the combination of values
    }
    const ValidationReport report = validate(editor.mesh(), 1);
    if (!report.valid()) {
      fuzz::finding(scheme.name + " made an invalid mesh: " + report.violations.at(0).message);
    }
    try {
      fuzz::check(replay_log(log_text(editor), "rewritten").mesh() == editor.mesh(),
                  "the log of " + scheme.name + " replays to a different mesh");
    } catch (const Error& e) {
      fuzz::finding("the log of " + scheme.name + " does not replay: " + e.what());
    }
  }
  return 0;
}
