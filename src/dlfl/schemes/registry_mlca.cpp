// The registry entries of MLCA on polygon meshes.

#include <dlfl/schemes/mlca_polygons.h>
#include <dlfl/schemes/detail/registry_entry.h>

namespace dlfl::detail {

std::vector<SchemeEntry> mlca_scheme_entries() {
  return {{"mlca",
           {},
           [](SchemeParams p) { return p; },
           [](const Mesh& m, const SchemeParams&) { return mlca(m); }}};
}

}  // namespace dlfl::detail
