#include <dlfl/schemes/meng_prautzsch_mixed.h>

#include <cctype>

#include <dlfl/analysis/convex_polyhedron.h>
#include <dlfl/errors.h>
#include <dlfl/schemes/detail/corner_origins.h>
#include <dlfl/schemes/detail/meng_prautzsch_common.h>
#include <dlfl/schemes/detail/meng_prautzsch_params.h>
#include <dlfl/schemes/detail/scheme_origins.h>
#include <dlfl/schemes/detail/scheme_table.h>

namespace dlfl {
namespace {

// Recursive descent over the grammar in mhp.h; every failure names its position.
class PatternParser {
 public:
  explicit PatternParser(std::string_view text) : text_(text) {}

  std::string parse() {
    std::string steps = sequence();
    if (pos_ < text_.size()) fail("unmatched ')'");
    return steps;
  }

 private:
  std::string sequence() {
    std::string steps;
    while (pos_ < text_.size() && text_[pos_] != ')') steps += item(steps.size());
    if (steps.empty()) fail("expected H, P or '('");
    return steps;
  }

  // One item with its count; `before` steps precede it in the enclosing sequence (for the length limit).
  std::string item(std::size_t before) {
    std::string unit;
    const char c = text_[pos_];
    if (c == 'H' || c == 'h' || c == 'P' || c == 'p') {
      unit = char(std::toupper(static_cast<unsigned char>(c)));
      ++pos_;
    } else if (c == '(') {
      // Groups nest by recursion: bound the depth so that no pattern can exhaust the stack.
      if (++depth_ > mhp_max_depth) fail("groups nested deeper than " + std::to_string(mhp_max_depth));
      ++pos_;
      unit = sequence();
      --depth_;
      if (pos_ >= text_.size()) fail("expected ')'");
      ++pos_;
    } else {
      fail(std::string("expected H, P or '(', not '") + c + "'");
    }
    std::size_t count = 1;
    if (pos_ < text_.size() && std::isdigit(static_cast<unsigned char>(text_[pos_]))) {
      const std::size_t start = pos_;
      count = 0;
      while (pos_ < text_.size() && std::isdigit(static_cast<unsigned char>(text_[pos_]))) {
        count = count * 10 + std::size_t(text_[pos_++] - '0');
        if (count > mhp_max_steps) too_long();
      }
      if (count == 0) {
        pos_ = start;
        fail("a count must be at least 1");
      }
    }
    if (before + unit.size() * count > mhp_max_steps) too_long();
    std::string steps;
    for (std::size_t i = 0; i < count; ++i) steps += unit;
    return steps;
  }

  [[noreturn]] void too_long() {
    fail("the pattern expands to more than " + std::to_string(mhp_max_steps) + " steps");
  }

  [[noreturn]] void fail(const std::string& what) const {
    const std::string text(text_);
    throw InvalidArgument("mhp: malformed pattern '" + text + "' at character " + std::to_string(pos_ + 1) +
                          " (" + text.substr(0, pos_) + "^" + text.substr(pos_) + "): " + what);
  }

