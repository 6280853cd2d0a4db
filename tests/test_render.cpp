// The renderer (dlfl/render/, `dlfl render`): pixels predicted from the camera formula by hand, colours from
// the fixed face-size palette, the orientation test against reverse_orientation, holes, PNG files read back
// through libpng's own reader, SVG structure, and the tool's refusals.

#include <doctest/doctest.h>
#include <png.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include <dlfl/build_mesh.h>
#include <dlfl/operations/reverse_orientation.h>
#include <dlfl/render/contact_sheet.h>
#include <dlfl/render/font.h>
#include <dlfl/render/png.h>
#include <dlfl/render/rasterizer.h>
#include <dlfl/render/svg.h>
#include "open_meshes.h"
#include "test_helpers.h"
#include "test_meshes.h"
#include "tool_runner.h"

using namespace dlfl;

namespace {

// The unit cube [0, 1]^3, faces counter-clockwise seen from outside.
PolygonSoup unit_cube_soup() {
  PolygonSoup s;
  for (int k = 0; k < 8; ++k) s.positions.push_back({double(k & 1), double(k >> 1 & 1), double(k >> 2 & 1)});
  s.add_face({0, 2, 3, 1});  // z = 0
  s.add_face({4, 5, 7, 6});  // z = 1
  s.add_face({0, 1, 5, 4});  // y = 0
  s.add_face({2, 6, 7, 3});  // y = 1
  s.add_face({0, 4, 6, 2});  // x = 0
  s.add_face({1, 3, 7, 5});  // x = 1
  return s;
}

Camera fitted(const RenderScene& scene, View view, int w, int h) {
  Camera camera(view_angles(view), w, h);
  camera.include(scene.positions);
  camera.fit();
  return camera;
}

RenderOptions transparent_without_edges() {
  RenderOptions o;
  o.edges = false;
  o.background = {255, 255, 255, 0};
  return o;
}

bool covered(const Image& image, int x, int y) { return image.at(x, y).a >= 128; }

// The colour of a face turned straight to the viewer: lit by the ambient share plus the rest times the cosine
// to the light, which for the normal (0, 0, 1) is the light direction's z.
Rgba facing_color(Rgba base) {
  const double intensity = light_ambient + (1 - light_ambient) * light_direction.z;
  auto channel = [&](std::uint8_t c) { return static_cast<std::uint8_t>(std::lround(c * intensity)); };
  return {channel(base.r), channel(base.g), channel(base.b), 255};
}

// Pixels of `a` whose colour differs from the same pixel of `b`.
std::vector<bool> differing(const Image& a, const Image& b) {
  std::vector<bool> d(a.pixels().size());
  for (std::size_t i = 0; i < d.size(); ++i) d[i] = !(a.pixels()[i] == b.pixels()[i]);
  return d;
}

}  // namespace

TEST_CASE("render: the front view of the unit cube covers the square the camera formula predicts") {
  // 200 x 100 pixels, the cube's front face 1 x 1: scale = min(200 * 0.9 / 1, 100 * 0.9 / 1) = 90 pixels per
  // unit, centred at (100, 50): the square [55, 145) x [5, 95).
  const RenderScene scene = mesh_scene(build_mesh(unit_cube_soup()));
  const Camera camera = fitted(scene, View::front, 200, 100);
  CHECK(camera.scale == doctest::Approx(90.0));
  const Image image = render(scene, camera, transparent_without_edges());
  REQUIRE(image.width() == 200);
  REQUIRE(image.height() == 100);
  int low_x = 200, high_x = -1, low_y = 100, high_y = -1;
  for (int y = 0; y < 100; ++y) {
    for (int x = 0; x < 200; ++x) {
      if (!covered(image, x, y)) continue;
      low_x = std::min(low_x, x), high_x = std::max(high_x, x);
      low_y = std::min(low_y, y), high_y = std::max(high_y, y);
    }
  }
  CHECK(std::abs(low_x - 55) <= 1);
  CHECK(std::abs(high_x + 1 - 145) <= 1);
  CHECK(std::abs(low_y - 5) <= 1);
  CHECK(std::abs(high_y + 1 - 95) <= 1);
  // Inside it, one pixel in from each side, every pixel is the lit front face; no hole in the square.
  for (int y = 6; y < 94; ++y) {
    for (int x = 56; x < 144; ++x) REQUIRE(image.at(x, y) == facing_color(face_size_color(4)));
  }
}

