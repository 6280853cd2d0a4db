// The operations that replace the whole mesh: loading one, setting one, and subdivision schemes. The editor
// keeps the previous mesh whole, so undoing them is a swap.

#include <dlfl/errors.h>
#include <dlfl/io/mesh_io.h>
#include <dlfl/mesh_hash.h>
#include <dlfl/operations/detail/operation_table.h>
#include <dlfl/schemes/scheme_registry.h>

namespace dlfl::detail {

namespace {

// A run whose result cannot have 32-bit handles is refused before its first step, from the scheme's closed
// forms, rather than failing when a step runs out of handles (or memory) hours later.
void check_handle_room(const Mesh& current, const Params& p) {
  const auto predicted = predict_counts(p.text("scheme"), p.get("params").as_params(), counts_of(current),
                                        p.integer("iterations"));
  if (!predicted) return;
  constexpr std::uint64_t limit = CornerId::invalid_index;
  const std::uint64_t corners = 2 * predicted->edges;
  if (corners < limit && predicted->vertices < limit && predicted->faces < limit) return;
  throw ParameterError(std::to_string(p.integer("iterations")) + " steps of " + p.text("scheme") +
                           " would make a mesh of " + std::to_string(predicted->faces) + " faces and " +
                           std::to_string(corners) + " corners, more than 32-bit handles can number (" +
                           std::to_string(limit - 1) + ")",
                       "iterations");
}

}  // namespace

std::vector<OperationSpec> whole_mesh_operation_specs() {
  std::vector<OperationSpec> ops;

  ops.push_back(replace_operation(
      "load", "makes a mesh read from a file the current mesh",
      {param("path", ParamType::text, "the file it was read from"),
       param("mesh", ParamType::mesh, "the mesh itself (self-contained logs)").optional("read from path"),
       param("hash", ParamType::text, "the mesh's mesh_hash when it was loaded; a different mesh is refused")
           .optional("not checked")},
      [](const Mesh&, const Params& p) {
        Mesh m = p.has("mesh") ? p.get("mesh").as_mesh() : read_mesh(p.text("path"));
        // A log that reads its input again must get the mesh it was written with.
        if (p.has("hash") && mesh_hash(m) != p.text("hash")) {
          throw ParameterError("the mesh of " + p.text("path") +
                                   " has changed since the log was written (hash " + mesh_hash(m) +
                                   ", the log expects " + p.text("hash") +
                                   "); replay with --no-verify to use it as it is now",
                               "hash");
        }
        return m;
      }));

  ops.push_back(replace_operation("mesh", "makes the given mesh the current mesh",
                                  {param("mesh", ParamType::mesh, "the mesh")},
                                  [](const Mesh&, const Params& p) { return p.get("mesh").as_mesh(); }));

  ops.push_back(replace_operation(
      "subdivide", "applies a subdivision scheme a number of times (dlfl schemes lists them)",
      {param("scheme", ParamType::text, "the scheme's name"),
       param("iterations", ParamType::integer, 1, "number of steps").in(0, 64),
       param("params", ParamType::params, Params{}, "the scheme's parameters")},
      [](const Mesh& current, const Params& p) {
        const std::string& scheme = p.text("scheme");
        const Params& params = p.get("params").as_params();
        const auto n = p.integer("iterations");
        // Each step reads the previous mesh and builds a new one; the current mesh is never touched.
        Mesh next = n == 0 ? current : apply_scheme(current, scheme, params);
        for (std::int64_t i = 1; i < n; ++i) next = apply_scheme(next, scheme, params);
        return next;
      },
      [](const Mesh& current, Params& p) {
        // Resolved now, so that an unknown scheme or a bad value fails before any work, and the log records
        // every parameter in force.
        try {
          p["params"] = resolve_scheme_params(p.text("scheme"), p.get("params").as_params());
        } catch (const UnknownNameError& e) {
          throw ParameterError(e.what(), "scheme");
        } catch (const ParameterError& e) {
          throw ParameterError(e.what(), "params." + e.parameter());
        }
        check_handle_room(current, p);
      }));
  return ops;
}

}  // namespace dlfl::detail
