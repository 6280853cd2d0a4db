#include <dlfl/mesh_hash.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <optional>
#include <string_view>
#include <variant>

namespace dlfl {
namespace {

// Two independent 64-bit multiply-xorshift lanes over a stream of 64-bit words.
class Digest {
 public:
  void add(std::uint64_t word) {
    a_ = mix(a_ ^ word, 0x9E3779B97F4A7C15ull);
    b_ = mix(b_ + word, 0xC2B2AE3D27D4EB4Full);
  }
  void add(double x) { add(std::bit_cast<std::uint64_t>(x)); }
  std::string hex() const {
    char buf[33];
    std::snprintf(buf, sizeof buf, "%016llx%016llx",
                  static_cast<unsigned long long>(mix(a_, 0xFF51AFD7ED558CCDull)),
                  static_cast<unsigned long long>(mix(b_, 0xC4CEB9FE1A85EC53ull)));
    return buf;
  }

 private:
  static std::uint64_t mix(std::uint64_t x, std::uint64_t k) {
    x *= k;
    x ^= x >> 31;
    x *= 0xBF58476D1CE4E5B9ull;
    x ^= x >> 29;
    return x;
  }
  std::uint64_t a_ = 0x243F6A8885A308D3ull;
  std::uint64_t b_ = 0x13198A2E03707344ull;
};

std::uint64_t pair(std::uint32_t hi, std::uint32_t lo) { return (std::uint64_t(hi) << 32) | lo; }

// The Zhang-Wang control point (dlfl/schemes/zhang_wang_honeycomb.h) was a kernel field before attributes
// existed, hashed inside the face loop; it still is, so that digests recorded back then (operation logs)
// stay valid.
constexpr std::string_view face_point_name = "face_point";

// Any NaN hashes as one: attribute equality makes every NaN equal.
void add_value(Digest& d, double x) { d.add(std::isnan(x) ? std::numeric_limits<double>::quiet_NaN() : x); }
void add_value(Digest& d, const glm::dvec3& p) {
  add_value(d, p.x);
  add_value(d, p.y);
  add_value(d, p.z);
}
void add_value(Digest& d, int x) { d.add(std::uint64_t(std::uint32_t(x))); }
void add_value(Digest& d, bool x) { d.add(std::uint64_t(x)); }

void add_text(Digest& d, std::string_view text) {
  d.add(std::uint64_t(text.size()));
  for (std::size_t i = 0; i < text.size(); i += 8) {
    std::uint64_t word = 0;
    for (std::size_t k = i; k < std::min(text.size(), i + 8); ++k)
      word |= std::uint64_t(static_cast<unsigned char>(text[k])) << (8 * (k - i));
    d.add(word);
  }
}

void add_attribute(Digest& d, const Mesh& m, const AttributeInfo& info) {
  d.add(pair(static_cast<std::uint32_t>(info.kind), static_cast<std::uint32_t>(info.type)));
  add_text(d, info.name);
  std::visit([&](const auto& value) { add_value(d, value); }, info.default_value);
  const auto values = [&]<class H>(H) {
    std::visit(
        [&]<class T>(const T&) {
          const ConstAttribute<H, T> a = m.attribute<H, T>(info.name);
          for (H h : m.elements<H>()) {
            d.add(std::uint64_t(h.index()));
            add_value(d, a[h]);
          }
        },
        info.default_value);
  };
  switch (info.kind) {
    case ElementKind::vertex:
      return values(VertexId());
    case ElementKind::edge:
      return values(EdgeId());
    case ElementKind::face:
      return values(FaceId());
    case ElementKind::corner:
      return values(CornerId());
  }
}

}  // namespace

std::string mesh_hash(const Mesh& m) {
  Digest d;
  d.add(pair(static_cast<std::uint32_t>(m.num_vertices()), static_cast<std::uint32_t>(m.num_edges())));
  d.add(pair(static_cast<std::uint32_t>(m.num_faces()), static_cast<std::uint32_t>(m.num_corners())));
  for (VertexId v : m.vertices()) {
    d.add(pair(v.index(), m.corner(v).index()));
    d.add(m.position(v).x);
    d.add(m.position(v).y);
    d.add(m.position(v).z);
  }
  for (EdgeId e : m.edges()) {
    d.add(pair(e.index(), 0));
    d.add(pair(m.corner(e, 0).index(), m.corner(e, 1).index()));
  }
  const std::vector<AttributeInfo> attributes = m.attributes();
  std::optional<ConstAttribute<FaceId, glm::dvec3>> face_points;
  for (const AttributeInfo& info : attributes) {
    if (info.kind == ElementKind::face && info.name == face_point_name && info.type == AttributeType::point)
      face_points = m.attribute<FaceId, glm::dvec3>(face_point_name);
  }
  for (FaceId f : m.faces()) {
    d.add(pair(f.index(), m.first_corner(f).index()));
    d.add(pair(m.size(f), m.is_hole(f)));
    if (face_points) {  // only set points count, so meshes without any hash as before
      const glm::dvec3& q = (*face_points)[f];
      if (!std::isnan(q.x) && !std::isnan(q.y) && !std::isnan(q.z)) {
        d.add(q.x);
        d.add(q.y);
        d.add(q.z);
      }
    }
  }
  for (CornerId c : m.corners()) {
    d.add(pair(c.index(), m.vertex(c).index()));
    d.add(pair(m.face(c).index(), m.edge(c).index()));
    d.add(pair(m.next(c).index(), m.prev(c).index()));
  }
  for (const AttributeInfo& info : attributes) {
    if (face_points && info.kind == ElementKind::face && info.name == face_point_name) continue;
    add_attribute(d, m, info);
  }
  return d.hex();
}

}  // namespace dlfl