TEST_CASE("render: colour by face size shows the quad's colour exactly where the quad projects") {
  // A 4 x 4 grid of unit squares in z = 0, each split into two triangles but the square [1, 2] x [1, 2]. At
  // 200 x 200 the fit gives 45 pixels per unit around (2, 2) -> (100, 100): the quad is [55, 100) x [100,
  // 145) and the mesh [10, 190)^2.
  PolygonSoup soup;
  for (int j = 0; j <= 4; ++j) {
    for (int i = 0; i <= 4; ++i) soup.positions.push_back({double(i), double(j), 0.0});
  }
  auto id = [](int i, int j) { return std::uint32_t(j * 5 + i); };
  for (int j = 0; j < 4; ++j) {
    for (int i = 0; i < 4; ++i) {
      if (i == 1 && j == 1) {
        soup.add_face({id(1, 1), id(2, 1), id(2, 2), id(1, 2)});
        continue;
      }
      soup.add_face({id(i, j), id(i + 1, j), id(i + 1, j + 1)});
      soup.add_face({id(i, j), id(i + 1, j + 1), id(i, j + 1)});
    }
  }
  const RenderScene scene = mesh_scene(build_mesh(soup), parse_color_by("face-size"));
  const Image image = render(scene, fitted(scene, View::front, 200, 200), transparent_without_edges());
  const Rgba quad = facing_color(face_size_color(4)), triangle = facing_color(face_size_color(3));
  REQUIRE_FALSE(quad == triangle);
  int quad_pixels = 0;
  for (int y = 0; y < 200; ++y) {
    for (int x = 0; x < 200; ++x) {
      const bool near_quad_border =
          x >= 54 && x <= 100 && y >= 99 && y <= 145 && !(x > 55 && x < 99 && y > 100 && y < 144);
      const bool near_mesh_border = x <= 10 || x >= 189 || y <= 10 || y >= 189;
      if (near_quad_border || near_mesh_border) continue;
      const bool in_quad = x > 55 && x < 99 && y > 100 && y < 144;
      const bool in_mesh = x > 10 && x < 189 && y > 10 && y < 189;
      const Rgba expected = in_quad ? quad : in_mesh ? triangle : Rgba{255, 255, 255, 0};
      if (in_quad) ++quad_pixels;
      REQUIRE(image.at(x, y) == expected);
    }
  }
  CHECK(quad_pixels == 43 * 43);
}

