#include <dlfl/operations/make_hole.h>

#include <dlfl/operations/detail/operation_table.h>
#include <dlfl/operations/detail/refusal.h>

namespace dlfl {
namespace {
constexpr const char* op_name = "make_hole";
}  // namespace

void check_make_hole(const Mesh& m, FaceId f) {
  detail::require_live(m, op_name, "face", f);
  if (m.is_hole(f)) detail::refuse(op_name, "face", to_string(f) + " is a hole already");
  if (m.size(f) == 1) {
    detail::refuse(op_name, "face",
                   to_string(f) + " is the face of the point sphere " +
                       to_string(m.vertex(m.first_corner(f))) + ", not a surface face");
  }
}

void make_hole(Transaction& tx, FaceId f) {
  check_make_hole(tx.mesh(), f);
  tx.set_hole(f, true);
}

namespace detail {

std::vector<OperationSpec> make_hole_operation_specs() {
  return {edit_operation(
      "make_hole", "opens the surface at a face: the face becomes a hole face (fill_hole is the inverse)",
      {param("face", ParamType::face, "the surface face to open")}, "V+0, E+0, F+0",
      [](Transaction& tx, const Params& p) {
        make_hole(tx, p.handle<FaceId>("face"));
        return Params{};
      },
      [](const Mesh& m, Params& p) { check_make_hole(m, p.handle<FaceId>("face")); })};
}

}  // namespace detail
}  // namespace dlfl
