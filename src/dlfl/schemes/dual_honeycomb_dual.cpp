#include <dlfl/schemes/dual_honeycomb_dual.h>

#include <string>

#include <dlfl/errors.h>
#include <dlfl/schemes/dual.h>

namespace dlfl {

Mesh dual_honeycomb_dual(const Mesh& mesh, const HoneycombParams& p) {
  Mesh d;
  try {
    d = dual(mesh);
  } catch (const TopologyError& e) {
    throw TopologyError(std::string("dual-honeycomb-dual: ") + e.what());
  }
  try {
    check_honeycomb_params(d, p);
  } catch (const InvalidArgument& e) {
    throw InvalidArgument(std::string("dual-honeycomb-dual: ") + e.what() +
                          " (the honeycomb step runs on the dual, whose N-sided faces are the input's N-valent "
                          "vertices)");
  }
  return dual(honeycomb(d, p));
}

}  // namespace dlfl
