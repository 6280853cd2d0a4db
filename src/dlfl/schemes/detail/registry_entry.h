#pragma once
// Internal to the scheme registry: one entry per scheme, and the lists each family of schemes contributes.
// Each family keeps its entries in its own registry_*.cpp file, so adding a scheme touches one file.

#include <functional>
#include <string>
#include <vector>

#include <dlfl/errors.h>
#include <dlfl/schemes/registry.h>

namespace dlfl::detail {

struct SchemeEntry {
  const char* name;
  std::vector<std::string> params;                          // every parameter name the scheme knows
  std::function<SchemeParams(SchemeParams)> fill_defaults;  // given (names known) -> full set, cross-checked
  std::function<Mesh(const Mesh&, const SchemeParams&)> apply;
};

/// The number parameter `name`; InvalidArgument naming the scheme and parameter if missing or text.
inline double number(const SchemeParams& p, const char* scheme, const char* name) {
  auto it = p.find(name);
  if (it == p.end()) throw InvalidArgument(std::string(scheme) + ": parameter " + name + " is missing");
  if (const double* d = std::get_if<double>(&it->second)) return *d;
  throw InvalidArgument(std::string(scheme) + ": parameter " + name + " must be a number, not '" +
                        std::get<std::string>(it->second) + "'");
}

/// Catmull-Clark, honeycomb, Zhang-Wang honeycomb, Doo-Sabin, Loop, sqrt(3), dual, dual-honeycomb-dual.
std::vector<SchemeEntry> classic_scheme_entries();
/// Meng-Prautzsch H, P and mixed MHP refinement of convex polyhedra.
std::vector<SchemeEntry> meng_prautzsch_scheme_entries();
/// MLCA on polygon meshes (split to quads, then the d = 2 scheme).
std::vector<SchemeEntry> mlca_scheme_entries();

}  // namespace dlfl::detail
