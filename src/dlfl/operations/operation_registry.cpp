#include <algorithm>

#include <dlfl/errors.h>
#include <dlfl/format.h>
#include <dlfl/operations/detail/operation_table.h>
#include <dlfl/operations/operation.h>

namespace dlfl {
namespace {

const std::vector<OperationSpec>& table() {
  static const std::vector<OperationSpec> all = [] {
    std::vector<OperationSpec> ops;
    for (auto declarations : detail::operation_files) {
      for (auto& op : declarations()) ops.push_back(std::move(op));
    }
    std::sort(ops.begin(), ops.end(), [](const auto& a, const auto& b) { return a.name < b.name; });
    return ops;
  }();
  return all;
}

}  // namespace

namespace {
OperationSpec declared(std::string name, OperationSpec::Kind kind, std::string doc,
                       std::vector<ParamSpec> params) {
  OperationSpec op;
  op.name = std::move(name);
  op.kind = kind;
  op.doc = std::move(doc);
  op.params = std::move(params);
  return op;
}
}  // namespace

OperationSpec edit_operation(std::string name, std::string doc, std::vector<ParamSpec> params,
                             std::string counts, EditFunction edit, CheckFunction check) {
  OperationSpec op = declared(std::move(name), OperationSpec::Kind::edit, std::move(doc), std::move(params));
  op.counts = std::move(counts);
  op.edit = std::move(edit);
  op.check = std::move(check);
  return op;
}

OperationSpec counting_operation(std::string name, std::string doc, std::string counts, std::string output,
                                 std::function<std::size_t(Transaction& tx)> run) {
  return edit_operation(std::move(name), std::move(doc), {}, std::move(counts),
                        [output = std::move(output), run = std::move(run)](Transaction& tx, const Params&) {
                          return Params{{output, run(tx)}};
                        });
}

OperationSpec replace_operation(std::string name, std::string doc, std::vector<ParamSpec> params,
                                ReplaceFunction replace, CheckFunction check) {
  OperationSpec op =
      declared(std::move(name), OperationSpec::Kind::replace, std::move(doc), std::move(params));
  op.replace = std::move(replace);
  op.check = std::move(check);
  return op;
}

OperationSpec history_operation(std::string name, std::string doc, std::vector<ParamSpec> params) {
  return declared(std::move(name), OperationSpec::Kind::history, std::move(doc), std::move(params));
}

std::span<const OperationSpec> operations() { return table(); }

std::vector<std::string> operation_names() {
  std::vector<std::string> names;
  for (const auto& op : table()) names.push_back(op.name);
  return names;
}

const OperationSpec& find_operation(std::string_view name) {
  for (const auto& op : table()) {
    if (op.name == name) return op;
  }
  const auto names = operation_names();
  const std::string suggestion = closest_name(name, names);
  throw UnknownNameError(unknown_name_message("operation", name, names, suggestion), suggestion);
}

Params resolve_operation_params(const OperationSpec& op, const Params& given, const Mesh& mesh) {
  Params full = resolve_params(op.name, op.params, given, &mesh);
  if (op.check) op.check(mesh, full);
  return full;
}

Params apply_operation(Mesh& mesh, std::string_view name, const Params& params) {
  const OperationSpec& op = find_operation(name);
  const Params full = resolve_operation_params(op, params, mesh);
  switch (op.kind) {
    case OperationSpec::Kind::edit: {
      Transaction tx(mesh);
      Params outputs = op.edit(tx, full);
      tx.commit();
      return outputs;
    }
    case OperationSpec::Kind::replace:
      mesh = op.replace(mesh, full);
      return {};
    case OperationSpec::Kind::history:
      break;
  }
  throw InvalidArgument(op.name + " acts on an editor's history; apply it through an Editor");
}

}  // namespace dlfl
