#pragma once
// The pieces that the binding's files share (the extension module dlfl._dlfl, docs/python.md): how a Python
// Mesh refers to its mesh, the lock of a Python Editor, handles checked before use, and the conversions
// between Python objects and the library's parameter values. Each .cpp binds one concept; module.cpp calls
// them in order.

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <cstdint>
#include <memory>
#include <mutex>
#include <optional>
#include <span>
#include <string_view>
#include <vector>

#include <dlfl/cells/cell_complex.h>
#include <dlfl/errors.h>
#include <dlfl/history/editor.h>
#include <dlfl/indexed_lists.h>
#include <dlfl/parameters.h>

namespace dlfl::python {

namespace py = pybind11;

/// A dlfl.Editor: the editor and the mutex that lets several Python threads share it. Operations that
/// release the GIL (schemes, files) keep the editor locked meanwhile, so another thread can neither change
/// its mesh nor read it half-changed.
struct EditorBox {
  explicit EditorBox(Editor::Options options) : editor(options) {}
  explicit EditorBox(Editor replayed) : editor(std::move(replayed)) {}
  Editor editor;
  std::mutex mutex;
};

/// Holds an editor's mutex; made and destroyed with the GIL held. It never waits for the mutex while
/// holding the GIL (it releases the GIL first), and a thread that holds a mutex without the GIL waits for
/// nothing else, so two threads never wait for each other. Never hold two at once.
class EditorLock {
 public:
  explicit EditorLock(EditorBox& box);
  ~EditorLock() { box_.mutex.unlock(); }
  EditorLock(const EditorLock&) = delete;
  EditorLock& operator=(const EditorLock&) = delete;

 private:
  EditorBox& box_;
};

/// What a dlfl.Mesh holds: a mesh of its own, which nothing changes once it is made (so NumPy arrays may
/// view its storage), or the current mesh of an editor, which follows the editor's operations ("live").
class MeshRef {
 public:
  explicit MeshRef(std::shared_ptr<const Mesh> mesh) : mesh_(std::move(mesh)) {}
  explicit MeshRef(Mesh mesh) : mesh_(std::make_shared<const Mesh>(std::move(mesh))) {}
  /// The live current mesh of an editor.
  explicit MeshRef(std::shared_ptr<EditorBox> editor) : editor_(std::move(editor)) {}

  bool live() const { return editor_ != nullptr; }
  /// The mesh, for a mesh of its own (null for a live one): what NumPy views keep alive.
  const std::shared_ptr<const Mesh>& owned() const { return mesh_; }

  /// f(mesh), under the editor's lock when live. The GIL stays held.
  template <class F>
  auto read(F&& f) const {
    if (!editor_) return f(*mesh_);
    EditorLock lock(*editor_);
    return f(editor_->editor.mesh());
  }
  /// f(mesh) with the GIL released, for long work (schemes, files); f must not touch Python objects.
  template <class F>
  auto read_without_gil(F&& f) const {
    std::optional<EditorLock> lock;
    if (editor_) lock.emplace(*editor_);
    const Mesh& mesh = editor_ ? editor_->editor.mesh() : *mesh_;
    py::gil_scoped_release no_gil;
    return f(mesh);
  }
  /// The mesh to keep: this one, shared; a live one is copied as it is now.
  std::shared_ptr<const Mesh> snapshot() const;

 private:
  std::shared_ptr<const Mesh> mesh_;
  std::shared_ptr<EditorBox> editor_;
};

/// What a dlfl.CellComplex holds: a complex that nothing changes once it is made.
struct ComplexRef {
  std::shared_ptr<const CellComplex> complex;
};

/// A Python int (or NumPy integer) as a handle of kind H alive in `mesh`; InvalidArgument naming `what`
/// otherwise ("next: c12 is not a live corner").
template <class H>
H live_handle(const Mesh& mesh, std::int64_t index, const char* what) {
  if (index < 0 || index >= std::int64_t(H::invalid_index) || !mesh.is_alive(H(std::uint32_t(index)))) {
    throw InvalidArgument(std::string(what) + ": " + std::to_string(index) + " is not a live " +
                          to_string(element_kind_v<H>) + " of this mesh");
  }
  return H(std::uint32_t(index));
}

/// A handle as Python sees it: its index, or None for the invalid handle.
template <class H>
std::optional<std::uint32_t> handle_or_none(H h) {
  return h.valid() ? std::optional<std::uint32_t>(h.index()) : std::nullopt;
}

/// Fills positions, offsets and indices from Python: positions an (n, 3) array (or anything NumPy reads as
/// one), lists a sequence of index sequences, an (m, k) integer array, or a tuple (offsets, indices).
/// `what` names the caller in messages. Throws InvalidArgument, or `bad_index(list, message)` for an index
/// that is negative or does not fit 32 bits.
void read_indexed_lists(IndexedLists& out, py::handle positions, py::handle lists, const char* what,
                        void (*bad_index)(std::size_t list, const std::string& message));

/// Read-only NumPy views, (n, 3) float64 of `n` points and uint32 of `n` values, that keep `owner` alive.
py::array point_view(const glm::dvec3* points, std::size_t n, py::handle owner);
py::array index_view(const std::uint32_t* values, std::size_t n, py::handle owner);
/// NumPy arrays that take over `values` (no copy), writeable: uint32, and (n, 3) float64.
py::array owned_array(std::vector<std::uint32_t> values);
py::array owned_points(std::vector<glm::dvec3> points);

/// A Python value as a parameter value. `spec`, when known, settles what a list means (handles, numbers,
/// points); None is "not given". Throws ParameterError naming `context` and `name` for an object that is no
/// kind of value; conversions and ranges are left to `resolve_params`, whose messages name the parameter.
Value to_value(py::handle object, std::string_view context, const std::string& name, const ParamSpec* spec);

/// Positional then keyword arguments as the parameters of an operation or scheme declared by `specs`:
/// positional ones in declaration order. Throws ParameterError for more positional arguments than declared
/// parameters, or a parameter given twice.
Params to_params(std::string_view context, std::span<const ParamSpec> specs, const py::args& args,
                 const py::kwargs& kwargs);

/// A parameter value as Python: bool, int, float, str, (x, y, z), lists, a Mesh, a dict.
py::object to_python(const Value& value);
/// Parameters as a dict by name.
py::dict to_python(const Params& params);

/// JSON text as Python objects (json.loads), for what the library gives as JSON.
py::object from_json(const std::string& text);

/// A path argument (str or os.PathLike) as text.
std::string path_text(py::handle path);

// The parts of the module, in the order module.cpp adds them:
/// the translation of the library's exceptions into dlfl.Error and its subclasses (errors.cpp);
void bind_errors(py::module_& m);
/// dlfl.Mesh, validate and info (mesh.cpp);
void bind_mesh(py::module_& m);
/// the mesh and cell complex files, and dlfl.CellComplex (io.cpp);
void bind_io(py::module_& m);
/// subdivide, schemes, operations and mlca_subdivide (schemes.cpp);
void bind_schemes(py::module_& m);
/// dlfl.Editor and replay (editor.cpp);
void bind_editor(py::module_& m);
/// render, pictures of meshes and cell complexes (render.cpp).
void bind_render(py::module_& m);

/// The parameters of the registered operation "subdivide" for `iterations` steps of `scheme` with the
/// scheme's parameters given as keywords (converted by the scheme's declarations): what dlfl.subdivide and
/// Editor.subdivide both run.
Params subdivide_params(const std::string& scheme, std::int64_t iterations, const py::kwargs& params);

}  // namespace dlfl::python
