// The chunked (parallel) OBJ parser: the serial parser's result and errors, whatever the chunk size and
// thread count.

#include <doctest/doctest.h>

#include <cstring>
#include <optional>
#include <string>
#include <vector>

#include <dlfl/errors.h>
#include <dlfl/io/detail/obj_lines.h>
#include <dlfl/thread_count.h>

using namespace dlfl;
using io_detail::parse_obj_chunked;
using io_detail::parse_obj_serial;

namespace {

// One block of OBJ with the features the reader handles: comments, ignored statements, blanks and CRLF,
// w and colour values, the index forms, relative indices, and tokens that only look like statements. It
// defines 6 vertices and 5 faces in 22 lines; relative indices stay within the block.
const std::string block =
    "# a square and more\n"              // 1
    "mtllib square.mtl\n"                // 2
    "o square\n"                         // 3
    "v 0 0 0\n"                          // 4
    "v 1 0 0 1.0\n"                      // 5
    "v 1 1 0 0.5 0.25 1\n"               // 6
    "  v\t0 1 0  \r\n"                   // 7
    "vt 0 0\n"                           // 8
    "v# not a vertex\n"                  // 9
    "fo 1 2 3\n"                         // 10
    "s off\n"                            // 11
    "\r\n"                               // 12
    "\n"                                 // 13
    "f 1/1/1 2/2/1 3/3/1 # a comment\n"  // 14
    "f 1//1 3//1 4//1\n"                 // 15
    "l 1 2\n"                            // 16
    "f -4/1 -2 -1\n"                     // 17
    "vp 0.5\n"                           // 18
    "v 2 0 0.1\n"                        // 19
    "v 2 1 -0.3e-2\n"                    // 20
    "\tf 2 5 6 3\n"                      // 21
    "f -5 -2 -1\n";                      // 22
constexpr std::size_t block_lines = 22, block_vertices = 6, block_faces = 5;

// `n` blocks, with a UTF-8 byte order mark before the first and no newline after the last.
std::string blocks(std::size_t n) {
  std::string text = "\xEF\xBB\xBF";
  for (std::size_t i = 0; i < n; ++i) text += block;
  text.pop_back();
  return text;
}

// Equal to the bit, positions included (== would take -0 for 0).
void check_same(const ParsedPolygons& a, const ParsedPolygons& b) {
  REQUIRE(a.soup.positions.size() == b.soup.positions.size());
  CHECK(std::memcmp(a.soup.positions.data(), b.soup.positions.data(),
                    a.soup.positions.size() * sizeof(glm::dvec3)) == 0);
  CHECK(a.soup.offsets == b.soup.offsets);
  CHECK(a.soup.indices == b.soup.indices);
  CHECK(a.vertex_lines == b.vertex_lines);
  CHECK(a.face_lines == b.face_lines);
  CHECK(a.numbering.first_vertex == b.numbering.first_vertex);
  CHECK(a.numbering.first_face == b.numbering.first_face);
}

// The IoError that `parse` throws.
template <class Parse>
IoError error_of(Parse&& parse) {
  std::optional<IoError> error;
  try {
    parse();
  } catch (const IoError& e) {
    error = e;
  }
  REQUIRE(error.has_value());
  return *error;
}

}  // namespace

TEST_CASE("obj chunks: the serial parser's polygons and lines, whatever the chunk size") {
  const std::size_t n = 300;
  const std::string text = blocks(n);
  const ParsedPolygons serial = parse_obj_serial(text, "blocks.obj");
  // Counts and lines from the block's layout, independently of either parser.
  REQUIRE(serial.soup.positions.size() == n * block_vertices);
  REQUIRE(serial.soup.num_faces() == n * block_faces);
  CHECK(serial.vertex_lines.back() == (n - 1) * block_lines + 20);
  CHECK(serial.face_lines.back() == (n - 1) * block_lines + 22);
  // The last block's relative face "f -5 -2 -1" names its vertices 2, 5 and 6.
  const std::size_t last = (n - 1) * block_vertices;
  CHECK(
      std::vector<std::uint32_t>(serial.soup.indices.end() - 3, serial.soup.indices.end()) ==
      std::vector<std::uint32_t>{std::uint32_t(last + 1), std::uint32_t(last + 4), std::uint32_t(last + 5)});
  // From a chunk per line to a single chunk, and sizes that cut lines anywhere.
  for (std::size_t chunk_bytes : {std::size_t{1}, std::size_t{2}, std::size_t{7}, std::size_t{64},
                                  std::size_t{1000}, std::size_t{4099}, text.size() - 1, text.size() + 1}) {
    CAPTURE(chunk_bytes);
    check_same(parse_obj_chunked(text, "blocks.obj", chunk_bytes), serial);
  }
}