TEST_CASE("render: a mesh and its reverse_orientation differ only in the back-face shading") {
  // An open box (the cube without its top), seen from above at an angle: its outside and its inside show.
  PolygonSoup soup = unit_cube_soup();
  const PolygonSoup box = test::soup_part(soup, [](std::size_t f) { return f != 3; });
  const Mesh mesh = build_mesh(box);
  Mesh reversed = mesh;
  {
    Transaction tx(reversed);
    reverse_orientation(tx);
    tx.commit();
  }
  const RenderScene a = mesh_scene(mesh), b = mesh_scene(reversed);
  const Camera camera = fitted(a, View::iso, 160, 120);
  RenderOptions plain = transparent_without_edges();
  plain.back_tint = false;
  RenderOptions tinted = transparent_without_edges();
  // Without the tint the two are the same picture, pixel for pixel.
  const Image a_plain = render(a, camera, plain), b_plain = render(b, camera, plain);
  CHECK(a_plain == b_plain);
  // With it, the pixels tinted in one are exactly the pixels not tinted in the other: back faces of one are
  // front faces of the other. Pixels that mix both (their border) are tinted in both.
  const Image a_tinted = render(a, camera, tinted), b_tinted = render(b, camera, tinted);
  const std::vector<bool> back_a = differing(a_tinted, a_plain), back_b = differing(b_tinted, b_plain);
  std::size_t covered_pixels = 0, in_a = 0, in_b = 0, in_both = 0;
  for (std::size_t i = 0; i < back_a.size(); ++i) {
    const bool is_covered = a_plain.pixels()[i].a > 0;
    covered_pixels += is_covered;
    REQUIRE(a_tinted.pixels()[i].a == b_tinted.pixels()[i].a);
    if (!is_covered) {
      REQUIRE_FALSE(back_a[i]);
      REQUIRE_FALSE(back_b[i]);
      continue;
    }
    REQUIRE((back_a[i] || back_b[i]));
    in_a += back_a[i], in_b += back_b[i], in_both += back_a[i] && back_b[i];
  }
  CHECK(in_a > covered_pixels / 10);
  CHECK(in_b > covered_pixels / 10);
  CHECK(in_both < covered_pixels / 25);
}

TEST_CASE("render: an open mesh shows the background through its hole") {
  // A 3 x 3 grid of unit quads with the middle one left out, front view at 90 x 90: 90 * 0.9 / 3 = 27 pixels
  // per unit around (1.5, 1.5) -> (45, 45), so the hole [1, 2]^2 covers the pixels [31.5, 58.5)^2.
  const Mesh open = build_mesh(test::grid_with_holes(3, 3, {{1, 1}}));
  const Mesh closed = build_mesh(test::grid_with_holes(3, 3, {}));
  REQUIRE(open.num_hole_faces() == 2);
  const RenderScene open_scene = mesh_scene(open), closed_scene = mesh_scene(closed);
  const Camera camera = fitted(open_scene, View::front, 90, 90);
  const Image with_hole = render(open_scene, camera, transparent_without_edges());
  const Image without = render(closed_scene, camera, transparent_without_edges());
  for (int y = 33; y < 57; ++y) {
    for (int x = 33; x < 57; ++x) {
      REQUIRE(with_hole.at(x, y).a == 0);
      REQUIRE(without.at(x, y).a == 255);
    }
  }
  CHECK(with_hole.at(20, 20).a == 255);  // the surface around the hole
}

TEST_CASE("render: a PNG read back through libpng's reader has the picture's size and pixels") {
  const RenderScene scene = mesh_scene(test::cube());
  for (bool transparent : {false, true}) {
    CAPTURE(transparent);
    RenderOptions options;
    if (transparent) options.background.a = 0;
    const Image image = render(scene, fitted(scene, View::iso, 37, 23), options);
    const auto path = test::scratch("render.png");
    write_png(image, path);
    png_image read{};
    read.version = PNG_IMAGE_VERSION;
    REQUIRE(png_image_begin_read_from_file(&read, path.c_str()) != 0);
    CHECK(read.width == 37);
    CHECK(read.height == 23);
    CHECK(((read.format & PNG_FORMAT_FLAG_ALPHA) != 0) == transparent);
    read.format = PNG_FORMAT_RGBA;
    std::vector<png_byte> bytes(PNG_IMAGE_SIZE(read));
    REQUIRE(png_image_finish_read(&read, nullptr, bytes.data(), 0, nullptr) != 0);
    for (int y = 0; y < 23; ++y) {
      for (int x = 0; x < 37; ++x) {
        const png_byte* p = bytes.data() + 4 * (y * 37 + x);
        const Rgba expected = image.at(x, y);
        REQUIRE(Rgba{p[0], p[1], p[2], p[3]} == expected);
      }
    }
  }
}

