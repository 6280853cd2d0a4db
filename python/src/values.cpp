// Conversions between Python objects and the library's values: parameters, arrays, paths, JSON; and the
// editor lock that the Mesh and Editor classes share.

#include <cstring>
#include <limits>
#include <string>

#include "binding.h"

namespace dlfl::python {

EditorLock::EditorLock(EditorBox& box) : box_(box) {
  if (box.mutex.try_lock()) return;
  py::gil_scoped_release no_gil;  // another thread works on this editor: wait for it without the GIL
  box.mutex.lock();
}

std::shared_ptr<const Mesh> MeshRef::snapshot() const {
  if (mesh_) return mesh_;
  return read([](const Mesh& m) { return std::make_shared<const Mesh>(m); });
}

namespace {

py::module_ numpy() { return py::module_::import("numpy"); }

[[noreturn]] void not_a_value(std::string_view context, const std::string& name, py::handle object,
                              const std::string& why) {
  throw ParameterError(
      std::string(context) + ": parameter " + name + " " + why + ", not " + std::string(py::repr(object)),
      name);
}

// A Python integer (or anything with __index__) as 64 bits; nullopt if it does not fit.
std::optional<std::int64_t> index_value(py::handle object) {
  const py::object number = py::reinterpret_steal<py::object>(PyNumber_Index(object.ptr()));
  if (!number) throw py::error_already_set();
  int overflow = 0;
  const long long i = PyLong_AsLongLongAndOverflow(number.ptr(), &overflow);
  if (overflow != 0) return std::nullopt;
  return i;
}

Value array_value(const py::array& a, std::string_view context, const std::string& name, py::handle object,
                  const ParamSpec* spec) {
  const char kind = a.dtype().kind();
  const bool whole = kind == 'i' || kind == 'u' || kind == 'b';
  if (!whole && kind != 'f') not_a_value(context, name, object, "must hold numbers");
  const bool wants_points = spec && (spec->type == ParamType::points || spec->type == ParamType::point);
  if (a.ndim() == 2 && a.shape(1) == 3) {
    const auto p = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(a);
    std::vector<glm::dvec3> points(std::size_t(p.shape(0)));
    if (!points.empty()) std::memcpy(points.data(), p.data(), points.size() * sizeof(glm::dvec3));
    return points;
  }
  if (a.ndim() != 1) not_a_value(context, name, object, "must be a list of values or of points (n, 3)");
  if (wants_points && a.shape(0) == 3) {
    const auto p = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(a);
    const glm::dvec3 point(p.at(0), p.at(1), p.at(2));
    if (spec->type == ParamType::points) return std::vector<glm::dvec3>{point};
    return point;
  }
  if (spec && spec->type == ParamType::points && a.shape(0) == 0) return std::vector<glm::dvec3>{};
  const bool wants_numbers = spec && (spec->type == ParamType::numbers || spec->type == ParamType::number);
  if (whole && !wants_numbers) {
    const auto i = py::array_t<std::int64_t, py::array::c_style | py::array::forcecast>::ensure(a);
    return std::vector<std::int64_t>(i.data(), i.data() + i.shape(0));
  }
  const auto d = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(a);
  if (spec && spec->is_handle() && d.shape(0) == 0) return std::vector<std::int64_t>{};
  return std::vector<double>(d.data(), d.data() + d.shape(0));
}

}  // namespace

std::string path_text(py::handle path) {
  return py::module_::import("os").attr("fsdecode")(path).cast<std::string>();
}

Value to_value(py::handle object, std::string_view context, const std::string& name, const ParamSpec* spec) {
  if (object.is_none()) return {};
  if (py::isinstance<py::array>(object)) {  // before the scalars: an array has __index__ too
    const auto a = py::reinterpret_borrow<py::array>(object);
    if (a.ndim() == 0) return to_value(a.attr("item")(), context, name, spec);
    return array_value(a, context, name, object, spec);
  }
  if (PyBool_Check(object.ptr())) return object.cast<bool>();
  if (PyLong_CheckExact(object.ptr())) {  // the common case first: a handle or a count
    const auto i = index_value(object);
    if (!i) not_a_value(context, name, object, "must fit 64 bits");
    return *i;
  }
  const py::module_ np = numpy();
  if (py::isinstance(object, np.attr("bool_"))) return object.cast<bool>();
  if (PyIndex_Check(object.ptr())) {
    const auto i = index_value(object);
    if (!i) not_a_value(context, name, object, "must fit 64 bits");
    return *i;
  }
  if (PyFloat_Check(object.ptr()) || py::isinstance(object, np.attr("floating"))) {
    return py::cast<double>(object);
  }
  if (py::isinstance<py::str>(object)) return object.cast<std::string>();
  if (py::hasattr(object, "__fspath__")) return path_text(object);  // a pathlib.Path for a file name
  if (py::isinstance<MeshRef>(object)) return object.cast<const MeshRef&>().snapshot();
  if (py::isinstance<py::dict>(object)) {
    Params nested;
    for (auto [key, value] : object.cast<py::dict>()) {
      const std::string k = py::str(key);
      nested[k] = to_value(value, context, name + "." + k, nullptr);
    }
    return nested;
  }
  py::object converted;  // a sequence, as NumPy reads it
  try {
    converted = np.attr("asarray")(object);
  } catch (const py::error_already_set&) {
    not_a_value(context, name, object, "is no kind of value");
  }
  const auto a = py::reinterpret_borrow<py::array>(converted);
  if (a.ndim() == 0) return to_value(a.attr("item")(), context, name, spec);
  return array_value(a, context, name, object, spec);
}

Params to_params(std::string_view context, std::span<const ParamSpec> specs, const py::args& args,
                 const py::kwargs& kwargs) {
  if (args.size() > specs.size()) {
    std::string names;
    for (const ParamSpec& s : specs) names += (names.empty() ? "" : ", ") + s.name;
    throw ParameterError(std::string(context) + ": " + std::to_string(args.size()) +
                             " positional arguments for " + std::to_string(specs.size()) + " parameters (" +
                             names + ")",
                         "");
  }
  Params params;
  for (std::size_t i = 0; i < args.size(); ++i) {
    params[specs[i].name] = to_value(args[i], context, specs[i].name, &specs[i]);
  }
  const auto declared = [&](const std::string& name) -> const ParamSpec* {
    for (const ParamSpec& s : specs) {
      if (s.name == name) return &s;
    }
    return nullptr;
  };
  for (auto [key, value] : kwargs) {
    std::string name = py::str(key);
    // A parameter named like a Python keyword ("lambda") is given with a trailing underscore ("lambda_").
    if (!declared(name) && name.size() > 1 && name.back() == '_' &&
        declared(name.substr(0, name.size() - 1))) {
      name.pop_back();
    }
    if (params.has(name)) {
      throw ParameterError(std::string(context) + ": parameter " + name + " given twice", name);
    }
    params[name] = to_value(value, context, name, declared(name));
  }
  return params;
}

py::object to_python(const Value& v) {
  using K = Value::Kind;
  const auto point = [](const glm::dvec3& p) { return py::make_tuple(p.x, p.y, p.z); };
  switch (v.kind()) {
    case K::empty:
      return py::none();
    case K::boolean:
      return py::bool_(v.as_bool());
    case K::integer:
      return py::int_(v.as_integer());
    case K::number:
      return py::float_(v.as_number());
    case K::text:
      return py::str(v.as_text());
    case K::point:
      return point(v.as_point());
    case K::integers: {
      py::list out;
      for (auto i : v.as_integers()) out.append(i);
      return out;
    }
    case K::numbers: {
      py::list out;
      for (double d : v.as_numbers()) out.append(d);
      return out;
    }
    case K::points: {
      py::list out;
      for (const auto& p : v.as_points()) out.append(point(p));
      return out;
    }
    case K::mesh:
      return py::cast(MeshRef(v.mesh_pointer()));
    case K::params:
      return to_python(v.as_params());
  }
  return py::none();
}

py::dict to_python(const Params& params) {
  py::dict out;
  for (const auto& [name, value] : params) out[py::str(name)] = to_python(value);
  return out;
}

py::object from_json(const std::string& text) { return py::module_::import("json").attr("loads")(text); }

namespace {

// `object` as a C-contiguous int64 array; InvalidArgument if it does not hold integers.
py::array_t<std::int64_t> integer_array(py::handle object, const char* what, const char* part) {
  const py::array a = numpy().attr("asarray")(object);
  const char kind = a.dtype().kind();
  if (a.size() > 0 && kind != 'i' && kind != 'u') {
    throw InvalidArgument(std::string(what) + ": " + part + " must be integers, not " +
                          std::string(py::str(a.dtype())));
  }
  return py::array_t<std::int64_t, py::array::c_style | py::array::forcecast>::ensure(a);
}

constexpr std::int64_t max_index = std::int64_t(std::numeric_limits<std::uint32_t>::max()) - 1;

}  // namespace

void read_indexed_lists(IndexedLists& out, py::handle positions, py::handle lists, const char* what,
                        void (*bad_index)(std::size_t list, const std::string& message)) {
  {
    const auto p = py::array_t<double, py::array::c_style | py::array::forcecast>::ensure(positions);
    if (!p) throw InvalidArgument(std::string(what) + ": positions must be numbers, an (n, 3) array");
    if (!(p.ndim() == 2 && p.shape(1) == 3) && p.size() != 0) {
      throw InvalidArgument(std::string(what) + ": positions must be an (n, 3) array");
    }
    out.positions.resize(p.size() / 3);
    if (p.size() != 0) std::memcpy(out.positions.data(), p.data(), sizeof(double) * std::size_t(p.size()));
  }
  const auto check = [&](std::size_t list, std::int64_t i) {
    if (i < 0 || i > max_index) {
      bad_index(list, "index " + std::to_string(i) + " is " + (i < 0 ? "negative" : "too large for 32 bits"));
    }
    return std::uint32_t(i);
  };
  out.offsets.assign(1, 0);
  out.indices.clear();
  if (py::isinstance<py::tuple>(lists) && py::len(lists) == 2) {  // (offsets, indices)
    const auto offsets = integer_array(lists[py::int_(0)], what, "offsets");
    const auto indices = integer_array(lists[py::int_(1)], what, "indices");
    const auto n = std::size_t(offsets.size()), m = std::size_t(indices.size());
    const std::int64_t* o = offsets.data();
    const std::int64_t* x = indices.data();
    if (offsets.ndim() != 1 || indices.ndim() != 1 || n == 0 || o[0] != 0 || o[n - 1] != std::int64_t(m) ||
        m > std::size_t(max_index)) {
      throw InvalidArgument(
          std::string(what) +
          ": (offsets, indices) needs offsets from 0 to len(indices), both one-dimensional");
    }
    out.offsets.resize(n);
    for (std::size_t k = 0; k < n; ++k) {
      if (k > 0 && o[k] < o[k - 1]) {
        throw InvalidArgument(std::string(what) + ": offsets decrease at list " + std::to_string(k - 1));
      }
      out.offsets[k] = std::uint32_t(o[k]);
    }
    out.indices.resize(m);
    for (std::size_t list = 0; list + 1 < n; ++list) {
      for (std::uint32_t k = out.offsets[list]; k < out.offsets[list + 1]; ++k)
        out.indices[k] = check(list, x[k]);
    }
    return;
  }
  if (py::isinstance<py::array>(lists) && py::array(py::reinterpret_borrow<py::array>(lists)).ndim() == 2) {
    const auto a = integer_array(lists, what, "lists");  // (m, k): m lists of k indices
    const auto m = std::size_t(a.shape(0)), k = std::size_t(a.shape(1));
    if (m * k > std::size_t(max_index)) throw InvalidArgument(std::string(what) + ": too many indices");
    out.indices.resize(m * k);
    out.offsets.resize(m + 1);
    const std::int64_t* data = a.data();
    for (std::size_t f = 0; f < m; ++f) {
      out.offsets[f + 1] = std::uint32_t((f + 1) * k);
      for (std::size_t j = 0; j < k; ++j) out.indices[f * k + j] = check(f, data[f * k + j]);
    }
    return;
  }
  if (!PySequence_Check(lists.ptr()) || py::isinstance<py::str>(lists)) {
    throw InvalidArgument(std::string(what) +
                          ": lists must be a sequence of index lists, an (m, k) array or (offsets, indices)");
  }
  const auto sequence = py::reinterpret_borrow<py::sequence>(lists);
  out.offsets.reserve(sequence.size() + 1);
  for (std::size_t f = 0; f < sequence.size(); ++f) {
    const py::object list = sequence[f];
    if (!PySequence_Check(list.ptr()) || py::isinstance<py::str>(list)) {
      throw InvalidArgument(std::string(what) + ": list " + std::to_string(f) +
                            " is not a sequence of indices");
    }
    for (py::handle item : py::reinterpret_borrow<py::sequence>(list)) {
      if (!PyIndex_Check(item.ptr()) || PyBool_Check(item.ptr())) {
        throw InvalidArgument(std::string(what) + ": list " + std::to_string(f) + " holds " +
                              std::string(py::repr(item)) + ", not an integer index");
      }
      out.indices.push_back(check(f, index_value(item).value_or(std::numeric_limits<std::int64_t>::max())));
    }
    if (out.indices.size() > std::size_t(max_index)) {
      throw InvalidArgument(std::string(what) + ": too many indices");
    }
    out.offsets.push_back(std::uint32_t(out.indices.size()));
  }
}

namespace {
template <class T>
py::array read_only_view(const T* data, std::vector<py::ssize_t> shape, std::vector<py::ssize_t> strides,
                         py::handle owner) {
  py::array view(py::dtype::of<T>(), std::move(shape), std::move(strides), data, owner);
  // Read-only: the storage belongs to a mesh or complex that nothing changes.
  py::detail::array_proxy(view.ptr())->flags &= ~py::detail::npy_api::NPY_ARRAY_WRITEABLE_;
  return view;
}

// An array over the vector's storage, kept alive by a capsule that owns the vector.
template <class T>
py::array owning(std::vector<T> values, std::vector<py::ssize_t> shape, std::vector<py::ssize_t> strides,
                 const py::dtype& dtype) {
  if (values.empty()) return py::array(dtype, std::move(shape), std::move(strides));
  auto* keep = new std::vector<T>(std::move(values));
  const py::capsule owner(keep, [](void* p) { delete static_cast<std::vector<T>*>(p); });
  return py::array(dtype, std::move(shape), std::move(strides), keep->data(), owner);
}

}  // namespace

py::array owned_array(std::vector<std::uint32_t> values) {
  const auto n = py::ssize_t(values.size());
  return owning(std::move(values), {n}, {py::ssize_t(sizeof(std::uint32_t))}, py::dtype::of<std::uint32_t>());
}

py::array owned_points(std::vector<glm::dvec3> points) {
  const auto n = py::ssize_t(points.size());
  return owning(std::move(points), {n, 3}, {py::ssize_t(sizeof(glm::dvec3)), py::ssize_t(sizeof(double))},
                py::dtype::of<double>());
}

py::array point_view(const glm::dvec3* points, std::size_t n, py::handle owner) {
  static_assert(sizeof(glm::dvec3) == 3 * sizeof(double), "glm::dvec3 is three packed doubles");
  return read_only_view(reinterpret_cast<const double*>(points), {py::ssize_t(n), 3},
                        {py::ssize_t(sizeof(glm::dvec3)), py::ssize_t(sizeof(double))}, owner);
}

py::array index_view(const std::uint32_t* values, std::size_t n, py::handle owner) {
  return read_only_view(values, {py::ssize_t(n)}, {py::ssize_t(sizeof(std::uint32_t))}, owner);
}

}  // namespace dlfl::python
