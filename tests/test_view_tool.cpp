// dlfl view: the page is self-contained (nothing to load from the network, no external script), holds the
// steps it was asked for with the counts derived by hand, leaves hole faces out, and bad input leaves no
// file. The page drawn in a real browser: tests/browser/view_in_chromium.py.

#include <doctest/doctest.h>

#ifdef DLFL_TOOL
#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include <dlfl/render/colors.h>
#include "tool_runner.h"

using namespace dlfl::test;

namespace {

// The page's data: the JSON of its <script id="dlfl-data"> element.
nlohmann::json page_data(const std::string& page) {
  const std::string open = "<script id=\"dlfl-data\" type=\"application/json\">";
  const std::size_t begin = page.find(open);
  REQUIRE(begin != std::string::npos);
  const std::size_t end = page.find("</script>", begin);
  REQUIRE(end != std::string::npos);
  return nlohmann::json::parse(page.substr(begin + open.size(), end - begin - open.size()));
}

// Base64 decoded here, independently of the tool's encoder.
std::vector<unsigned char> decoded(const std::string& text) {
  const std::string digits = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::vector<unsigned char> bytes;
  unsigned bits = 0, held = 0;
  for (const char c : text) {
    if (c == '=') break;
    const std::size_t value = digits.find(c);
    if (value == std::string::npos) FAIL("not base64: " << c);
    bits = (bits << 6 | static_cast<unsigned>(value)) & 0xffffff;
    held += 6;
    if (held >= 8) {
      held -= 8;
      bytes.push_back(static_cast<unsigned char>(bits >> held));
    }
  }
  return bytes;
}

// Little-endian 32-bit unsigned values.
std::vector<std::uint32_t> uint32s(const std::string& text) {
  const std::vector<unsigned char> bytes = decoded(text);
  REQUIRE(bytes.size() % 4 == 0);
  std::vector<std::uint32_t> values;
  for (std::size_t i = 0; i < bytes.size(); i += 4)
    values.push_back(bytes[i] | bytes[i + 1] << 8 | bytes[i + 2] << 16 | std::uint32_t{bytes[i + 3]} << 24);
  return values;
}

std::string quoted(const std::filesystem::path& path) { return "'" + path.string() + "'"; }

}  // namespace

TEST_CASE("view: the cube through two Catmull-Clark steps, a page that loads nothing") {
  const auto out = scratch("cube.html");
  const Run r = run("view " + example("cube.obj") + " -s catmull-clark -n 2 -o " + quoted(out));
  REQUIRE(r.exit_code == 0);
  CHECK(r.err.empty());
  const std::string page = read_text(out);
  CHECK(page.rfind("<!DOCTYPE html>", 0) == 0);
  CHECK(page.find("http://") == std::string::npos);
  CHECK(page.find("https://") == std::string::npos);
  CHECK(page.find("<script src") == std::string::npos);  // viewer.js is inline
  CHECK(page.find("<link") == std::string::npos);
  CHECK(page.find("@DLFL_") == std::string::npos);  // every marker filled
  const nlohmann::json data = page_data(page);
  const auto& steps = data["steps"];
  REQUIRE(steps.size() == 3);
  // Catmull-Clark on a closed quad mesh: V' = V + E + F, E' = 2E + 4F... per step, F' = 4F (all quads).
  const int vertices[] = {8, 26, 98}, edges[] = {12, 48, 192}, faces[] = {6, 24, 96};
  for (int k = 0; k < 3; ++k) {
    CAPTURE(k);
    const auto& step = steps[k];
    CHECK(step["label"] == "M_" + std::to_string(k));
    CHECK(step["counts"] == "V " + std::to_string(vertices[k]) + ", E " + std::to_string(edges[k]) + ", F " +
                                std::to_string(faces[k]));
    CHECK(decoded(step["positions"]).size() == 12u * vertices[k]);  // three float32 per vertex
    const std::vector<std::uint32_t> triangles = uint32s(step["triangles"]);
    CHECK(triangles.size() == 3u * 2 * faces[k]);  // two triangles per quad
    CHECK(*std::max_element(triangles.begin(), triangles.end()) < static_cast<std::uint32_t>(vertices[k]));
    CHECK(uint32s(step["edges"]).size() == 2u * edges[k]);
    const std::vector<unsigned char> colors = decoded(step["triangle_colors"]);
    CHECK(colors.size() == 3u * 2 * faces[k]);
    // One row for the quads, in the palette's quad colour as #rrggbb.
    const dlfl::Rgba quad = dlfl::face_size_color(4);
    char hex[8];
    std::snprintf(hex, sizeof hex, "#%02x%02x%02x", quad.r, quad.g, quad.b);
    CHECK(step["face_sizes"] == nlohmann::json::array({{4, faces[k], std::string(hex)}}));
  }
  // The data's frame: the cube [-1, 1]^3 centred on the origin already.
  CHECK(steps[0]["bbox"] == nlohmann::json({{-1.0, -1.0, -1.0}, {1.0, 1.0, 1.0}}));
}

