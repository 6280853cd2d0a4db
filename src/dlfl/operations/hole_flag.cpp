// make_hole and fill_hole: a face's hole flag set or cleared, each the other's inverse, declared together.

#include <dlfl/operations/fill_hole.h>
#include <dlfl/operations/make_hole.h>

#include <dlfl/operations/detail/operation_table.h>
#include <dlfl/operations/detail/refusal.h>

namespace dlfl {

void check_make_hole(const Mesh& m, FaceId f) {
  detail::require_live(m, "make_hole", "face", f);
  if (m.is_hole(f)) detail::refuse("make_hole", "face", to_string(f) + " is a hole already");
  if (m.size(f) == 1) {
    detail::refuse("make_hole", "face",
                   to_string(f) + " is the face of the point sphere " +
                       to_string(m.vertex(m.first_corner(f))) + ", not a surface face");
  }
}

void make_hole(Transaction& tx, FaceId f) {
  check_make_hole(tx.mesh(), f);
  tx.set_hole(f, true);
}

void check_fill_hole(const Mesh& m, FaceId f) {
  detail::require_live(m, "fill_hole", "face", f);
  if (!m.is_hole(f)) detail::refuse("fill_hole", "face", to_string(f) + " is not a hole");
}

void fill_hole(Transaction& tx, FaceId f) {
  check_fill_hole(tx.mesh(), f);
  tx.set_hole(f, false);
}

namespace detail {
namespace {

// One of the two: `act` sets the flag, `check` refuses what it cannot.
OperationSpec hole_flag_operation(std::string name, std::string doc, std::string face_doc,
                                  void (*act)(Transaction&, FaceId), void (*check)(const Mesh&, FaceId)) {
  return edit_operation(
      std::move(name), std::move(doc), {param("face", ParamType::face, std::move(face_doc))}, "V+0, E+0, F+0",
      [act](Transaction& tx, const Params& p) {
        act(tx, p.handle<FaceId>("face"));
        return Params{};
      },
      [check](const Mesh& m, Params& p) { check(m, p.handle<FaceId>("face")); });
}

}  // namespace

std::vector<OperationSpec> hole_flag_operation_specs() {
  return {
      hole_flag_operation(
          "make_hole", "opens the surface at a face: the face becomes a hole face (fill_hole is the inverse)",
          "the surface face to open", &make_hole, &check_make_hole),
      hole_flag_operation("fill_hole",
                          "closes a hole: the hole face becomes a surface face (the inverse of make_hole)",
                          "the hole face to fill", &fill_hole, &check_fill_hole)};
}

}  // namespace detail
}  // namespace dlfl
