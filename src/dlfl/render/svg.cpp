#include <dlfl/render/svg.h>

#include <algorithm>
#include <cstdio>
#include <ostream>
#include <vector>

#include <dlfl/io/atomic_file.h>

namespace dlfl {

namespace {

struct Item {
  double depth;         // nearness of the centroid
  std::uint32_t index;  // polygon, curve or point
  std::uint8_t kind;    // 0 polygon, 1 curve, 2 point
};

void write_number(std::ostream& out, double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%.2f", v);
  out << text;
}

}  // namespace

void write_svg(const RenderScene& scene, const Camera& camera, const RenderOptions& options,
               std::ostream& out) {
  std::vector<glm::dvec3> at(scene.positions.size());
  for (std::size_t v = 0; v < at.size(); ++v) at[v] = camera.project(scene.positions[v]);
  std::vector<Item> items;
  items.reserve(scene.num_polygons() + scene.curves.size() / 2 + scene.points.size());
  std::vector<glm::dvec3> normals(scene.num_polygons());
  for (std::size_t f = 0; f < scene.num_polygons(); ++f) {
    normals[f] = camera.to_view(polygon_newell(scene, f));
    // The area seen, relative to the face's own: below 1e-9 it is edge-on.
    const double length =
        std::sqrt(normals[f].x * normals[f].x + normals[f].y * normals[f].y + normals[f].z * normals[f].z);
    if (!(std::fabs(normals[f].z) > 1e-9 * length)) continue;
    if (normals[f].z < 0 && scene.closed && scene.oriented) continue;
    double depth = 0;
    for (std::uint32_t k = scene.offsets[f]; k < scene.offsets[f + 1]; ++k) {
      depth += at[scene.indices[k]].z;
    }
    items.push_back({depth / (scene.offsets[f + 1] - scene.offsets[f]), std::uint32_t(f), 0});
  }
  for (std::size_t k = 0; k + 1 < scene.curves.size(); k += 2) {
    items.push_back({0.5 * (at[scene.curves[k]].z + at[scene.curves[k + 1]].z), std::uint32_t(k), 1});
  }
  for (std::size_t k = 0; k < scene.points.size(); ++k) {
    items.push_back({at[scene.points[k]].z, std::uint32_t(k), 2});
  }
  std::stable_sort(items.begin(), items.end(),
                   [](const Item& a, const Item& b) { return a.depth < b.depth; });

  char hex[8];
  out << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n<svg xmlns=\"http://www.w3.org/2000/svg\" "
         "version=\"1.1\" "
         "width=\""
      << camera.width << "\" height=\"" << camera.height << "\" viewBox=\"0 0 " << camera.width << ' '
      << camera.height << "\">\n";
  if (options.background.a > 0) {
    out << "<rect width=\"100%\" height=\"100%\" fill=\"" << hex_text(options.background, hex) << "\"/>\n";
  }
  const bool edges = options.draws_edges(scene);
  out << "<g stroke-linejoin=\"round\" stroke-linecap=\"round\"";
  if (edges) out << " stroke=\"" << hex_text(edge_color, hex) << "\" stroke-width=\"0.6\"";
  out << ">\n";
  for (const Item& item : items) {
    if (item.kind == 0) {
      const std::size_t f = item.index;
      Rgba base = scene.polygon_colors[f];
      if (normals[f].z < 0 && scene.oriented && options.back_tint) base = back_tinted(base);
      out << "<polygon points=\"";
      for (std::uint32_t k = scene.offsets[f]; k < scene.offsets[f + 1]; ++k) {
        const glm::dvec3& p = at[scene.indices[k]];
        if (k > scene.offsets[f]) out << ' ';
        write_number(out, p.x);
        out << ',';
        write_number(out, p.y);
      }
      out << "\" fill=\"" << hex_text(lit(base, light_intensity(normals[f])), hex) << "\"/>\n";
    } else if (item.kind == 1) {
      const glm::dvec3 &a = at[scene.curves[item.index]], &b = at[scene.curves[item.index + 1]];
      out << "<line x1=\"";
      write_number(out, a.x);
      out << "\" y1=\"";
      write_number(out, a.y);
      out << "\" x2=\"";
      write_number(out, b.x);
      out << "\" y2=\"";
      write_number(out, b.y);
      out << "\" stroke=\"" << hex_text(curve_color, hex) << "\" stroke-width=\"2\"/>\n";
    } else {
      const glm::dvec3& p = at[scene.points[item.index]];
      out << "<circle cx=\"";
      write_number(out, p.x);
      out << "\" cy=\"";
      write_number(out, p.y);
      out << "\" r=\"3\" stroke=\"none\" fill=\"" << hex_text(point_color, hex) << "\"/>\n";
    }
  }
  out << "</g>\n</svg>\n";
}

void write_svg(const RenderScene& scene, const Camera& camera, const RenderOptions& options,
               const std::filesystem::path& path, FileBatch* batch) {
  auto write = [&](std::ostream& out) { write_svg(scene, camera, options, out); };
  if (batch) {
    batch->stage(path, write);
  } else {
    write_atomically(path, write);
  }
}

}  // namespace dlfl