TEST_CASE("view: a log's steps are the meshes after each op, group brackets left out") {
  const std::string log = std::string(DLFL_SOURCE_DIR) + "/data/genus3_handles.log.json";
  const auto out = scratch("handles.html");
  REQUIRE(run("view '" + log + "' -o " + quoted(out)).exit_code == 0);
  const nlohmann::json ops = nlohmann::json::parse(read_text(log))["ops"];
  std::vector<std::string> expected;
  for (std::size_t i = 0; i < ops.size(); ++i) {
    const std::string op = ops[i]["op"];
    if (op != "begin_group" && op != "end_group") expected.push_back(std::to_string(i) + ": " + op);
  }
  REQUIRE(expected.size() == 6);  // load, extrude_face, three connect_faces, subdivide
  const nlohmann::json data = page_data(read_text(out));
  const auto& steps = data["steps"];
  REQUIRE(steps.size() == expected.size());
  for (std::size_t k = 0; k < expected.size(); ++k) {
    const std::string label = steps[k]["label"];
    CHECK(label.rfind(expected[k], 0) == 0);
  }
  CHECK(steps[0]["label"] == "0: load cube.obj");
}

TEST_CASE("view: hole faces are left out, their edges drawn") {
  // One quad, open: the quad and its hole face share four edges.
  const auto in = scratch_file("quad.obj", "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n");
  const auto out = scratch("quad.html");
  REQUIRE(run("view " + quoted(in) + " -o " + quoted(out)).exit_code == 0);
  const nlohmann::json data = page_data(read_text(out));
  const auto& step = data["steps"][0];
  CHECK(uint32s(step["triangles"]).size() == 6u);  // the quad's two triangles only
  CHECK(uint32s(step["edges"]).size() == 8u);
  CHECK(step["counts"] == "V 4, E 4, F 1, 1 hole");
}

TEST_CASE("view: a name with markup stays text in the page") {
  ScratchDir dir;
  const auto in = dir / "a<b>&.obj";
  std::filesystem::copy_file(std::string(DLFL_SOURCE_DIR) + "/data/cube.obj", in);
  const auto out = dir / "page.html";
  REQUIRE(run("view " + quoted(in) + " -o " + quoted(out)).exit_code == 0);
  const std::string page = read_text(out);
  CHECK(page.find("a<b>") == std::string::npos);
  CHECK(page.find("<title>a&lt;b&gt;&amp;.obj</title>") != std::string::npos);
  CHECK(page_data(page)["title"] == "a<b>&.obj");
}

TEST_CASE("view: refusals write nothing, with one line and the tool's exit codes") {
  ScratchDir dir;
  const auto out = dir / "page.html";
  struct Case {
    std::string args;
    int exit_code;
  };
  const std::string log = std::string("'") + DLFL_SOURCE_DIR + "/data/genus3_handles.log.json'";
  const Case cases[] = {
      {"view " + example("cube.obj") + " -o " + quoted(dir / "page.png"), 2},   // not a page's name
      {"view " + example("cube.obj") + " -n 2 -o " + quoted(out), 2},           // -n without -s
      {"view " + example("cube.obj") + " --param t=0.5 -o " + quoted(out), 2},  // --param without -s
      {"view " + example("cube.obj") + " -s no-such-scheme -o " + quoted(out), 2},
      {"view " + log + " -s catmull-clark -o " + quoted(out), 2},  // a log's steps are its ops
      {"view /nonexistent/cube.obj -o " + quoted(out), 1},
      // 6 + 24 + 96 faces planned: refused before the steps run.
      {"view " + example("cube.obj") + " -s catmull-clark -n 2 --max-faces 100 -o " + quoted(out), 1},
      {"view " + example("cube.obj") + " --max-faces 5 -o " + quoted(out), 1},
  };
  for (const Case& c : cases) {
    CAPTURE(c.args);
    const Run r = run(c.args);
    CHECK(r.exit_code == c.exit_code);
    CHECK(r.err.rfind("error: ", 0) == 0);
    CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
    CHECK(dir.entries().empty());
  }
  // The face limit counts every step: 6 + 24 + 96 = 126 faces pass at 126.
  CHECK(run("view " + example("cube.obj") + " -s catmull-clark -n 2 --max-faces 126 -o " + quoted(out))
            .exit_code == 0);
}

TEST_CASE("view: the face-size colours tell every size from 3 to 11 apart, hexagons one colour") {
  for (std::uint32_t a = 3; a <= 11; ++a)
    for (std::uint32_t b = a + 1; b <= 11; ++b)
      CHECK_FALSE(dlfl::face_size_color(a) == dlfl::face_size_color(b));
  // Faces of 11 sides and more share one colour; so do those below 3.
  CHECK(dlfl::face_size_color(11) == dlfl::face_size_color(40));
  CHECK(dlfl::face_size_color(1) == dlfl::face_size_color(2));
}
#endif
