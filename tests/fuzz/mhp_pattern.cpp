// MHP patterns (expand_mhp_pattern, dlfl/schemes/meng_prautzsch_mixed.h): a pattern expands to at most
// mhp_max_steps letters H and P, and the expansion is itself a pattern that expands to itself.

#include <dlfl/errors.h>
#include <dlfl/schemes/meng_prautzsch_mixed.h>

#include "fuzz_common.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace dlfl;
  if (size > 1024) return 0;
  std::string steps;
  try {
    steps = expand_mhp_pattern(fuzz::text_of(data, size));
  } catch (const Error&) {
    return 0;
  }
  fuzz::check(!steps.empty() && steps.size() <= mhp_max_steps, "an expansion of a bad length");
  fuzz::check(steps.find_first_not_of("HP") == std::string::npos,
              "an expansion with other letters than H, P");
  try {
    fuzz::check(expand_mhp_pattern(steps) == steps, "an expansion does not expand to itself");
  } catch (const Error& e) {
    fuzz::finding(std::string("an expansion is not a pattern: ") + e.what());
  }
  return 0;
}
