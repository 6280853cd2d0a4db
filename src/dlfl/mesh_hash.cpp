#include <dlfl/mesh_hash.h>

#include <bit>
#include <cstdint>
#include <cstdio>

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
  for (FaceId f : m.faces()) {
    d.add(pair(f.index(), m.first_corner(f).index()));
    d.add(pair(m.size(f), m.is_hole(f)));
    if (const auto q = m.face_point(f)) {  // only set points count, so meshes without any hash as before
      d.add(q->x);
      d.add(q->y);
      d.add(q->z);
    }
  }
  for (CornerId c : m.corners()) {
    d.add(pair(c.index(), m.vertex(c).index()));
    d.add(pair(m.face(c).index(), m.edge(c).index()));
    d.add(pair(m.next(c).index(), m.prev(c).index()));
  }
  return d.hex();
}

}  // namespace dlfl
