#pragma once
// Internal to the schemes: a vertex rule's weight by valence (Loop's beta, sqrt(3)'s a_n), looked up in a
// table for the usual valences rather than computed with a cosine per vertex.

#include <array>
#include <cstdint>

namespace dlfl::detail {

/// `weight(n)` for every valence n: tabulated below 32, computed above.
template <class Weight>
class ValenceWeights {
 public:
  explicit ValenceWeights(Weight weight) : weight_(weight) {
    for (std::uint32_t n = 1; n < table_.size(); ++n) table_[n] = weight_(n);
  }
  double operator()(std::uint32_t n) const { return n < table_.size() ? table_[n] : weight_(n); }

 private:
  Weight weight_;
  std::array<double, 32> table_{};
};

}  // namespace dlfl::detail
