// The triangles of the triangle formats: see triangles.h.

#include <dlfl/io/detail/triangles.h>

#include <cmath>
#include <limits>
#include <optional>

#include <dlfl/detail/ear_clipping.h>
#include <dlfl/errors.h>
#include <dlfl/geometry.h>

namespace dlfl::io_detail {
namespace {

bool fits_float(const glm::dvec3& p) {
  constexpr double largest = std::numeric_limits<float>::max();
  return std::abs(p.x) <= largest && std::abs(p.y) <= largest && std::abs(p.z) <= largest;
}

}  // namespace

MeshTriangles mesh_triangles(const Mesh& m, const std::string& file) {
  MeshTriangles t;
  t.first_corner.push_back(0);
  detail::EarClipper clipper;
  for (FaceId f : m.faces()) {
    if (m.is_hole(f) || m.size(f) < 3) continue;
    const auto base = static_cast<std::uint32_t>(t.corners.size());
    const auto face = static_cast<std::uint32_t>(t.faces.size());
    for (CornerId c : m.corners(f)) {
      if (!fits_float(m.position(m.vertex(c)))) {
        throw IoError(
            to_string(m.vertex(c)) + " lies beyond the range of 32-bit floats, which the file stores", file);
      }
      t.corners.push_back(c);
    }
    t.faces.push_back(f);
    t.normals.push_back(face_normal(m, f));
    t.first_corner.push_back(static_cast<std::uint32_t>(t.corners.size()));
    auto triangle = [&](std::uint32_t a, std::uint32_t b, std::uint32_t c) {
      t.triangles.insert(t.triangles.end(), {base + a, base + b, base + c});
      t.triangle_face.push_back(face);
    };
    if (m.size(f) == 3) {
      triangle(0, 1, 2);
      continue;
    }
    clipper.start(m, f);
    while (const std::optional<detail::EarClipper::Ear> ear = clipper.cut()) {
      triangle(ear->before, ear->tip, ear->after);
    }
    // What is left: a triangle, or a remainder no diagonal can cut, fanned from its first node.
    const std::uint32_t a = clipper.rest();
    std::uint32_t b = clipper.next(a);
    for (std::uint32_t k = 2; k < clipper.remaining(); ++k) {
      const std::uint32_t c = clipper.next(b);
      triangle(a, b, c);
      b = c;
    }
  }
  if (t.triangle_face.empty()) throw IoError("no triangles: the mesh has no face to write", file);
  return t;
}

}  // namespace dlfl::io_detail
