#pragma once
// The editor: one mesh, an undo/redo history, and a log of everything done to it.
//
// Every Euler operator applied through the editor is undone by its exact inverse (same handles, bit-identical
// positions). Applying a scheme, loading or setting a mesh keeps the previous mesh M_n whole, so undoing it
// is O(1) and gives back exactly M_n; redo gives back M_{n+1}. Fine-grained steps and whole-mesh steps
// interleave freely.

#include <cstddef>
#include <deque>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include <dlfl/create_face_manifold.h>
#include <dlfl/mesh.h>
#include <dlfl/schemes/scheme_registry.h>

namespace dlfl {

class Editor {
 public:
  struct Options {
    /// Put the mesh itself (native JSON) into the log's load ops, making the log self-contained.
    bool embed_meshes = false;
    /// Most undoable entries kept; the oldest are dropped first. 0 keeps everything.
    std::size_t undo_limit = 0;
  };

  Editor() = default;
  explicit Editor(Options options) : options_(options) {}

  /// The current mesh.
  const Mesh& mesh() const { return mesh_; }
  const Options& options() const { return options_; }

  // ---- whole-mesh operations (undo swaps meshes: O(1))
  // -------------------------------------------------------

  /// Reads a mesh file (any format `read_mesh` knows) and makes it the current mesh. Logged with its absolute
  /// path, plus the mesh itself when `embed_meshes` is set.
  void load(const std::filesystem::path& path);
  /// Makes `mesh` the current mesh. Logged with the mesh inline.
  void set_mesh(Mesh mesh);
  /// Applies a scheme `iterations` times (one undo entry for all of them). Parameters are resolved with their
  /// defaults and logged in full. The current mesh changes only if every iteration succeeds.
  void subdivide(const std::string& scheme, const SchemeParams& params = {}, int iterations = 1);

  // ---- Euler operators (undo applies the exact inverse)
  // -------------------------------------------------------

  VertexId create_vertex(const glm::dvec3& position);
  void delete_vertex(VertexId v);
  InsertEdgeResult insert_edge(CornerId c1, CornerId c2);
  DeleteEdgeResult delete_edge(EdgeId e);
  VertexId subdivide_edge(EdgeId e, const glm::dvec3& position);
  void unsubdivide_edge(VertexId v);
  void set_position(VertexId v, const glm::dvec3& position);
  /// Sets a face's control point (the central control vertex of the Zhang-Wang honeycomb scheme), or clears
  /// it with `std::nullopt`, as one undoable entry. Throws InvalidArgument for a removed face or a non-finite
  /// point.
  void set_face_point(FaceId f, const std::optional<glm::dvec3>& point);
  /// CREATEFACEMANIFOLD as one undoable entry; `vertices`, `front_corners`, `back_corners` as in the free
  /// function.
  FaceManifold create_face_manifold(std::span<const glm::dvec3> positions, std::span<VertexId> vertices = {},
                                    std::span<CornerId> front_corners = {},
                                    std::span<CornerId> back_corners = {});

  // ---- history
  // ---------------------------------------------------------------------------------------------

  /// Undoes the latest entry; returns false (and logs nothing) if there is none.
  bool undo();
  /// Redoes the latest undone entry; returns false (and logs nothing) if there is none. Any new operation
  /// clears the redo list.
  bool redo();
  bool can_undo() const { return !undo_.empty(); }
  bool can_redo() const { return !redo_.empty(); }

  // ---- the operation log
  // -------------------------------------------------------------------------------------

  /// The session so far as a versioned document: {"format": "dlfl-oplog", "version": 1, "undo_limit": N,
  /// "ops": [...]} (see docs/oplog.md). Replaying it gives a mesh equal to `mesh()`.
  nlohmann::json log() const;

 private:
  // One undoable entry: Euler steps to apply back to front, or a whole mesh to swap with the current one.
  struct Entry {
    std::vector<Step> steps;
    std::optional<Mesh> mesh;
  };
  void push(Entry entry, nlohmann::json op);
  Step run(const Step& step, nlohmann::json op);  // applies one operator as its own entry
  static void flip(Mesh& mesh, Entry& entry);     // undo or redo an entry, turning it into its opposite

  Options options_;
  Mesh mesh_;
  std::deque<Entry> undo_;
  std::vector<Entry> redo_;
  nlohmann::json ops_ = nlohmann::json::array();
};

}  // namespace dlfl
