#pragma once
// One subdivision step in each library, from the same polygon soup: each function builds its library's mesh
// (not timed), times the step alone, and returns the cost and the face counts. A library that lacks the
// scheme returns nothing.

#include <optional>

#include <dlfl/polygon_soup.h>
#include "peer_schemes.h"
#include "step_measure.h"

namespace dlfl::bench {

std::optional<StepResult> dlfl_step(Scheme scheme, const PolygonSoup& input);
std::optional<StepResult> cgal_step(Scheme scheme, const PolygonSoup& input);      // Subdivision_method_3
std::optional<StepResult> openmesh_step(Scheme scheme, const PolygonSoup& input);  // Subdivider::Uniform

}  // namespace dlfl::bench
