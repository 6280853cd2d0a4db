// dlfl.Editor: any registered operation by name (the package turns each into a method, python/dlfl/
// __init__.py), subdivision, undo and redo, groups, the history, and the operation log; dlfl.replay.

#include <dlfl/history/oplog.h>
#include <dlfl/io/mesh_io.h>
#include <dlfl/operations/operation.h>
#include "binding.h"

namespace dlfl::python {
namespace {

using Box = std::shared_ptr<EditorBox>;

// Runs f(editor) under the editor's lock; with the GIL released too when `long_work` (whole-mesh operations,
// files).
template <class F>
auto edit(EditorBox& box, bool long_work, F f) {
  EditorLock lock(box);
  if (!long_work) return f(box.editor);
  py::gil_scoped_release no_gil;
  return f(box.editor);
}

// Makes `mesh` (a Mesh, or a path to read) the editor's mesh, logged as "mesh" or as "load" of the path.
void set_mesh(EditorBox& box, py::handle mesh, py::handle source) {
  std::optional<std::filesystem::path> path;
  if (!source.is_none()) path = path_text(source);
  Mesh copy;
  if (py::isinstance<MeshRef>(mesh)) {
    copy = *mesh.cast<const MeshRef&>().snapshot();
  } else {
    if (!path) path = path_text(mesh);
    py::gil_scoped_release no_gil;
    copy = read_mesh(*path);
  }
  edit(box, true, [&](Editor& e) {
    e.set_mesh(std::move(copy), path);
    return 0;
  });
}

py::list history(const std::vector<Editor::HistoryEntry>& entries) {
  py::list out;
  for (const auto& e : entries) {
    py::dict d;
    d["label"] = e.label;
    d["operations"] = e.operations;
    out.append(d);
  }
  return out;
}

}  // namespace

void bind_editor(py::module_& m) {
  py::class_<EditorBox, Box> c(m, "Editor",
                               R"doc(An editing session: one mesh, an undo/redo history and the operation log.

Every registered operation (dlfl.operations()) is a method taking its parameters positionally in declaration
order or by keyword, with the declared defaults: ed.insert_edge(c1, c2), ed.connect_faces(face1=3, face2=9,
segments=4); each returns its outputs (the handles it made) as a dict and is one undo entry, or part of the
open group. Parameters are checked before the mesh changes; on any error the mesh, history and log are
unchanged. An editor may be shared by threads: each call holds it, and the GIL is released during
whole-mesh operations (subdivision, loading).)doc");
  c.def(
      py::init([](py::object mesh, bool embed_meshes, std::size_t undo_limit) {
        auto box = std::make_shared<EditorBox>(Editor::Options{embed_meshes, undo_limit});
        if (!mesh.is_none()) set_mesh(*box, mesh, py::none());
        return box;
      }),
      R"doc(An editor, starting from `mesh` (a Mesh, copied, logged inline as op "mesh"; or a path, read and logged
as op "load" with the mesh's hash) or from an empty mesh. embed_meshes keeps loaded meshes inside the log,
making it self-contained; undo_limit bounds the history (0: unlimited).)doc",
      py::arg("mesh") = py::none(), py::kw_only(), py::arg("embed_meshes") = false,
      py::arg("undo_limit") = 0);
  c.def_property_readonly(
      "mesh", [](const Box& self) { return MeshRef(self); },
      "The current mesh, live: it follows the editor's operations (mesh.copy() keeps it as it is now).");
  c.def(
      "apply",
      // The name is taken from *args, so that an operation may have a parameter called "name"
      // (set_attribute).
      [](EditorBox& self, const py::args& args, const py::kwargs& kwargs) {
        if (args.empty() || !py::isinstance<py::str>(args[0])) {
          throw py::type_error("Editor.apply(name, /, *args, **kwargs): the operation's name comes first");
        }
        const OperationSpec& op = find_operation(args[0].cast<std::string>());
        const py::args rest =
            py::reinterpret_steal<py::args>(PySequence_GetSlice(args.ptr(), 1, py::len(args)));
        const Params params = to_params(op.name, op.params, rest, kwargs);
        const bool whole_mesh = op.kind == OperationSpec::Kind::replace;
        return to_python(edit(self, whole_mesh, [&](Editor& e) { return e.apply(op.name, params); }));
      },
      "apply(name, /, *args, **kwargs): applies the registered operation `name` (positional parameters in "
      "declaration order, or keywords) as one undo entry; returns its outputs as a dict. A wrong keyword "
      "raises ParameterError naming the operation and its known parameters.");
  c.def(
      "subdivide",
      [](EditorBox& self, const std::string& scheme, std::int64_t iterations, const py::kwargs& params) {
        const Params given = subdivide_params(scheme, iterations, params);
        edit(self, true, [&](Editor& e) { return e.apply("subdivide", given); });
      },
      "Applies `iterations` steps of a scheme, its parameters as keywords, as one undo entry (undo gives "
      "back the previous mesh exactly). The GIL is released meanwhile.",
      py::arg("scheme"), py::arg("iterations") = 1);
  c.def(
      "set_mesh", [](EditorBox& self, py::handle mesh, py::handle source) { set_mesh(self, mesh, source); },
      "Makes a copy of `mesh` the current mesh (one undo entry), logged as op \"mesh\"; with a source path, "
      "as op \"load\" of that file (which a replay reads again).",
      py::arg("mesh"), py::arg("source") = py::none());
  c.def(
      "undo", [](EditorBox& self) { return edit(self, false, [](Editor& e) { return e.undo(); }); },
      "Undoes the latest entry exactly; False if there is none. Raises InvalidArgument inside a group.");
  c.def(
      "redo", [](EditorBox& self) { return edit(self, false, [](Editor& e) { return e.redo(); }); },
      "Redoes the latest undone entry; False if there is none. Raises InvalidArgument inside a group.");
  const auto property = [&c](const char* name, auto get, const char* doc) {
    c.def_property_readonly(
        name, [get](EditorBox& self) { return edit(self, false, [get](Editor& e) { return (e.*get)(); }); },
        doc);
  };
  property("can_undo", &Editor::can_undo, "True if there is an entry to undo.");
  property("can_redo", &Editor::can_redo, "True if there is an entry to redo.");
  property("group_depth", &Editor::group_depth, "The number of groups open.");
  c.def(
      "undo_history",
      [](EditorBox& self) { return history(edit(self, false, [](Editor& e) { return e.undo_history(); })); },
      "The entries undo would undo, oldest first: [{'label', 'operations'}].");
  c.def(
      "redo_history",
      [](EditorBox& self) { return history(edit(self, false, [](Editor& e) { return e.redo_history(); })); },
      "The entries redo would redo, the next one last: [{'label', 'operations'}].");
  c.def(
      "log",
      [](EditorBox& self) { return from_json(edit(self, true, [](Editor& e) { return log_text(e); })); },
      "The operation log as a dict (format dlfl-oplog, docs/oplog.md): every operation applied, undo and "
      "redo included, with the final mesh's hash. dlfl.replay takes it back.");
  c.def(
      "write_log",
      [](EditorBox& self, py::handle path) {
        const std::string p = path_text(path);
        edit(self, true, [&](Editor& e) {
          write_log(e, p);
          return 0;
        });
      },
      "Writes the operation log to a file atomically; `dlfl replay` and dlfl.replay replay it.",
      py::arg("path"));
  c.def_property_readonly(
      "embed_meshes", [](EditorBox& self) { return self.editor.options().embed_meshes; },
      "Whether loaded meshes are kept in the log.");
  c.def_property_readonly(
      "undo_limit", [](EditorBox& self) { return self.editor.options().undo_limit; },
      "The most undo entries kept (0: unlimited).");
  c.def("__repr__", [](EditorBox& self) {
    return edit(self, false, [](Editor& e) {
      return "<dlfl.Editor " + std::to_string(e.log().size()) + " operations logged, " +
             std::to_string(e.undo_history().size()) + " undo entries>";
    });
  });

  m.def(
      "replay",
      [](py::handle log, bool verify) {
        ReplayOptions options;
        options.verify = verify;
        if (py::isinstance<py::dict>(log)) {
          const std::string text = py::module_::import("json").attr("dumps")(log).cast<std::string>();
          py::gil_scoped_release no_gil;
          return std::make_shared<EditorBox>(replay_log(text, "<dict>", options));
        }
        const std::string path = path_text(log);
        py::gil_scoped_release no_gil;
        return std::make_shared<EditorBox>(replay_log_file(path, options));
      },
      "Replays an operation log, a path or a dict as Editor.log() gives it, in a new Editor and returns it. "
      "With verify, the hashes the log carries are checked. Raises LogError (op_index, field) for anything "
      "that cannot be replayed.",
      py::arg("log"), py::arg("verify") = true);
}

}  // namespace dlfl::python