namespace {

// The number of elements named `tag`, after checking that the text is well-formed XML as far as a line
// drawing uses it: one root, every element closed in order, attribute values quoted, no stray '<' or '&'.
std::size_t well_formed_count(const std::string& text, const std::string& tag) {
  std::vector<std::string> open;
  std::size_t count = 0, roots = 0;
  std::size_t at = text.find("?>");
  REQUIRE(text.starts_with("<?xml"));
  REQUIRE(at != std::string::npos);
  for (at += 2; (at = text.find('<', at)) != std::string::npos;) {
    const std::size_t end = text.find('>', at);
    REQUIRE(end != std::string::npos);
    std::string inside = text.substr(at + 1, end - at - 1);
    REQUIRE(inside.find('<') == std::string::npos);
    std::size_t quotes = std::count(inside.begin(), inside.end(), '"');
    REQUIRE(quotes % 2 == 0);
    if (inside.starts_with("/")) {
      REQUIRE_FALSE(open.empty());
      REQUIRE(inside.substr(1) == open.back());
      open.pop_back();
    } else {
      const std::string name = inside.substr(0, inside.find_first_of(" /"));
      if (open.empty()) ++roots;
      count += name == tag;
      if (!inside.ends_with("/")) open.push_back(name);
    }
    at = end + 1;
  }
  CHECK(open.empty());
  CHECK(roots == 1);
  CHECK(text.find('&') == std::string::npos);
  return count;
}

std::string svg_of(const Mesh& mesh, View view) {
  const RenderScene scene = mesh_scene(mesh);
  std::ostringstream out;
  write_svg(scene, fitted(scene, view, 120, 90), RenderOptions{}, out);
  return out.str();
}

}  // namespace

TEST_CASE("render: SVG is well-formed with one polygon per face in sight") {
  const Mesh cube = build_mesh(unit_cube_soup());
  // From the front, the four sides are edge-on and the back is hidden: one face. From (1, 1, 1): three.
  CHECK(well_formed_count(svg_of(cube, View::front), "polygon") == 1);
  CHECK(well_formed_count(svg_of(cube, View::iso), "polygon") == 3);
  // An open box shows its inside too: all five faces.
  const Mesh box = build_mesh(test::soup_part(unit_cube_soup(), [](std::size_t f) { return f != 3; }));
  CHECK(well_formed_count(svg_of(box, View::iso), "polygon") == 5);
}

TEST_CASE("render: hexahedra show their boundary quads, cells their curves and points") {
  // Two hexahedra sharing a face: 2 * 6 - 2 = 10 boundary quads, 20 - 2 = ... edges: a 2 x 1 x 1 block has
  // 12 vertices and 20 edges. One extra segment and one point.
  CellComplex c;
  for (int k = 0; k < 12; ++k) c.positions.push_back({double(k % 3), double(k / 3 % 2), double(k / 6)});
  auto v = [](int x, int y, int z) { return std::uint32_t(x + 3 * y + 6 * z); };
  for (int x = 0; x < 2; ++x) {
    c.add_cell({v(x, 0, 0), v(x + 1, 0, 0), v(x, 1, 0), v(x + 1, 1, 0), v(x, 0, 1), v(x + 1, 0, 1),
                v(x, 1, 1), v(x + 1, 1, 1)});
  }
  c.add_cell({v(0, 0, 0), v(2, 1, 1)});
  c.add_cell({v(1, 1, 1)});
  const RenderScene scene = cell_scene(c);
  CHECK(scene.num_polygons() == 10);
  CHECK(scene.edges.size() == 2 * 20);
  CHECK(scene.curves.size() == 2);
  CHECK(scene.points.size() == 1);
  CHECK_THROWS_AS(cell_scene(c, parse_color_by("component")), ParameterError);
}

