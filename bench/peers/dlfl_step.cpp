// One step of this library's schemes, timed alone (peer_steps.h).

#include <dlfl/build_mesh.h>
#include <dlfl/schemes/catmull_clark.h>
#include <dlfl/schemes/doo_sabin.h>
#include <dlfl/schemes/honeycomb.h>
#include <dlfl/schemes/loop.h>
#include <dlfl/schemes/sqrt3.h>
#include "peer_steps.h"

namespace dlfl::bench {

namespace {

Mesh step(Scheme scheme, const Mesh& m) {
  switch (scheme) {
    case Scheme::catmull_clark:
      return catmull_clark(m);
    case Scheme::loop:
      return loop(m);
    case Scheme::sqrt3:
      return sqrt3(m);
    case Scheme::doo_sabin:
      return doo_sabin(m);
    case Scheme::honeycomb:
      return honeycomb(m);
  }
  throw InvalidArgument("unknown scheme");
}

}  // namespace

std::optional<StepResult> dlfl_step(Scheme scheme, const PolygonSoup& input) {
  const Mesh mesh = build_mesh(input);
  Mesh result;  // destroyed after the timing, as the other libraries' results are
  const StepCost cost = measure_step([&] { result = step(scheme, mesh); });
  return StepResult{cost, mesh.num_surface_faces(), result.num_surface_faces()};
}

}  // namespace dlfl::bench
