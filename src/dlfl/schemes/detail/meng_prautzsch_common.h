#pragma once
// What the Meng-Prautzsch schemes H and P share: their parameters, the per-element random choices (the paper,
// section 1.2, tried choosing the ratio of every edge and the offset of every face independently), portable
// and reproducible, the checks of their input and parameters, and the layout of their output faces.

#include <cmath>
#include <cstdint>
#include <glm/vec3.hpp>
#include <optional>
#include <random>
#include <string>
#include <vector>

#include <dlfl/analysis/convex_polyhedron.h>
#include <dlfl/errors.h>
#include <dlfl/format.h>
#include <dlfl/mesh.h>

namespace dlfl {

/// Random per-element parameters. When `enabled`, every edge gets its own split fraction and every face (H)
/// or vertex (P) its own tau, each uniform in [epsilon, 1 - epsilon]; `epsilon` is the paper's honeycomb or
/// pushing tolerance, so edge ratios lie in [epsilon : (1 - epsilon), (1 - epsilon) : epsilon]. The same seed
/// gives the same choices on every platform.
struct MpRandomChoice {
  bool enabled = false;
  double epsilon = 0.25;  ///< in (0, 1/2]
  std::uint64_t seed = 1;
};

/// Uniform doubles from std::mt19937_64, whose output sequence the C++ standard fixes. The mapping to
/// [0, 1) is ours (53 high bits times 2^-53) because std::uniform_real_distribution differs between standard
/// libraries.
class MpRandom {
 public:
  explicit MpRandom(std::uint64_t seed) : engine_(seed) {}
  /// Uniform in [lo, hi).
  double uniform(double lo, double hi) {
    const double unit = double(engine_() >> 11) * 0x1.0p-53;
    return lo + (hi - lo) * unit;
  }

 private:
  std::mt19937_64 engine_;
};

/// The parameters of one step of H or P. What tau and ratio mean differs between the two: see
/// MpHoneycombParams and MpPushingParams.
struct MpStepParams {
  /// In (0, 1).
  double tau = 0.5;
  /// Positive and finite; 1 is the symmetric choice.
  double ratio = 1.0;
  /// The centre (the paper's origin), strictly inside; by default the vertex centroid.
  std::optional<glm::dvec3> center;
  /// Random per-element ratios and taus instead of `ratio` and `tau`.
  MpRandomChoice random;
};

namespace detail {

/// Throws InvalidArgument naming `scheme` and the parameter if tau is not in (0, 1), ratio is not positive
/// and finite, the centre is not finite, or epsilon is not in (0, 1/2] (checked whether or not random choices
/// are on, so that a wrong value never passes unnoticed).
inline void check_mp_params(const char* scheme, double tau, double ratio,
                            const std::optional<glm::dvec3>& center, const MpRandomChoice& random) {
  const std::string s(scheme);
  if (!(tau > 0.0 && tau < 1.0)) {
    throw InvalidArgument(s + ": parameter tau must be in (0, 1), not " + format_number(tau));
  }
  if (!(ratio > 0.0 && std::isfinite(ratio))) {
    throw InvalidArgument(s + ": parameter ratio must be positive and finite, not " + format_number(ratio));
  }
  if (center && !(std::isfinite(center->x) && std::isfinite(center->y) && std::isfinite(center->z))) {
    throw InvalidArgument(s + ": parameter center must be finite");
  }
  if (!(random.epsilon > 0.0 && random.epsilon <= 0.5)) {
    throw InvalidArgument(s + ": parameter epsilon must be in (0, 0.5], not " +
                          format_number(random.epsilon));
  }
}

/// Throws InvalidArgument if a step with `edges_out` output edges would have more corners (2 per edge) than
/// 32-bit handles can number, before anything is allocated.
inline void check_output_size(const char* scheme, double edges_out) {
  if (2.0 * edges_out > double(0xFFFFFFFEu)) {
    throw InvalidArgument(std::string(scheme) + ": the result would have " + format_number(edges_out) +
                          " edges, more than 32-bit handles can hold");
  }
}

/// The result of an H or P step must be a strictly convex polyhedron like its input. Legal but extreme
/// parameters (tau near 0 or 1, a ratio of 1e17) can round a new point onto an old one or flatten an edge;
/// then the caller is told which parameters to move away from their bounds, instead of the next step
/// failing on its input. O(size).
inline Mesh require_convex_result(Mesh result, const glm::dvec3& centre, const char* scheme, double tau,
                                  double ratio) {
  if (auto violation = convexity_violation(result, centre)) {
    throw InvalidArgument(std::string(scheme) + ": tau = " + format_number(tau) + " and ratio = " +
                          format_number(ratio) + " give a result that is not strictly convex (" +
                          violation->message + "); move them away from their bounds");
  }
  return result;
}

/// The per-element choices of one H or P step: a split fraction per edge (ratio / (1 + ratio)) and a tau per
/// face (H) or vertex (P), or, with `random` on, all of them drawn uniformly in [epsilon, 1 - epsilon] from
/// the seed, edges first, then the other elements, in handle order.
struct MpChoices {
  std::vector<double> fraction;
  std::vector<double> tau;
};
inline MpChoices mp_choices(std::size_t edges, std::size_t elements, double ratio, double tau,
                            const MpRandomChoice& random) {
  MpChoices c{std::vector<double>(edges, ratio / (1.0 + ratio)), std::vector<double>(elements, tau)};
  if (random.enabled) {
    MpRandom rng(random.seed);
    const double lo = random.epsilon, hi = 1.0 - random.epsilon;
    for (double& s : c.fraction) s = rng.uniform(lo, hi);
    for (double& t : c.tau) t = rng.uniform(lo, hi);
  }
  return c;
}

/// The start of an H or P step (`scheme` names it in messages): the parameters checked (`check_mp_params`),
/// the input read by dense handles, the centre (the given one, or the input's vertex centroid), the input
/// checked to be a closed, strictly convex polyhedron around it (`require_convex_polyhedron`) whose result
/// (4E edges) fits 32-bit handles, and the per-element choices (`mp_choices`), with a tau per face (H) or per
/// vertex (P). Not copied: `mesh()` may be its own compacted copy of the input.
class MpStepInput {
 public:
  MpStepInput(const char* scheme, const Mesh& input, const MpStepParams& params, ElementKind taus_per);
  MpStepInput(const MpStepInput&) = delete;
  MpStepInput& operator=(const MpStepInput&) = delete;

  /// The input, handles 0 .. count-1.
  const Mesh& mesh() const { return *mesh_; }
  const glm::dvec3& center() const { return center_; }
  const MpChoices& choices() const { return choices_; }

 private:
  std::optional<Mesh> storage_;
  const Mesh* mesh_ = nullptr;
  glm::dvec3 center_{0.0};
  MpChoices choices_;
};

/// The face layout of an H or P result on dense `m`: first a copy of every input face (H's f-faces, P's
/// central faces), in face order and corner for corner (`position[c]` is the output corner made from input
/// corner c), then `count` faces of `size` corners each (H: a hexagon per edge, P: a triangle per corner).
struct MpFaceLayout {
  std::vector<std::uint32_t> offsets;
  std::vector<std::uint32_t> position;
};
MpFaceLayout mp_face_layout(const Mesh& m, std::uint32_t count, std::uint32_t size);

}  // namespace detail
}  // namespace dlfl
