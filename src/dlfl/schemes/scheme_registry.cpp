#include <dlfl/schemes/scheme_registry.h>

#include <algorithm>

#include <dlfl/errors.h>
#include <dlfl/format.h>
#include <dlfl/schemes/detail/scheme_table.h>

namespace dlfl {
namespace {

// Every scheme, once: one line per scheme.
std::vector<SchemeSpec> all_schemes() {
  return {
      detail::catmull_clark_scheme(), detail::doo_sabin_scheme(),
      detail::dual_scheme(),          detail::dual_honeycomb_dual_scheme(),
      detail::honeycomb_scheme(),     detail::zhang_wang_honeycomb_scheme(),
      detail::loop_scheme(),          detail::mhp_scheme(),
      detail::mlca_scheme(),          detail::mp_honeycomb_scheme(),
      detail::mp_pushing_scheme(),    detail::sqrt3_scheme(),
  };
}

const std::vector<SchemeSpec>& table() {
  static const std::vector<SchemeSpec> sorted = [] {
    std::vector<SchemeSpec> all = all_schemes();
    std::sort(all.begin(), all.end(),
              [](const SchemeSpec& a, const SchemeSpec& b) { return a.name < b.name; });
    return all;
  }();
  return sorted;
}

}  // namespace

std::span<const SchemeSpec> schemes() { return table(); }

std::vector<std::string> scheme_names() { return names_of(table()); }

const SchemeSpec& find_scheme(std::string_view name) { return find_named(table(), "scheme", name); }

namespace {
Params resolve(const SchemeSpec& spec, const Params& given) {
  Params resolved = resolve_params(spec.name, spec.params, given);
  if (spec.check) spec.check(given, resolved);
  return resolved;
}
}  // namespace

Params resolve_scheme_params(std::string_view scheme, const Params& given) {
  return resolve(find_scheme(scheme), given);
}

namespace {
thread_local StepObserver* step_observer = nullptr;
}  // namespace

ObservedSteps::ObservedSteps(StepObserver& observer) : previous_(step_observer) { step_observer = &observer; }
ObservedSteps::~ObservedSteps() { step_observer = previous_; }

Mesh apply_scheme(const Mesh& mesh, std::string_view scheme, const Params& params, Origins* origins) {
  const SchemeSpec& spec = find_scheme(scheme);
  const Params resolved = resolve(spec, params);
  if (step_observer) step_observer->step_started(spec.name, mesh);
  Mesh result = spec.apply(mesh, resolved, origins);
  if (step_observer) step_observer->step_finished(spec.name, result);
  return result;
}

MeshCounts counts_of(const Mesh& mesh) {
  std::uint64_t spheres = 0;
  for (VertexId v : mesh.vertices()) spheres += mesh.is_point_sphere(v);
  return {mesh.num_vertices() - spheres, mesh.num_edges(), mesh.num_faces() - spheres};
}

std::optional<MeshCounts> predict_counts(std::string_view scheme, const Params& params, MeshCounts start,
                                         std::int64_t iterations) {
  const SchemeSpec& spec = find_scheme(scheme);
  if (!spec.counts) return std::nullopt;
  constexpr std::uint64_t far = std::uint64_t{1} << 40;
  for (std::int64_t i = 0; i < iterations; ++i) {
    if (start.vertices > far || start.edges > far || start.faces > far) break;
    start = spec.counts(start, params);
  }
  return start;
}

}  // namespace dlfl
