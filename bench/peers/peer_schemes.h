#pragma once
// The schemes that the peer benchmarks compare, and the input each starts from: a closed torus grid of quads
// (Catmull-Clark, Doo-Sabin, honeycomb) or of triangles (Loop, sqrt3), sized so that one step gives about the
// requested number of faces. Every library gets the same grid.

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

namespace dlfl::bench {

enum class Scheme { catmull_clark, loop, sqrt3, doo_sabin, honeycomb };

inline constexpr Scheme all_schemes[] = {Scheme::catmull_clark, Scheme::loop, Scheme::sqrt3,
                                         Scheme::doo_sabin, Scheme::honeycomb};

inline const char* scheme_name(Scheme s) {
  switch (s) {
    case Scheme::catmull_clark:
      return "catmull-clark";
    case Scheme::loop:
      return "loop";
    case Scheme::sqrt3:
      return "sqrt3";
    case Scheme::doo_sabin:
      return "doo-sabin";
    case Scheme::honeycomb:
      return "honeycomb";
  }
  return "?";
}

inline std::optional<Scheme> parse_scheme(std::string_view name) {
  for (Scheme s : all_schemes) {
    if (name == scheme_name(s)) return s;
  }
  return std::nullopt;
}

/// Whether the scheme's input grid is cut into triangles.
inline bool takes_triangles(Scheme s) { return s == Scheme::loop || s == Scheme::sqrt3; }

/// Faces after one step from an n x n torus grid, in closed form (V = n^2, E = 2 n^2, F = n^2 quads; the
/// triangulated grid has E = 3 n^2, F = 2 n^2): Catmull-Clark 4 F, Doo-Sabin V + E + F, honeycomb F + V,
/// Loop 4 F, sqrt3 3 F.
inline std::size_t output_faces(Scheme s, std::size_t n) {
  const std::size_t n2 = n * n;
  switch (s) {
    case Scheme::catmull_clark:
      return 4 * n2;
    case Scheme::doo_sabin:
      return 4 * n2;
    case Scheme::honeycomb:
      return 2 * n2;
    case Scheme::loop:
      return 8 * n2;
    case Scheme::sqrt3:
      return 6 * n2;
  }
  return 0;
}

/// The grid side n whose one step gives closest to `faces` output faces.
inline std::size_t grid_side(Scheme s, std::size_t faces) {
  const double per_n2 = double(output_faces(s, 1));
  return std::max<std::size_t>(3, std::size_t(std::lround(std::sqrt(double(faces) / per_n2))));
}

}  // namespace dlfl::bench
