// MeshAssembler: a small closed mesh assembles to a valid one, and counts beyond 32-bit handles or offsets
// past the corners are refused before anything is allocated or written.

#include <doctest/doctest.h>

#include <cstdint>
#include <string>
#include <vector>

#include <dlfl/errors.h>
#include <dlfl/mesh_assembler.h>
#include <dlfl/validate.h>
#include "test_helpers.h"

using namespace dlfl;

namespace {
// The message of the InvalidArgument that `f` throws, or "" if it throws none.
template <class F>
std::string refusal(F&& f) {
  return test::error_message<InvalidArgument>(std::forward<F>(f));
}
}  // namespace

TEST_CASE("mesh assembler: two triangles back to back make a valid sphere") {
  // Face 0 is 0 1 2, face 1 is 0 2 1; each corner's twin runs along its outgoing edge the other way.
  const std::vector<std::uint32_t> offsets{0, 3, 6};
  MeshAssembler a(3, offsets);
  const std::uint32_t vertex[6] = {0, 1, 2, 0, 2, 1}, twin[6] = {5, 4, 3, 2, 1, 0};
  for (std::uint32_t k = 0; k < 6; ++k) a.set_corner(k, vertex[k], twin[k]);
  for (std::uint32_t v = 0; v < 3; ++v) a.set_position(v, glm::dvec3(v, v * v, 1));
  const Mesh m = a.finish();
  CHECK(m.num_vertices() == 3);
  CHECK(m.num_edges() == 3);
  CHECK(m.num_faces() == 2);
  CHECK(validate(m).valid());
}

TEST_CASE("mesh assembler: counts beyond 32-bit handles are refused naming the count") {
  const std::size_t max = MeshAssembler::max_count;
  CHECK(max == 0xFFFFFFFEu);
  CHECK_NOTHROW(MeshAssembler::check_counts(max, max, max));
  CHECK(refusal([&] { MeshAssembler::check_counts(max + 1, 1, 3); }) ==
        "MeshAssembler: 4294967295 vertices do not fit 32-bit handles (at most 4294967294)");
  CHECK(refusal([&] { MeshAssembler::check_counts(3, std::size_t(1) << 32, 3); }).find("4294967296 faces") !=
        std::string::npos);
  CHECK(refusal([&] {
          MeshAssembler::check_counts(3, 1, std::size_t(5) << 30);
        }).find("5368709120 corners") != std::string::npos);
  // The constructors check before they allocate. These counts are safe even without the check (std::vector
  // would throw std::length_error, not InvalidArgument): 2^62 quads wrap std::size_t to 0 corners, and 2^60
  // vertices are beyond any vector of positions.
  CHECK(
      refusal([] { MeshAssembler(4, std::size_t(1) << 62, 4); }) ==
      "MeshAssembler: 4611686018427387904 faces of 4 corners do not fit 32-bit handles (at most 4294967294)");
  CHECK(refusal([] { MeshAssembler(std::size_t(1) << 60, 1, 3); }).find("1152921504606846976 vertices") !=
        std::string::npos);
  const std::vector<std::uint32_t> one_triangle{0, 3};
  CHECK(refusal([&] {
          MeshAssembler(std::size_t(1) << 60, one_triangle);
        }).find("1152921504606846976 vertices") != std::string::npos);
  // 2^31 quads, as a scheme would ask for them: 2^33 corners.
  CHECK(refusal([&] {
          MeshAssembler::check_counts(4, std::size_t(1) << 31, std::size_t(1) << 33);
        }).find("8589934592 corners") != std::string::npos);
}

TEST_CASE("mesh assembler: offsets past the last corner are refused before they are written") {
  // Face 0 would own corners 0 .. 9 of only 5; the decrease is seen at face 1, too late without the check.
  const std::vector<std::uint32_t> offsets{0, 10, 5};
  CHECK(refusal([&] { MeshAssembler(3, offsets); }).find("face 0 ends at corner 10, past the 5 corners") !=
        std::string::npos);
  const std::vector<std::uint32_t> from_one{1, 4};
  CHECK(refusal([&] { MeshAssembler(3, from_one); }).find("start at 0") != std::string::npos);
  CHECK(refusal([] { MeshAssembler(3, 2, 1); }).find("at least 2 corners") != std::string::npos);
}
