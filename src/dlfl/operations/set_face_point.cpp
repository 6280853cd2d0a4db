// set_face_point: sets or clears the control point of a face (the central control vertex of the Zhang-Wang
// honeycomb scheme, dlfl/schemes/zhang_wang_honeycomb.h).

#include <cmath>

#include <dlfl/operations/detail/operation_table.h>

namespace dlfl::detail {

std::vector<OperationSpec> face_point_operation_specs() {
  return {edit_operation(
      "set_face_point", "sets or clears a face's control point (the Zhang-Wang central control vertex)",
      {param("face", ParamType::face, "the face"),
       param("position", ParamType::point, "the control point").optional("none: the point is cleared")},
      "V+0, E+0, F+0", [](Transaction& tx, const Params& p) {
        Step s{Step::Kind::set_face_point};
        s.face = p.handle<FaceId>("face");
        s.position = p.has("position") ? p.point("position") : glm::dvec3(std::nan(""), 0.0, 0.0);
        tx.apply(s);
        return Params{};
      })};
}

}  // namespace dlfl::detail
