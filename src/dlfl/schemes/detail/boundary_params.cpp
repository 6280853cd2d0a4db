#include <dlfl/schemes/detail/boundary_params.h>

#include <dlfl/errors.h>

namespace dlfl {

std::string_view to_string(BoundaryRule rule) { return rule == BoundaryRule::curve ? "curve" : "hole"; }

namespace detail {

std::vector<ParamSpec> boundary_param_specs() {
  return {param("boundary", ParamType::text, "curve",
                "open meshes: curve (the scheme's boundary rule) or hole (as before boundary rules: holes "
                "subdivided like faces, or refused)")
              .one_of({"curve", "hole"})
              .before_version3("hole"),
          param("sharp_corners", ParamType::boolean, true,
                "boundary vertices with exactly two edges stay put (with boundary=curve)")};
}

std::vector<ParamSpec> with_boundary_params(std::vector<ParamSpec> specs) {
  for (ParamSpec& spec : boundary_param_specs()) specs.push_back(std::move(spec));
  return specs;
}

BoundaryOptions boundary_options_from(const Params& resolved) {
  BoundaryOptions options;
  options.rule = resolved.text("boundary") == "hole" ? BoundaryRule::hole : BoundaryRule::curve;
  options.sharp_corners = resolved.boolean("sharp_corners");
  return options;
}

}  // namespace detail
}  // namespace dlfl
