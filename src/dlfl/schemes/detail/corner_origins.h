#pragma once
// Internal to the schemes: the steps that composite schemes chain, also reporting where their output corners
// come from (by corner handle). A later step's origins may name corners of this step's output (a honeycomb
// vertex stems from a corner); `compose` (scheme_origins.h) takes those back through this map. Each is the
// public function of the same name with one more output; `corners` may be null.

#include <vector>

#include <dlfl/mesh.h>
#include <dlfl/schemes/boundary_rule.h>
#include <dlfl/schemes/meng_prautzsch_honeycomb.h>
#include <dlfl/schemes/meng_prautzsch_pushing.h>
#include <dlfl/schemes/origins.h>

namespace dlfl::detail {

/// `dual`; the corner for input corner c (at v, in face f) <- c; under the boundary rule every corner of a
/// hole corner's group, in its vertex's face and in the hole face, <- that hole corner.
Mesh dual(const Mesh& mesh, const BoundaryOptions& boundary, Origins* origins, std::vector<Origin>* corners);

/// `mp_honeycomb`; a corner at the f-face vertex of input corner x <- x (in the f-face and in the hexagons);
/// a hexagon's corner at an old vertex <- the input corner that leaves that vertex along the hexagon's edge.
Mesh mp_honeycomb(const Mesh& mesh, const MpHoneycombParams& params, Origins* origins,
                  std::vector<Origin>* corners);

/// `mp_pushing`; the central face's corner on the edge of input corner c <- c, and the three corners of the
/// triangle at c <- c.
Mesh mp_pushing(const Mesh& mesh, const MpPushingParams& params, Origins* origins,
                std::vector<Origin>* corners);

}  // namespace dlfl::detail
