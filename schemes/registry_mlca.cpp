// The registry entries of MLCA on polygon meshes.

#include "schemes/registry_entry.h"

namespace dlfl::detail {

std::vector<SchemeEntry> mlca_scheme_entries() { return {}; }

}  // namespace dlfl::detail