TEST_CASE("render: colour modes and options are refused by name") {
  CHECK_THROWS_AS(parse_color_by("rainbow"), ParameterError);
  CHECK_THROWS_AS(parse_color_by("attribute="), ParameterError);
  CHECK_THROWS_AS(parse_view("sideways"), ParameterError);
  CHECK_THROWS_AS(parse_color("#12345"), ParameterError);
  CHECK(parse_color("#102030") == Rgba{16, 32, 48, 255});
  Mesh mesh = test::cube();
  CHECK_THROWS_AS(mesh_scene(mesh, parse_color_by("attribute=weight")), ParameterError);
  mesh.add_face_attribute<glm::dvec3>("direction");
  CHECK_THROWS_AS(mesh_scene(mesh, parse_color_by("attribute=direction")), ParameterError);
  // A numeric face attribute: the smallest value at one end of the ramp, the largest at the other.
  auto weight = mesh.add_face_attribute<double>("weight", 1.0);
  weight[FaceId(0)] = 5.0;
  const RenderScene scene = mesh_scene(mesh, parse_color_by("attribute=weight"));
  CHECK(scene.polygon_colors[0] == ramp_color(1.0));
  CHECK(scene.polygon_colors[1] == ramp_color(0.0));
}

TEST_CASE("render: a contact sheet puts its pictures side by side above their captions") {
  const std::vector<Image> pictures(3, Image(40, 30, {255, 0, 0, 255}));
  const std::vector<std::string> captions{"M0", "M1", "M2\nV 1"};
  const Image sheet = contact_sheet(pictures, captions, {255, 255, 255, 255});
  CHECK(sheet.width() == 3 * 40);
  CHECK(sheet.height() > 30 + 2 * glyph_height);
  CHECK(sheet.at(119, 29) == Rgba{255, 0, 0, 255});
  CHECK(sheet.at(119, 30) == Rgba{255, 255, 255, 255});
  CHECK_THROWS_AS(contact_sheet(pictures, std::vector<std::string>{"M0"}, {}), InvalidArgument);
  // A caption far wider than its picture is cut at the picture's sides: the other captions' strips stay
  // background.
  const std::vector<std::string> long_first{std::string(40, 'W'), "", ""};
  const Image cut = contact_sheet(pictures, long_first, {255, 255, 255, 255});
  for (int y = 30; y < cut.height(); ++y) {
    for (int x = 40; x < 120; ++x) REQUIRE(cut.at(x, y) == Rgba{255, 255, 255, 255});
  }
}

#ifdef DLFL_TOOL
TEST_CASE("dlfl render: refusals leave no file; a good run writes a PNG") {
  using test::run;
  const auto out = test::scratch("picture.png");
  const std::string cube = test::example("cube.obj");
  std::filesystem::remove(out);
  for (const std::string bad : {"--size 0x10", "--size 20x20x", "--view sideways", "--color-by rainbow",
                                "--color-by attribute=nope", "--zoom 0"}) {
    CAPTURE(bad);
    const test::Run r = run("render " + cube + " -o '" + out.string() + "' " + bad);
    CHECK(r.exit_code == 2);
    CHECK(r.err.starts_with("error: "));
    CHECK(std::count(r.err.begin(), r.err.end(), '\n') == 1);
    CHECK_FALSE(std::filesystem::exists(out));
  }
  const auto text = test::scratch("picture.txt");
  CHECK(run("render " + cube + " -o '" + text.string() + "'").exit_code == 2);
  CHECK_FALSE(std::filesystem::exists(text));
  const test::Run good = run("render " + cube + " --size 64x48 --view front -o '" + out.string() + "'");
  REQUIRE(good.exit_code == 0);
  png_image read{};
  read.version = PNG_IMAGE_VERSION;
  REQUIRE(png_image_begin_read_from_file(&read, out.c_str()) != 0);
  CHECK(read.width == 64);
  CHECK(read.height == 48);
  png_image_free(&read);
}
#endif
