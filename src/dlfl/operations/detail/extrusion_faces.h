#pragma once
// Internal to the extrusions (extrude_face, inset_face): which faces an operation acts on. The registered
// operations take `face` (one) or `faces` (a list), both declared optional, exactly one given; the library
// functions refuse faces they cannot act on, naming the parameter that gave them.

#include <span>
#include <string>
#include <string_view>
#include <vector>

#include <dlfl/mesh.h>
#include <dlfl/operations/detail/refusal.h>
#include <dlfl/operations/operation.h>
#include <dlfl/operations/transaction.h>
#include <dlfl/parameters.h>

namespace dlfl::detail {

/// The two declarations: `face` and `faces`, both optional.
ParamSpec face_param(std::string doc);
ParamSpec faces_param(std::string doc);

/// The faces given, and the name of the parameter that gave them.
struct FaceSelection {
  std::vector<FaceId> faces;
  std::string parameter;
};

/// The faces of `params`: exactly one of `face` and `faces` must be there. Throws ParameterError naming
/// "face" otherwise ("OP: give exactly one of parameters face and faces").
FaceSelection selected_faces(std::string_view op, const Params& params);

/// Refuses, with a ParameterError naming `parameter`: an empty list, a face listed twice, a removed face, a
/// hole face, a point sphere's face. O(k log k) for k faces.
void check_surface_faces(std::string_view op, const Mesh& mesh, std::span<const FaceId> faces,
                         std::string_view parameter);

/// Puts what an operation made under `many` in `out`, and its first element under `one` as well when the
/// operation was given one element (`one_given`). Nothing when `made` is empty.
template <class H>
void put_made(Params& out, const char* many, const char* one, const std::vector<H>& made, bool one_given) {
  if (made.empty()) return;
  out[many] = made;
  if (one_given) out[one] = made.front();
}

/// The declaration of an edit operation on `face` or `faces` (exactly one given; documented by `face_doc`
/// and `faces_doc`, declared before `params`). `act(tx, selection, params)` changes the mesh and returns the
/// outputs; `check(mesh, selection, params)` makes every refusal before anything changes.
template <class Act, class Check>
OperationSpec face_operation(std::string_view op, std::string doc, std::string face_doc,
                             std::string faces_doc, std::vector<ParamSpec> params, std::string counts,
                             Act act, Check check) {
  params.insert(params.begin(), {face_param(std::move(face_doc)), faces_param(std::move(faces_doc))});
  return edit_operation(
      std::string(op), std::move(doc), std::move(params), std::move(counts),
      [op, act](Transaction& tx, const Params& p) { return act(tx, selected_faces(op, p), p); },
      [op, check](const Mesh& mesh, Params& p) { check(mesh, selected_faces(op, p), p); });
}

/// Builds each plan in turn, `build(tx, plan)`, and returns the results in the plans' order. The extrusions
/// plan every face before the first change: each face's build touches only its own face and new elements,
/// so every plan made beforehand still holds when its turn comes.
template <class Plan, class Build>
auto build_each(Transaction& tx, const std::vector<Plan>& plans, Build build) {
  std::vector<decltype(build(tx, plans.front()))> results;
  results.reserve(plans.size());
  for (const Plan& plan : plans) results.push_back(build(tx, plan));
  return results;
}

}  // namespace dlfl::detail
