#pragma once
// The declarations of operations and schemes as JSON text: what `dlfl ops --json` and `dlfl schemes --json`
// print and what the Python binding's `dlfl.operations()` and `dlfl.schemes()` return. One home for the
// listing format, read from the registries.

#include <string>
#include <string_view>

#include <dlfl/operations/operation.h>
#include <dlfl/schemes/scheme_registry.h>

namespace dlfl {

/// "edit", "replace" or "history".
const char* to_string(OperationSpec::Kind kind);

/// One operation: {"name", "kind", "doc", "counts", "params": [parameter, ...]}, each parameter {"name",
/// "type", "default", "default_doc" (when set), "range": {"min", "max", "min_open", "max_open"} (absent when
/// unbounded), "keywords", "doc", "optional"}. "default" is typed (0.5, false, 1, "centroid", [x, y, z]) or
/// null when there is none; then "optional" says whether the parameter may be left out (and "default_doc"
/// how the value is chosen) or is required. An infinite end of a range is null and open (JSON has no
/// infinity). `indent` as nlohmann::json::dump takes it (-1: one line).
std::string to_json(const OperationSpec& op, int indent = -1);

/// One scheme: {"name", "doc", "params": [parameter, ...]}.
std::string to_json(const SchemeSpec& scheme, int indent = -1);

/// Every registered operation, as an array of `to_json(op)`, sorted by name.
std::string operations_json(int indent = -1);

/// Every registered scheme, as an array of `to_json(scheme)`, sorted by name.
std::string schemes_json(int indent = -1);

}  // namespace dlfl
