// Binary PLY in the common layouts (x y z only; faces of the index list only), which the reader takes in
// whole blocks: the same polygons as element by element, and errors that still name the element.

#include <doctest/doctest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <optional>
#include <string>
#include <type_traits>
#include <vector>

#include <dlfl/errors.h>
#include <dlfl/io/detail/text_io.h>
#include "little_endian_bytes.h"

using namespace dlfl;

namespace {

// Little-endian bytes, independent of the host's byte order.
template <class T>
void put(std::string& data, T value) {
  put_little_endian(data, value);
}

// A strip of `n` quads over 2n + 2 vertices, vertex i at (i, i / 2, -i / 3) (the /3 not exact in binary).
// Coordinates of type Real, list counts of type Count, indices of type Index. `index` replaces index j of
// face f when f == bad_face (and a face of size `size`, with indices 0, 1, ..., is written there instead when
// `size` is set); `coordinate` replaces the y of vertex bad_vertex.
struct Strip {
  std::size_t n = 100;
  std::size_t bad_face = std::size_t(-1);
  std::int64_t index = 0;
  std::optional<std::uint32_t> size;
  std::size_t bad_vertex = std::size_t(-1);
  double coordinate = 0;
};
Strip bad_index(std::size_t face, std::int64_t index) {
  Strip s;
  s.bad_face = face;
  s.index = index;
  return s;
}
Strip short_face(std::size_t face, std::uint32_t size) {
  Strip s;
  s.bad_face = face;
  s.size = size;
  return s;
}
Strip bad_coordinate(std::size_t vertex, double value) {
  Strip s;
  s.bad_vertex = vertex;
  s.coordinate = value;
  return s;
}
double x_of(std::size_t i) { return double(i); }
double y_of(std::size_t i) { return double(i) / 2; }
double z_of(std::size_t i) { return -double(i) / 3; }
std::vector<std::uint32_t> quad(std::size_t f) {
  const auto a = std::uint32_t(2 * f);
  return {a, a + 2, a + 3, a + 1};
}

template <class Real, class Count, class Index>
std::string strip_ply(const Strip& s) {
  const std::size_t nv = 2 * s.n + 2;
  auto type = [](auto t) -> std::string {
    using T = decltype(t);
    if constexpr (std::is_same_v<T, float>) return "float";
    if constexpr (std::is_same_v<T, double>) return "double";
    if constexpr (std::is_same_v<T, std::uint8_t>) return "uchar";
    if constexpr (std::is_same_v<T, std::uint32_t>) return "uint";
    return "int";
  };
  std::string data = "ply\nformat binary_little_endian 1.0\nelement vertex " + std::to_string(nv) +
                     "\nproperty " + type(Real{}) + " x\nproperty " + type(Real{}) + " y\nproperty " +
                     type(Real{}) + " z\nelement face " + std::to_string(s.n) + "\nproperty list " +
                     type(Count{}) + " " + type(Index{}) + " vertex_indices\nend_header\n";
  for (std::size_t i = 0; i < nv; ++i) {
    put(data, Real(x_of(i)));
    put(data, Real(i == s.bad_vertex ? s.coordinate : y_of(i)));
    put(data, Real(z_of(i)));
  }
  for (std::size_t f = 0; f < s.n; ++f) {
    std::vector<std::uint32_t> face = quad(f);
    if (f == s.bad_face && s.size) {
      face.resize(*s.size);
      for (std::uint32_t j = 0; j < *s.size; ++j) face[j] = j;
    }
    put(data, Count(face.size()));
    for (std::size_t j = 0; j < face.size(); ++j) {
      put(data, f == s.bad_face && !s.size && j == 2 ? Index(s.index) : Index(face[j]));
    }
  }
  return data;
}

std::string error_of(const std::string& data) {
  try {
    io_detail::parse_ply_text(data, "s.ply");
  } catch (const IoError& e) {
    CHECK(e.line() == 0);
    return e.what();
  }
  FAIL("no error");
  return {};
}

template <class Real, class Count, class Index>
void check_layout() {
  const Strip good;
  const ParsedPolygons parsed = io_detail::parse_ply_text(strip_ply<Real, Count, Index>(good), "s.ply");
  const std::size_t nv = 2 * good.n + 2;
  REQUIRE(parsed.soup.positions.size() == nv);
  bool positions_ok = true;
  for (std::size_t i = 0; i < nv; ++i) {
    positions_ok =
        positions_ok && parsed.soup.positions[i] ==
                            glm::dvec3(double(Real(x_of(i))), double(Real(y_of(i))), double(Real(z_of(i))));
  }
  CHECK(positions_ok);
  REQUIRE(parsed.soup.num_faces() == good.n);
  for (std::size_t f = 0; f < good.n; ++f) {
    const auto face = parsed.soup.face(f);
    CHECK(std::vector<std::uint32_t>(face.begin(), face.end()) == quad(f));
  }
  CHECK(parsed.vertex_lines == std::vector<std::size_t>(nv, 0));
  CHECK(parsed.face_lines == std::vector<std::size_t>(good.n, 0));

  // Errors deep in the blocks name their element.
  CHECK(error_of(strip_ply<Real, Count, Index>(bad_index(61, std::int64_t(nv)))) ==
        "s.ply: face 61: vertex index " + std::to_string(nv) + " is out of range (there are " +
            std::to_string(nv) + " vertices)");
  CHECK(error_of(strip_ply<Real, Count, Index>(short_face(7, 2))) ==
        "s.ply: face 7: face has 2 vertices; at least 3 are needed");
  CHECK(error_of(strip_ply<Real, Count, Index>(bad_coordinate(150, HUGE_VAL))) ==
        "s.ply: vertex 150: coordinate is not finite");
  if constexpr (std::is_same_v<Index, std::int32_t>) {
    CHECK(error_of(strip_ply<Real, Count, Index>(bad_index(99, -1))) ==
          "s.ply: face 99: vertex index -1 is out of range (there are " + std::to_string(nv) + " vertices)");
  }
  // Cut in the last face, then in the vertex block (its last vertex lacks 2 bytes).
  const std::string data = strip_ply<Real, Count, Index>(good);
  CHECK(error_of(data.substr(0, data.size() - 3)) == "s.ply: face 99: the file ends early");
  const std::size_t vertex_block = data.find("end_header\n") + 11 + nv * 3 * sizeof(Real);
  CHECK(error_of(data.substr(0, vertex_block - 2)) == "s.ply: vertex 201: the file ends early");
}

}  // namespace

TEST_CASE("ply blocks: double and float coordinates, uchar and uint counts, uint and int indices") {
  check_layout<double, std::uint8_t, std::uint32_t>();
  check_layout<double, std::uint32_t, std::int32_t>();
  check_layout<float, std::uint8_t, std::int32_t>();
  check_layout<float, std::uint32_t, std::uint32_t>();
}
