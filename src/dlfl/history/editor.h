#pragma once
// The editor: one mesh, an undo/redo history, and a record of everything done to it (the operation log).
//
// Any registered operation (dlfl/operations/operation.h) is applied by name as one undo entry. Edit
// operations are undone by the exact inverses their transaction recorded (same handles, bit-identical
// positions). Loading, setting a mesh and subdivision keep the previous mesh M_n whole, so undoing them is
// O(1) and gives back exactly M_n; redo gives back M_{n+1}. Groups make several operations one entry.

#include <cstddef>
#include <deque>
#include <filesystem>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

#include <dlfl/create_face_manifold.h>
#include <dlfl/mesh.h>
#include <dlfl/operations/transaction.h>
#include <dlfl/parameters.h>

namespace dlfl {

/// One operation as the log records it: its name and its full parameter set (defaults included).
struct LoggedOperation {
  std::string name;
  Params params;
};

class Editor {
 public:
  struct Options {
    /// Keep the loaded mesh itself in the log's load operations, making the log self-contained.
    bool embed_meshes = false;
    /// Most undo entries kept; the oldest are dropped first. 0 keeps everything.
    std::size_t undo_limit = 0;
    /// false: nothing is kept for undo, so a replaced mesh (M_n after a subdivision) is freed as soon as its
    /// successor is built, and `undo` has nothing to do. For callers that never undo: the `dlfl` tool's
    /// subdivide, and its edit and replay when they hold no undo or redo op.
    bool keep_history = true;
  };

  /// One entry of the history, as `undo_history` and `redo_history` report it.
  struct HistoryEntry {
    /// The operation's name, or the group's label.
    std::string label;
    /// Operations in the entry (1 unless it is a group).
    std::size_t operations = 0;
  };

  Editor() = default;
  explicit Editor(Options options) : options_(options) {}

  /// The current mesh.
  const Mesh& mesh() const { return mesh_; }
  const Options& options() const { return options_; }

  // ---- any registered operation
  // ----------------------------------------------------------------------------------------

  /// Applies the operation called `name` with `params` (defaults filled in, everything checked before the
  /// mesh changes) as one undo entry, or as part of the open group. Returns the operation's outputs (the
  /// handles it made, by name). History operations (undo, redo, begin_group, end_group, clear_history) are
  /// carried out as the functions of the same name; `undo` and `redo` with nothing to do throw
  /// InvalidArgument here. On any error the mesh, the history and the log are unchanged.
  Params apply(std::string_view name, const Params& params = {});

  // ---- whole-mesh operations (undo swaps meshes: O(1))
  // ---------------------------------------------------------

  /// Makes `mesh` the current mesh. With a `source` path it is logged as `load` of that path (and, with
  /// `embed_meshes`, the mesh itself); without one, as `mesh` with the mesh inline.
  void set_mesh(Mesh mesh, const std::optional<std::filesystem::path>& source = std::nullopt);
  /// Applies a scheme `iterations` times (one undo entry for all of them). Parameters are resolved with
  /// their defaults and logged in full. The current mesh changes only if every iteration succeeds.
  void subdivide(std::string_view scheme, const Params& params = {}, int iterations = 1);

  // ---- the Euler operators, typed (each is `apply` of the operation of the same name)
  // --------------------------

  VertexId create_vertex(const glm::dvec3& position);
  void delete_vertex(VertexId v);
  /// The result's `inverse` is left empty: the editor keeps the undo record itself.
  InsertEdgeResult insert_edge(CornerId c1, CornerId c2);
  /// The result's `inverse` is left empty: the editor keeps the undo record itself.
  DeleteEdgeResult delete_edge(EdgeId e);
  VertexId subdivide_edge(EdgeId e, const glm::dvec3& position);
  void unsubdivide_edge(VertexId v);
  void set_position(VertexId v, const glm::dvec3& position);
  /// Sets (or, with `std::nullopt`, clears) a face's control point, the central control vertex of the
  /// Zhang-Wang honeycomb scheme: `apply("set_face_point", ...)`.
  void set_face_point(FaceId f, const std::optional<glm::dvec3>& point);
  /// CREATEFACEMANIFOLD as one undoable entry.
  FaceManifold create_face_manifold(std::span<const glm::dvec3> positions);

  // ---- groups and history
  // ----------------------------------------------------------------------------------------------

  /// Starts a group: every operation until the matching `end_group` becomes one undo entry labelled `label`.
  /// Groups nest; the outermost one makes the entry.
  void begin_group(std::string label);
  /// Ends the group begun last. An empty group adds no entry. Throws InvalidArgument if none is open.
  void end_group();
  /// Number of groups open.
  std::size_t group_depth() const { return groups_.size(); }

  /// Undoes the latest entry; returns false (and logs nothing) if there is none. Throws InvalidArgument
  /// while a group is open.
  bool undo();
  /// Redoes the latest undone entry; returns false (and logs nothing) if there is none. Any new operation
  /// clears the redo list. Throws InvalidArgument while a group is open.
  bool redo();
  bool can_undo() const { return !undo_.empty(); }
  bool can_redo() const { return !redo_.empty(); }
  /// The entries that `undo` would undo, oldest first (the last is undone first).
  std::vector<HistoryEntry> undo_history() const;
  /// The entries that `redo` would redo, the next to redo last.
  std::vector<HistoryEntry> redo_history() const;
  /// Forgets every undo and redo entry (the mesh and the log stay). Throws InvalidArgument while a group is
  /// open.
  void clear_history();

  // ---- the operation log
  // ------------------------------------------------------------------------------------------------

  /// Everything applied so far, in order, undo and redo included; replaying it (dlfl/history/oplog.h) gives a
  /// mesh equal to `mesh()`.
  const std::vector<LoggedOperation>& log() const { return log_; }

 private:
  // A part of an undo entry: the inverses of an edit operation, or the other mesh of a swap.
  using Part = std::variant<ChangeRecord, Mesh>;
  struct Entry {
    std::string label;
    std::size_t operations = 0;
    std::vector<Part> parts;
  };
  struct OpenGroup {
    std::string label;
    Entry entry;
  };

  void record(std::string label, Part part);  // adds a part as its own entry or to the open group
  void push(Entry entry);                     // onto the undo list, trimmed to the undo limit
  void require_no_group(const char* what) const;
  static void flip(Mesh& mesh, Entry& entry);  // undo or redo an entry, turning it into its opposite
  // `undo` or `redo` (`op`): the latest entry of `from`, flipped and handed to `keep`, and logged.
  template <class Entries, class Keep>
  bool flip_latest(const char* op, Entries& from, const Keep& keep);

  Options options_;
  Mesh mesh_;
  std::deque<Entry> undo_;
  std::vector<Entry> redo_;
  std::vector<OpenGroup> groups_;
  std::vector<LoggedOperation> log_;
};

}  // namespace dlfl
