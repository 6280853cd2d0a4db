#pragma once
// Operations as data. Every operation that changes a mesh is declared once, next to its implementation: its
// name, its parameters (name, type, default, range, one line of documentation) and the function that runs
// it. The editor applies any of them by name as one undo entry; the operation log writes and reads them from
// these declarations; `dlfl ops` lists them and `dlfl edit --op` runs them.
//
// Three kinds:
// - edit operations change the mesh only through a Transaction (the Euler operators), so their exact undo is
//   the transaction's record;
// - replace operations build a whole new mesh from the current one (load, subdivide); undo swaps meshes;
// - history operations (undo, redo, groups) act on the editor itself and are carried out by it.

#include <functional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include <dlfl/mesh.h>
#include <dlfl/operations/transaction.h>
#include <dlfl/parameters.h>

namespace dlfl {

/// The declaration of one operation.
struct OperationSpec {
  enum class Kind : std::uint8_t { edit, replace, history };

  std::string name;
  Kind kind = Kind::edit;
  /// One line for listings.
  std::string doc;
  std::vector<ParamSpec> params;
  /// The change of the element counts, for listings: "V+1 E+0 F+1" or a closed form ("E+n, F+n-1").
  std::string counts;
  /// Checks against the mesh that the generic ones (types, ranges, live handles) cannot make, run before
  /// anything changes (a face given twice, a hole where a face is needed). Throws ParameterError. It may also
  /// complete the set, so that the log records every value in force (subdivide resolves the scheme's own
  /// parameters). Optional.
  std::function<void(const Mesh& mesh, Params& params)> check;
  /// Edit operations: changes the mesh through `tx` and returns what it made (new handles by name).
  std::function<Params(Transaction& tx, const Params& params)> edit;
  /// Replace operations: the new mesh, built from the current one.
  std::function<Mesh(const Mesh& current, const Params& params)> replace;
};

using EditFunction = std::function<Params(Transaction& tx, const Params& params)>;
using ReplaceFunction = std::function<Mesh(const Mesh& current, const Params& params)>;
using CheckFunction = std::function<void(const Mesh& mesh, Params& params)>;

/// Declarations, one per kind: `edit_operation("create_vertex", "doc", {param(...)}, "V+1, E+0, F+1", fn)`.
OperationSpec edit_operation(std::string name, std::string doc, std::vector<ParamSpec> params,
                             std::string counts, EditFunction edit, CheckFunction check = {});
OperationSpec replace_operation(std::string name, std::string doc, std::vector<ParamSpec> params,
                                ReplaceFunction replace, CheckFunction check = {});
OperationSpec history_operation(std::string name, std::string doc, std::vector<ParamSpec> params = {});

/// An edit operation without parameters over the whole mesh that reports how many elements it changed, as
/// the integer output `output` (remove_2gons: "two_gons_removed").
OperationSpec counting_operation(std::string name, std::string doc, std::string counts, std::string output,
                                 std::function<std::size_t(Transaction& tx)> run);

/// Every registered operation, sorted by name.
std::span<const OperationSpec> operations();

/// Names of the registered operations, sorted.
std::vector<std::string> operation_names();

/// The operation called `name`. Throws UnknownNameError (with a "did you mean" suggestion) otherwise.
const OperationSpec& find_operation(std::string_view name);

/// The full parameter set of an operation for the current mesh: every value checked (known name, type,
/// range, handles alive in `mesh`), every default filled in, then the operation's own `check`. Throws
/// ParameterError naming the parameter.
Params resolve_operation_params(const OperationSpec& op, const Params& given, const Mesh& mesh);

/// Runs an edit or replace operation on `mesh` directly, without an editor: resolves the parameters, runs
/// it, and returns its outputs (empty for a replace operation). On any error the mesh is unchanged. Throws
/// InvalidArgument for a history operation (those need an Editor).
Params apply_operation(Mesh& mesh, std::string_view name, const Params& params = {});

}  // namespace dlfl