  std::string_view text_;
  std::size_t pos_ = 0;
  std::size_t depth_ = 0;
};

// Reruns `step`, putting "mhp step i (X): " in front of the message of any error, keeping its type.
template <class Step>
Mesh labelled(std::size_t i, char kind, const Step& step) {
  const std::string label = "mhp step " + std::to_string(i) + " (" + kind + "): ";
  try {
    return step();
  } catch (const TopologyError& e) {
    throw TopologyError(label + e.what());
  } catch (const InvalidArgument& e) {
    throw InvalidArgument(label + e.what());
  }
}

}  // namespace

std::string expand_mhp_pattern(std::string_view pattern) { return PatternParser(pattern).parse(); }

void check_mhp_params(const MhpParams& params) {
  expand_mhp_pattern(params.pattern);
  detail::check_mp_params("mhp", params.honeycomb.tau, params.honeycomb.ratio, params.center,
                          params.honeycomb.random);
  detail::check_mp_params("mhp", params.pushing.tau, params.pushing.ratio, params.center,
                          params.pushing.random);
}

Mesh mhp(const Mesh& input, const MhpParams& params, const MhpStepObserver& observer, Origins* origins) {
  check_mhp_params(params);
  const std::string steps = expand_mhp_pattern(params.pattern);
  // Every step multiplies the edges by 4: refuse at once a pattern whose end could not be stored, rather than
  // after minutes of steps.
  double edges = double(input.num_edges());
  for (std::size_t i = 0; i < steps.size(); ++i) edges *= 4.0;
  detail::check_output_size(("mhp pattern '" + params.pattern + "'").c_str(), edges);
  const glm::dvec3 center = params.center.value_or(vertex_centroid(input));
  MpHoneycombParams h = params.honeycomb;
  MpPushingParams p = params.pushing;
  h.center = p.center = center;
  Mesh current;
  // With origins: those of the steps so far, to the input, and of the current mesh's corners (which the next
  // step's origins may name).
  Origins so_far, step;
  std::vector<Origin> corners_so_far, step_corners;
  for (std::size_t i = 0; i < steps.size(); ++i) {
    const char kind = steps[i];
    const Mesh& source = i == 0 ? input : current;  // no copy of the input
    Origins* step_origins = origins ? &step : nullptr;
    std::vector<Origin>* corners = origins && i + 1 < steps.size() ? &step_corners : nullptr;
    if (kind == 'H') {
      h.random.seed = params.honeycomb.random.seed + i;
      current = labelled(i, kind, [&] { return detail::mp_honeycomb(source, h, step_origins, corners); });
    } else {
      p.random.seed = params.pushing.random.seed + i;
      current = labelled(i, kind, [&] { return detail::mp_pushing(source, p, step_origins, corners); });
    }
    if (origins) {
      if (i > 0) {
        detail::compose(step, so_far, corners_so_far);
        if (corners) detail::compose(step_corners, so_far, corners_so_far);
      }
      std::swap(so_far, step);
      std::swap(corners_so_far, step_corners);
    }
    if (observer) observer(i, kind, current);
  }
  if (origins) *origins = std::move(so_far);
  return current;
}

namespace detail {

SchemeSpec mhp_scheme() {
  std::vector<ParamSpec> params = {
      param("pattern", ParamType::text, MhpParams().pattern,
            "the steps in order, H (honeycomb) and P (pushing) with counts and groups: H4P4, (HP)2"),
  };
  for (const std::vector<ParamSpec>& specs :
       {mp_step_param_specs("tau_h", "tau of the H steps (see mp-honeycomb)", "ratio_h",
                            "ratio of the H steps (see mp-honeycomb)"),
        mp_step_param_specs("tau_p", "tau of the P steps (see mp-pushing)", "ratio_p",
                            "ratio of the P steps (see mp-pushing)"),
        mp_shared_param_specs()}) {
    params.insert(params.end(), specs.begin(), specs.end());
  }
  return {"mhp", "Meng-Prautzsch mixed honeycomb pushing: a pattern of H and P steps around one centre",
          std::move(params),
          // The pattern's grammar needs no mesh: a malformed one is refused before any work.
          [](const Params&, Params& resolved) {
            try {
              expand_mhp_pattern(resolved.text("pattern"));
            } catch (const ParameterError&) {
              throw;
            } catch (const InvalidArgument& e) {
              throw ParameterError(e.what(), "pattern");
            }
          },
          [](const Mesh& m, const Params& p, Origins* origins) {
            MhpParams x;
            x.pattern = p.text("pattern");
            x.honeycomb = MpHoneycombParams{mp_step_params_from(p, "tau_h", "ratio_h")};
            x.pushing = MpPushingParams{mp_step_params_from(p, "tau_p", "ratio_p")};
            x.center = mp_center_from(p);
            return mhp(m, x, {}, origins);
          },
          [](const MeshCounts& c, const Params& p) {
            MeshCounts next = c;
            for (char step : expand_mhp_pattern(p.text("pattern")))
              next = step == 'H' ? mp_honeycomb_counts(next) : mp_pushing_counts(next);
            return next;
          }};
}

}  // namespace detail
}  // namespace dlfl
