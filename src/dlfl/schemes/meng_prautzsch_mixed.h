#pragma once
// Mixed honeycomb pushing refinement (MHP) of Meng and Prautzsch (section 5): a pattern of honeycomb (H) and
// corner pushing (P) steps, e.g. H4P4 or (HP)4. See docs/meng_prautzsch.md for the pattern grammar.

#include <cstddef>
#include <functional>
#include <glm/vec3.hpp>
#include <optional>
#include <string>
#include <string_view>

#include <dlfl/mesh.h>
#include <dlfl/schemes/meng_prautzsch_honeycomb.h>
#include <dlfl/schemes/meng_prautzsch_pushing.h>
#include <dlfl/schemes/origins.h>

namespace dlfl {

/// The most steps a pattern may expand to (each step multiplies the number of edges by 4).
inline constexpr std::size_t mhp_max_steps = 64;
/// The deepest nesting of groups a pattern may have.
inline constexpr std::size_t mhp_max_depth = 16;

/// Expands a pattern into its steps, one letter each: "H4P4" -> "HHHHPPPP", "(HP)2" -> "HPHP".
///
/// Grammar: pattern = item {item}; item = ("H" | "P" | "(" pattern ")") [count]; count = decimal digits with
/// a value of at least 1. Letters may be lower case; no spaces. Throws InvalidArgument for a malformed
/// pattern, naming the character position (1-based) where parsing fails and showing the pattern cut there,
/// for a pattern longer than `mhp_max_steps` steps, or for groups nested deeper than `mhp_max_depth`.
std::string expand_mhp_pattern(std::string_view pattern);

struct MhpParams {
  std::string pattern = "HP";
  /// Parameters of the H steps. Their `center` is replaced by the MHP centre.
  MpHoneycombParams honeycomb;
  /// Parameters of the P steps. Their `center` is replaced by the MHP centre.
  MpPushingParams pushing;
  /// The centre of every step (the paper's origin stays put); by default the vertex centroid of the input.
  std::optional<glm::dvec3> center;
};

/// Throws InvalidArgument, naming mhp, for a malformed pattern or a bad H or P parameter.
void check_mhp_params(const MhpParams& params);

/// Called after each step with its index (0-based), its letter ('H' or 'P') and its result.
using MhpStepObserver = std::function<void(std::size_t step, char kind, const Mesh& result)>;

/// Applies the steps of the pattern in order, each to the result of the one before, all around one centre.
/// When random choices are enabled, step i uses the seed of its H or P parameters plus i, so that repeated
/// steps draw afresh. The result of the last step is returned, with the handle order of that step's scheme.
/// Errors are those of `mp_honeycomb` and `mp_pushing`, prefixed with the step ("mhp step 3 (P): ..."). A
/// pattern whose last step would not fit 32-bit handles (the edges grow 4-fold per step) is refused before
/// the first step.
///
/// Origins (filled when `origins` is given; handles of `mesh` itself): those of the steps (see `mp_honeycomb`
/// and `mp_pushing`) taken back through every step to the input; an intermediate corner stems from what the
/// step's corners do (an H corner at an f-face vertex of corner x <- x, at an old vertex <- the side corner
/// of its edge leaving it; a P corner <- the corner of its central face side or triangle). So an element
/// stems from an input vertex only if it is that vertex's image, and an f-face or central face made, step by
/// step, from an input face stays parallel to it. Costs nothing when not asked for.
Mesh mhp(const Mesh& mesh, const MhpParams& params = {}, const MhpStepObserver& observer = {},
         Origins* origins = nullptr);

}  // namespace dlfl
