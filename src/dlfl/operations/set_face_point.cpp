// set_face_point: sets or clears the control point of a face (the central control vertex of the Zhang-Wang
// honeycomb scheme, dlfl/schemes/zhang_wang_honeycomb.h), stored in the "face_point" face attribute.

#include <dlfl/operations/detail/operation_table.h>
#include <dlfl/schemes/zhang_wang_honeycomb.h>

namespace dlfl::detail {

std::vector<OperationSpec> face_point_operation_specs() {
  return {edit_operation(
      "set_face_point", "sets or clears a face's control point (the Zhang-Wang central control vertex)",
      {param("face", ParamType::face, "the face"),
       param("position", ParamType::point, "the control point").optional("none: the point is cleared")},
      "V+0, E+0, F+0", [](Transaction& tx, const Params& p) {
        // As set_face_point(Mesh&, ...): the attribute appears with the first point set, and clearing a
        // point of a mesh without any changes nothing.
        const FaceId f = p.handle<FaceId>("face");
        if (p.has("position")) {
          tx.add_attribute(ElementKind::face, face_point_attribute, unset_face_point());
          tx.set_attribute(ElementKind::face, face_point_attribute, f.index(), p.point("position"));
        } else if (tx.mesh().has_face_attribute(face_point_attribute)) {
          tx.set_attribute(ElementKind::face, face_point_attribute, f.index(), unset_face_point());
        }
        return Params{};
      })};
}

}  // namespace dlfl::detail