TEST_CASE("obj chunks: only the file's first byte order mark is skipped") {
  // After the first mark, a second one is part of the first token, which is then no statement.
  const std::string text = "\xEF\xBB\xBF\xEF\xBB\xBFv 9 9 9\n" + blocks(3);
  const ParsedPolygons serial = parse_obj_serial(text, "marks.obj");
  CHECK(serial.soup.positions.size() == 3 * block_vertices);
  for (std::size_t chunk_bytes : {std::size_t{1}, std::size_t{40}, text.size()}) {
    CAPTURE(chunk_bytes);
    check_same(parse_obj_chunked(text, "marks.obj", chunk_bytes), serial);
  }
}

TEST_CASE("obj chunks: a file of several default chunks, and any thread count") {
  // Over 2 MiB: parse_obj_text splits it into chunks of obj_chunk_bytes.
  const std::size_t n = 3 * io_detail::obj_chunk_bytes / block.size();
  const std::string text = blocks(n);
  REQUIRE(text.size() > 2 * io_detail::obj_chunk_bytes);
  const ParsedPolygons serial = parse_obj_serial(text, "big.obj");
  for (unsigned threads : {1u, 2u, 3u}) {
    CAPTURE(threads);
    set_thread_count(threads);
    check_same(io_detail::parse_obj_text(text, "big.obj"), serial);
  }
  set_thread_count(0);
}

TEST_CASE("obj chunks: an error in a late chunk is the serial parser's, at the same line") {
  const std::size_t n = 200;
  const std::string good = blocks(n) + "\n";
  const std::size_t good_lines = n * block_lines;
  const std::size_t vertices = n * block_vertices;
  struct Case {
    std::string tail;   // after the good blocks
    std::size_t line;   // of the error, counted from the end of the good blocks
    const char* start;  // of the message, after "bad.obj:<line>: "
  };
  const std::vector<Case> cases = {
      {"v 0 0 0\nf 1 2\n", 2, "face has 2 vertices"},
      {"v 1 oops 0\n", 1, "bad y coordinate 'oops'"},
      {"f 1 x 3\n", 1, "bad vertex index 'x'"},
      {"# c\nf 1 2 0\n", 2, "vertex index 0 is out of range"},
      {"f 1 2 -" + std::to_string(vertices + 1) + "\n", 1, "relative vertex index"},
      // Checked once the whole file is read; the first bad face counts, not the last.
      {"f 1 2 " + std::to_string(vertices + 1) + "\nf 1 2 " + std::to_string(vertices + 9) + "\n", 1,
       "vertex index "},
      // Two errors in different chunks: the first one counts.
      {"v 1 2 nan\n" + block + "v 1 1 1 \nf 1\n", 1, "z coordinate 'nan' is not finite"},
  };
  for (const Case& c : cases) {
    const std::string text = good + c.tail;
    CAPTURE(c.tail);
    const IoError serial = error_of([&] { parse_obj_serial(text, "bad.obj"); });
    CHECK(serial.line() == good_lines + c.line);
    for (std::size_t chunk_bytes : {std::size_t{1}, std::size_t{100}, std::size_t{5000}}) {
      CAPTURE(chunk_bytes);
      const IoError chunked = error_of([&] { parse_obj_chunked(text, "bad.obj", chunk_bytes); });
      CHECK(chunked.line() == serial.line());
      CHECK(std::string(chunked.what()) == serial.what());
      CHECK(chunked.file() == "bad.obj");
      const std::string location = "bad.obj:" + std::to_string(good_lines + c.line) + ": ";
      CHECK(std::string(chunked.what()).rfind(location + c.start, 0) == 0);
    }
  }
}
