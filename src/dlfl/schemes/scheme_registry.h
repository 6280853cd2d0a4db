#pragma once
// Schemes by name. Each scheme declares itself once, next to its implementation (a `SchemeSpec` with its
// parameters); generic code checks parameters, fills in defaults and refuses bad values before any work. The
// editor, the operation log and `dlfl subdivide` / `dlfl schemes` all read this table.

#include <cstdint>
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include <dlfl/mesh.h>
#include <dlfl/parameters.h>
#include <dlfl/schemes/origins.h>

namespace dlfl {

/// Element counts for predictions: vertices, edges and faces (hole faces included; corners are 2 x edges).
struct MeshCounts {
  std::uint64_t vertices = 0, edges = 0, faces = 0;
  bool operator==(const MeshCounts&) const = default;
};

/// The counts of a mesh, point spheres left out (each is a vertex and a face without edges).
MeshCounts counts_of(const Mesh& mesh);

/// The declaration of one scheme. Each scheme's .cpp defines its own (see detail/scheme_table.h); adding a
/// scheme is one new file plus one line in scheme_registry.cpp.
struct SchemeSpec {
  std::string name;
  /// One line for listings.
  std::string doc;
  std::vector<ParamSpec> params;
  /// Checks that involve several parameters, run on the resolved set after the generic checks; it may also
  /// drop defaults that do not apply (honeycomb: a constant `a` replaces a0/a1). `given` is what the caller
  /// passed. Optional.
  std::function<void(const Params& given, Params& resolved)> check;
  /// One step on `mesh` with resolved parameters. Fills `origins` when it is not null (see the scheme's
  /// header for what each output element's origin is).
  std::function<Mesh(const Mesh& mesh, const Params& params, Origins* origins)> apply;
  /// The counts after one step, by the closed forms in the scheme's header (exact for a mesh without point
  /// spheres; on an open mesh under boundary=curve the points a boundary rule adds along the boundary, which
  /// V, E and F do not tell, are left out), for predicting the size of a run before it starts. Optional.
  std::function<MeshCounts(const MeshCounts& counts, const Params& params)> counts;
};

// Deprecated, to be removed once the editor and the operation log are rewritten on Params: the names of the
// parameter types before the registry. New code uses Params and Value.
using SchemeParams = Params;
using ParamValue = Value;

/// Every registered scheme, sorted by name.
std::span<const SchemeSpec> schemes();

/// Names of the registered schemes, sorted.
std::vector<std::string> scheme_names();

/// The scheme called `name`. Throws UnknownNameError (with a "did you mean" suggestion) otherwise.
const SchemeSpec& find_scheme(std::string_view name);

/// The full parameter set for a scheme: every given value checked (known name, type, range), every default
/// filled in, the scheme's own cross-checks run. Logging the result records all parameters. Throws
/// UnknownNameError for an unknown scheme and ParameterError naming the parameter.
Params resolve_scheme_params(std::string_view scheme, const Params& given);

/// The counts after `iterations` steps of the named scheme with resolved `params`, from `start`; nullopt
/// when the scheme declares no counts. Stops growing past 2^40 (far beyond what handles hold), so it never
/// overflows.
std::optional<MeshCounts> predict_counts(std::string_view scheme, const Params& params, MeshCounts start,
                                         std::int64_t iterations);

/// Told of every scheme step that its thread runs through apply_scheme (so through the editor, the log and
/// the tool alike): for progress reports. Its functions must not throw.
class StepObserver {
 public:
  virtual ~StepObserver() = default;
  /// A step of `scheme` on `input` starts.
  virtual void step_started(std::string_view scheme, const Mesh& input) = 0;
  /// That step made `output`.
  virtual void step_finished(std::string_view scheme, const Mesh& output) = 0;
};

/// Makes an observer the calling thread's for the lifetime of this object, then restores the one before.
class ObservedSteps {
 public:
  explicit ObservedSteps(StepObserver& observer);
  ~ObservedSteps();
  ObservedSteps(const ObservedSteps&) = delete;
  ObservedSteps& operator=(const ObservedSteps&) = delete;

 private:
  StepObserver* previous_;
};

/// One step of the named scheme. `params` are resolved first (so a partial set is fine). The input is not
/// modified. Fills `origins` when it is not null.
Mesh apply_scheme(const Mesh& mesh, std::string_view scheme, const Params& params = {},
                  Origins* origins = nullptr);

}  // namespace dlfl
