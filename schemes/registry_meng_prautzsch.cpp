// The registry entries of Meng-Prautzsch H, P and MHP.

#include "schemes/registry_entry.h"

namespace dlfl::detail {

std::vector<SchemeEntry> meng_prautzsch_scheme_entries() { return {}; }

}  // namespace dlfl::detail
