// The library's exceptions as the Python classes of dlfl/_errors.py, with their fields: the C++ hierarchy
// (dlfl/errors.h, LogError in dlfl/history/oplog.h) mirrored class for class, messages unchanged.

#include <dlfl/build_mesh.h>
#include <dlfl/history/oplog.h>
#include "binding.h"

namespace dlfl::python {
namespace {

py::object text_or_none(const std::string& s) { return s.empty() ? py::none() : py::object(py::str(s)); }

// Raises dlfl.NAME(message, **fields) as the pending Python exception.
void raise(const char* name, const std::exception& e, const py::dict& fields = {}) {
  const py::object type = py::module_::import("dlfl._errors").attr(name);
  const py::object error = type(e.what(), **fields);
  PyErr_SetObject(type.ptr(), error.ptr());
}

py::dict file_fields(const IoError& e) {
  py::dict fields;
  fields["path"] = text_or_none(e.file());
  fields["line"] = e.line() == 0 ? py::none() : py::object(py::int_(e.line()));
  return fields;
}

}  // namespace

void bind_errors(py::module_&) {
  // Most derived first: each C++ class becomes its Python twin.
  py::register_exception_translator([](std::exception_ptr p) {
    try {
      std::rethrow_exception(p);
    } catch (const LogError& e) {
      py::dict fields = file_fields(e);
      fields["op_index"] = e.op() == LogError::npos ? py::none() : py::object(py::int_(e.op()));
      fields["field"] = text_or_none(e.field());
      raise("LogError", e, fields);
    } catch (const IoError& e) {
      raise("IoError", e, file_fields(e));
    } catch (const PolygonError& e) {
      py::dict fields;
      fields["element"] = e.element() == PolygonError::Element::face ? "face" : "vertex";
      fields["index"] = e.index();
      raise("PolygonError", e, fields);
    } catch (const TopologyError& e) {
      raise("TopologyError", e);
    } catch (const ParameterError& e) {
      py::dict fields;
      fields["parameter"] = text_or_none(e.parameter());
      raise("ParameterError", e, fields);
    } catch (const UnknownNameError& e) {
      py::dict fields;
      fields["suggestion"] = text_or_none(e.suggestion());
      raise("UnknownNameError", e, fields);
    } catch (const InvalidArgument& e) {
      raise("InvalidArgument", e);
    } catch (const Error& e) {
      raise("Error", e);
    }
  });
}

}  // namespace dlfl::python
