// Text written in parallel parts (OBJ): the bytes of a plain serial formatting, whatever the thread count.

#include <doctest/doctest.h>

#include <charconv>
#include <cmath>
#include <sstream>
#include <string>

#include <dlfl/io/detail/write_in_parts.h>
#include <dlfl/io/obj.h>
#include <dlfl/thread_count.h>

using namespace dlfl;

namespace {

// OBJ as the writer is documented to write it, one number at a time: shortest round-trip decimals.
std::string reference_obj(const PolygonSoup& soup) {
  std::string text;
  char buffer[32];
  auto number = [&](auto value) { text.append(buffer, std::to_chars(buffer, buffer + 32, value).ptr); };
  for (const glm::dvec3& p : soup.positions) {
    text += "v ";
    number(p.x);
    text += ' ';
    number(p.y);
    text += ' ';
    number(p.z);
    text += '\n';
  }
  for (std::size_t f = 0; f < soup.num_faces(); ++f) {
    text += 'f';
    for (std::uint32_t i : soup.face(f)) {
      text += ' ';
      number(std::uint64_t{i} + 1);
    }
    text += '\n';
  }
  return text;
}

}  // namespace

TEST_CASE("write in parts: OBJ of many parts is the serial formatting, byte for byte") {
  // A fan of triangles and a few large faces around a spiral of awkward doubles: several parts of each.
  const std::size_t n = 5 * io_detail::lines_per_part + 17;
  PolygonSoup soup;
  for (std::size_t i = 0; i < n; ++i) {
    const double t = double(i);
    soup.positions.push_back({std::sin(t) / 3, -std::cos(t) * 1e-7, t * 1e20 + 0.1});
  }
  for (std::uint32_t i = 1; i + 1 < n; ++i) soup.add_face({0, i, i + 1});
  for (std::uint32_t i = 0; i + 400 < n; i += 5000) {
    std::vector<std::uint32_t> big;
    for (std::uint32_t j = 0; j < 400; ++j) big.push_back(i + j);
    soup.add_face(big);
  }
  REQUIRE(soup.num_faces() > 2 * io_detail::lines_per_part);
  const std::string expected = reference_obj(soup);
  for (unsigned threads : {1u, 2u, 3u}) {
    CAPTURE(threads);
    set_thread_count(threads);
    std::ostringstream out;
    write_obj(out, soup);
    CHECK(out.str() == expected);
  }
  set_thread_count(0);
}
