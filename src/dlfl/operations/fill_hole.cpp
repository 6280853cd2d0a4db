#include <dlfl/operations/fill_hole.h>

#include <dlfl/operations/detail/operation_table.h>
#include <dlfl/operations/detail/refusal.h>

namespace dlfl {
namespace {
constexpr const char* op_name = "fill_hole";
}  // namespace

void check_fill_hole(const Mesh& m, FaceId f) {
  detail::require_live(m, op_name, "face", f);
  if (!m.is_hole(f)) detail::refuse(op_name, "face", to_string(f) + " is not a hole");
}

void fill_hole(Transaction& tx, FaceId f) {
  check_fill_hole(tx.mesh(), f);
  tx.set_hole(f, false);
}

namespace detail {

std::vector<OperationSpec> fill_hole_operation_specs() {
  return {edit_operation(
      "fill_hole", "closes a hole: the hole face becomes a surface face (the inverse of make_hole)",
      {param("face", ParamType::face, "the hole face to fill")}, "V+0, E+0, F+0",
      [](Transaction& tx, const Params& p) {
        fill_hole(tx, p.handle<FaceId>("face"));
        return Params{};
      },
      [](const Mesh& m, Params& p) { check_fill_hole(m, p.handle<FaceId>("face")); })};
}

}  // namespace detail
}  // namespace dlfl
