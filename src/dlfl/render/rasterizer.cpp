#include <dlfl/render/rasterizer.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

namespace dlfl {

namespace {

constexpr int samples = 2;  // per pixel along x and y
constexpr int sub = 16;     // fixed-point steps per sample
constexpr int half_sub = sub / 2;
constexpr double polygon_offset = 1.5;  // samples of depth slope that faces are pushed back by

struct Point {
  std::int64_t x, y;
};

// A plane over the sample grid: value at sample (i, j) = at0 + dx * i + dy * j (sample centres).
struct Plane {
  double at0 = 0, dx = 0, dy = 0;
  double at(int i, int j) const { return at0 + dx * i + dy * j; }
};

// The plane through three values at three fixed-point points (area2 = their doubled signed area, not 0).
Plane plane_through(Point a, Point b, Point c, double va, double vb, double vc, double area2) {
  const double x1 = double(b.x - a.x), y1 = double(b.y - a.y), x2 = double(c.x - a.x), y2 = double(c.y - a.y);
  const double d1 = vb - va, d2 = vc - va;
  // Gradient per fixed-point unit, then per sample.
  const double gx = (d1 * y2 - d2 * y1) / area2, gy = (d2 * x1 - d1 * x2) / area2;
  Plane p;
  p.dx = gx * sub;
  p.dy = gy * sub;
  p.at0 = va + gx * (half_sub - double(a.x)) + gy * (half_sub - double(a.y));
  return p;
}

std::int64_t cross(Point a, Point b, Point c) {
  return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
}

// Samples of the triangle (a, b, c) (either orientation; none if degenerate), within [0, w) x [0, h):
// plot(i, j) for each. The fill rule owns an edge's boundary samples on one side only.
template <class Plot>
void raster_triangle(Point a, Point b, Point c, int w, int h, Plot&& plot) {
  std::int64_t area = cross(a, b, c);
  if (area == 0) return;
  if (area < 0) std::swap(b, c), area = -area;
  const std::int64_t min_x = std::min({a.x, b.x, c.x}), max_x = std::max({a.x, b.x, c.x});
  const std::int64_t min_y = std::min({a.y, b.y, c.y}), max_y = std::max({a.y, b.y, c.y});
  // Samples whose centre (sub * i + half_sub) lies in the bounding box (>> is floor division in C++20).
  auto first = [](std::int64_t v) { return -((half_sub - v) >> 4); };
  auto last = [](std::int64_t v) { return (v - half_sub) >> 4; };
  static_assert(sub == 16);
  const int i0 = static_cast<int>(std::max<std::int64_t>(0, first(min_x)));
  const int i1 = static_cast<int>(std::min<std::int64_t>(w - 1, last(max_x)));
  const int j0 = static_cast<int>(std::max<std::int64_t>(0, first(min_y)));
  const int j1 = static_cast<int>(std::min<std::int64_t>(h - 1, last(max_y)));
  if (i0 > i1 || j0 > j1) return;
  // Edge function of (p, q) at s: cross(p, q, s) >= 0 inside; minus 1 where the edge does not own its
  // boundary, so that the two triangles of a shared edge never both take a sample on it.
  struct Edge {
    std::int64_t value, step_x, step_y;
  };
  auto edge = [&](Point p, Point q) {
    const std::int64_t dx = q.x - p.x, dy = q.y - p.y;
    const bool owns = dy < 0 || (dy == 0 && dx > 0);
    const Point s{std::int64_t(i0) * sub + half_sub, std::int64_t(j0) * sub + half_sub};
    return Edge{cross(p, q, s) - (owns ? 0 : 1), -dy * sub, dx * sub};
  };
  Edge e0 = edge(b, c), e1 = edge(c, a), e2 = edge(a, b);
  for (int j = j0; j <= j1; ++j) {
    std::int64_t v0 = e0.value, v1 = e1.value, v2 = e2.value;
    for (int i = i0; i <= i1; ++i) {
      if ((v0 | v1 | v2) >= 0) plot(i, j);
      v0 += e0.step_x, v1 += e1.step_x, v2 += e2.step_x;
    }
    e0.value += e0.step_y, e1.value += e1.step_y, e2.value += e2.step_y;
  }
}

std::uint32_t pack(Rgba c) {
  return std::uint32_t(c.r) | std::uint32_t(c.g) << 8 | std::uint32_t(c.b) << 16 | std::uint32_t(c.a) << 24;
}

class Raster {
 public:
  Raster(const RenderScene& scene, const Camera& camera, const RenderOptions& options)
      : scene_(scene),
        camera_(camera),
        options_(options),
        w_(camera.width * samples),
        h_(camera.height * samples) {
    depth_.assign(std::size_t(w_) * h_, -std::numeric_limits<float>::infinity());
    color_.assign(std::size_t(w_) * h_, pack(options.background));
    project();
  }

  Image run() {
    if (options_.smooth && scene_.oriented) vertex_normals();
    fill_polygons();
    if (options_.draws_edges(scene_)) strokes(scene_.edges, 2.0, edge_color);
    strokes(scene_.curves, 4.0, curve_color);
    dots();
    return resolve();
  }

 private:
  void project() {
    const std::size_t n = scene_.positions.size();
    xy_.resize(n);
    z_.resize(n);
    double low = std::numeric_limits<double>::infinity(), high = -low;
    constexpr double limit = double(1 << 29);  // keeps edge functions far inside 64 bits
    for (std::size_t v = 0; v < n; ++v) {
      const glm::dvec3 p = camera_.project(scene_.positions[v]);
      // Clamped (a NaN too) so that rounding is defined and edge functions stay within 64 bits.
      auto fixed = [&](double c) { return std::llround(c > -limit ? (c < limit ? c : limit) : -limit); };
      xy_[v] = {fixed(p.x * samples * sub), fixed(p.y * samples * sub)};
      z_[v] = p.z;
      if (std::isfinite(p.z)) low = std::min(low, p.z), high = std::max(high, p.z);
    }
    // Strokes pass where they are this close behind the surface, besides the faces' slope offset.
    tolerance_ = high >= low ? 1e-5 * (high - low) + 1e-12 : 0;
  }

  void vertex_normals() {
    normals_.assign(scene_.positions.size(), glm::dvec3(0.0));
    for (std::size_t f = 0; f < scene_.num_polygons(); ++f) {
      const glm::dvec3 n = polygon_newell(scene_, f);
      for (std::uint32_t k = scene_.offsets[f]; k < scene_.offsets[f + 1]; ++k) {
        normals_[scene_.indices[k]] += n;
      }
    }
    for (glm::dvec3& n : normals_) n = camera_.to_view(n);
  }

  void store(int i, int j, double z, std::uint32_t color) {
    const std::size_t at = std::size_t(j) * w_ + i;
    if (z > depth_[at]) {
      depth_[at] = static_cast<float>(z);
      color_[at] = color;
    }
  }

  void fill_polygons() {
    for (std::size_t f = 0; f < scene_.num_polygons(); ++f) {
      const std::uint32_t begin = scene_.offsets[f], end = scene_.offsets[f + 1];
      const std::uint32_t* ids = scene_.indices.data() + begin;
      const std::uint32_t n = end - begin;
      // Twice the signed area in the picture (y down: negative for a face turned to the viewer), and
      // whether every fan triangle turns the same way (then the fan covers the polygon exactly once).
      std::int64_t total = 0;
      bool fan = true;
      int sign = 0;
      for (std::uint32_t k = 1; k + 1 < n; ++k) {
        const std::int64_t a = cross(xy_[ids[0]], xy_[ids[k]], xy_[ids[k + 1]]);
        total += a;
        if (a != 0) {
          const int s = a > 0 ? 1 : -1;
          fan = fan && (sign == 0 || s == sign);
          sign = s;
        }
      }
      if (total == 0) continue;  // seen edge-on
      const bool back = total > 0;
      Rgba base = scene_.polygon_colors[f];
      if (back && scene_.oriented && options_.back_tint) base = back_tinted(base);
      if (!normals_.empty() && fan) {
        smooth_fan(ids, n, base, back);
        continue;
      }
      // Flat: the face's normal; under smooth shading a face the fan cannot fill takes the mean of its
      // vertex normals, which matches its neighbours better than its own normal.
      glm::dvec3 normal(0.0);
      if (normals_.empty()) {
        normal = camera_.to_view(polygon_newell(scene_, f));
      } else {
        for (std::uint32_t k = 0; k < n; ++k) normal += normals_[ids[k]];
      }
      const std::uint32_t color = pack(lit(base, light_intensity(normal)));
      if (fan) {
        for (std::uint32_t k = 1; k + 1 < n; ++k) flat_triangle(ids[0], ids[k], ids[k + 1], color);
      } else {
        even_odd(ids, n, color);
      }
    }
  }

  Plane depth_plane(std::uint32_t a, std::uint32_t b, std::uint32_t c, double area2) const {
    Plane p = plane_through(xy_[a], xy_[b], xy_[c], z_[a], z_[b], z_[c], area2);
    p.at0 -= polygon_offset * (std::fabs(p.dx) + std::fabs(p.dy));
    return p;
  }

  void flat_triangle(std::uint32_t a, std::uint32_t b, std::uint32_t c, std::uint32_t color) {
    const std::int64_t area2 = cross(xy_[a], xy_[b], xy_[c]);
    if (area2 == 0) return;
    const Plane z = depth_plane(a, b, c, double(area2));
    raster_triangle(xy_[a], xy_[b], xy_[c], w_, h_, [&](int i, int j) { store(i, j, z.at(i, j), color); });
  }

  void smooth_fan(const std::uint32_t* ids, std::uint32_t n, Rgba base, bool back) {
    const double turn = back ? -1 : 1;  // the normal of the side that is seen
    for (std::uint32_t k = 1; k + 1 < n; ++k) {
      const std::uint32_t a = ids[0], b = ids[k], c = ids[k + 1];
      const std::int64_t area2 = cross(xy_[a], xy_[b], xy_[c]);
      if (area2 == 0) continue;
      const Plane z = depth_plane(a, b, c, double(area2));
      Plane normal[3];
      for (int d = 0; d < 3; ++d) {
        normal[d] = plane_through(xy_[a], xy_[b], xy_[c], turn * normals_[a][d], turn * normals_[b][d],
                                  turn * normals_[c][d], double(area2));
      }
      raster_triangle(xy_[a], xy_[b], xy_[c], w_, h_, [&](int i, int j) {
        const double depth = z.at(i, j);
        const std::size_t at = std::size_t(j) * w_ + i;
        if (!(depth > depth_[at])) return;
        glm::dvec3 nv(normal[0].at(i, j), normal[1].at(i, j), normal[2].at(i, j));
        if (nv.z < 0) nv.z = 0;  // interpolated past the silhouette: lit as seen edge-on
        depth_[at] = static_cast<float>(depth);
        color_[at] = pack(lit(base, light_intensity(nv)));
      });
    }
  }

  // A polygon that a fan would not cover exactly once: filled row by row by the even-odd rule, its depth
  // from its plane (Newell's normal in sample space).
  void even_odd(const std::uint32_t* ids, std::uint32_t n, std::uint32_t color) {
    glm::dvec3 normal(0.0), mid(0.0);
    std::int64_t min_y = xy_[ids[0]].y, max_y = min_y;
    for (std::uint32_t k = 0; k < n; ++k) {
      const std::uint32_t p = ids[k], q = ids[(k + 1) % n];
      const double px = double(xy_[p].x) / sub, py = double(xy_[p].y) / sub;
      const double qx = double(xy_[q].x) / sub, qy = double(xy_[q].y) / sub;
      normal += glm::dvec3((py - qy) * (z_[p] + z_[q]), (z_[p] - z_[q]) * (px + qx), (px - qx) * (py + qy));
      mid += glm::dvec3(px, py, z_[p]);
      min_y = std::min(min_y, xy_[p].y), max_y = std::max(max_y, xy_[p].y);
    }
    if (normal.z == 0) return;
    mid /= double(n);
    Plane z;
    z.dx = -normal.x / normal.z, z.dy = -normal.y / normal.z;
    z.at0 = mid.z + z.dx * (0.5 - mid.x) + z.dy * (0.5 - mid.y) -
            polygon_offset * (std::fabs(z.dx) + std::fabs(z.dy));
    const int j0 = static_cast<int>(std::max<std::int64_t>(0, (min_y - half_sub) / sub));
    const int j1 = static_cast<int>(std::min<std::int64_t>(h_ - 1, (max_y - half_sub) / sub + 1));
    for (int j = j0; j <= j1; ++j) {
      const std::int64_t yc = std::int64_t(j) * sub + half_sub;
      crossings_.clear();
      for (std::uint32_t k = 0; k < n; ++k) {
        const Point a = xy_[ids[k]], b = xy_[ids[(k + 1) % n]];
        if ((a.y <= yc) == (b.y <= yc)) continue;
        crossings_.push_back(double(a.x) + double(yc - a.y) * double(b.x - a.x) / double(b.y - a.y));
      }
      std::sort(crossings_.begin(), crossings_.end());
      for (std::size_t k = 0; k + 1 < crossings_.size(); k += 2) {
        // Samples whose centre x is in [left, right).
        const int i0 = std::max(0, static_cast<int>(std::ceil((crossings_[k] - half_sub) / sub)));
        const int i1 = std::min(w_, static_cast<int>(std::ceil((crossings_[k + 1] - half_sub) / sub)));
        for (int i = i0; i < i1; ++i) store(i, j, z.at(i, j), color);
      }
    }
  }

  // The samples of a stroke or dot that are no further than the surface there.
  void overlay(int i, int j, double z, std::uint32_t color) {
    const std::size_t at = std::size_t(j) * w_ + i;
    if (z >= depth_[at] - tolerance_) color_[at] = color;
  }

  // Segments as strips `width` samples wide (and as long again at the ends), their depth linear along them.
  void strokes(const std::vector<std::uint32_t>& pairs, double width, Rgba rgba) {
    const std::uint32_t color = pack(rgba);
    for (std::size_t k = 0; k + 1 < pairs.size(); k += 2) {
      const std::uint32_t a = pairs[k], b = pairs[k + 1];
      const double ax = double(xy_[a].x), ay = double(xy_[a].y), bx = double(xy_[b].x), by = double(xy_[b].y);
      const double length = std::hypot(bx - ax, by - ay);
      const double r = 0.5 * width * sub;
      // Along the segment (ux, uy) and across it (-uy, ux), r long; a point segment becomes a square.
      const double ux = length > 0 ? r * (bx - ax) / length : r, uy = length > 0 ? r * (by - ay) / length : 0;
      const Point corners[4] = {{std::llround(ax - ux + uy), std::llround(ay - uy - ux)},
                                {std::llround(bx + ux + uy), std::llround(by + uy - ux)},
                                {std::llround(bx + ux - uy), std::llround(by + uy + ux)},
                                {std::llround(ax - ux - uy), std::llround(ay - uy + ux)}};
      // Depth along the segment: z_a at a, z_b at b, constant across.
      const double dz = length > 0 ? (z_[b] - z_[a]) / (length * length) : 0;
      Plane z;
      z.dx = dz * (bx - ax) * sub, z.dy = dz * (by - ay) * sub;
      z.at0 = z_[a] + dz * ((half_sub - ax) * (bx - ax) + (half_sub - ay) * (by - ay));
      auto plot = [&](int i, int j) {
        overlay(i, j, std::clamp(z.at(i, j), std::min(z_[a], z_[b]), std::max(z_[a], z_[b])), color);
      };
      raster_triangle(corners[0], corners[1], corners[2], w_, h_, plot);
      raster_triangle(corners[0], corners[2], corners[3], w_, h_, plot);
    }
  }

  // Points as discs of radius 3 pixels (octagons).
  void dots() {
    const std::uint32_t color = pack(point_color);
    const double r = 3.0 * samples * sub;
    for (std::uint32_t v : scene_.points) {
      Point ring[8];
      for (int k = 0; k < 8; ++k) {
        const double angle = k * 0.7853981633974483;
        ring[k] = {xy_[v].x + std::llround(r * std::cos(angle)),
                   xy_[v].y + std::llround(r * std::sin(angle))};
      }
      for (int k = 1; k + 1 < 8; ++k) {
        raster_triangle(ring[0], ring[k], ring[k + 1], w_, h_,
                        [&](int i, int j) { overlay(i, j, z_[v], color); });
      }
    }
  }

  // Each pixel the mean of its samples, weighted by their alpha (straight alpha out).
  Image resolve() const {
    Image image(camera_.width, camera_.height);
    for (int y = 0; y < camera_.height; ++y) {
      for (int x = 0; x < camera_.width; ++x) {
        std::uint32_t sum[4] = {0, 0, 0, 0};
        for (int sy = 0; sy < samples; ++sy) {
          for (int sx = 0; sx < samples; ++sx) {
            const std::uint32_t c = color_[std::size_t(y * samples + sy) * w_ + x * samples + sx];
            const std::uint32_t a = c >> 24;
            sum[0] += (c & 255) * a, sum[1] += (c >> 8 & 255) * a, sum[2] += (c >> 16 & 255) * a, sum[3] += a;
          }
        }
        Rgba& out = image.at(x, y);
        if (sum[3] == 0) {
          out = {options_.background.r, options_.background.g, options_.background.b, 0};
          continue;
        }
        out = {std::uint8_t((sum[0] + sum[3] / 2) / sum[3]), std::uint8_t((sum[1] + sum[3] / 2) / sum[3]),
               std::uint8_t((sum[2] + sum[3] / 2) / sum[3]),
               std::uint8_t((sum[3] + samples * samples / 2) / (samples * samples))};
      }
    }
    return image;
  }

  const RenderScene& scene_;
  const Camera& camera_;
  const RenderOptions& options_;
  int w_, h_;
  std::vector<float> depth_;
  std::vector<std::uint32_t> color_;
  std::vector<Point> xy_;            // per position, fixed point
  std::vector<double> z_;            // per position, nearness
  std::vector<glm::dvec3> normals_;  // per position, camera space (smooth shading)
  std::vector<double> crossings_;    // reused by even_odd
  double tolerance_ = 0;
};

}  // namespace

Image render(const RenderScene& scene, const Camera& camera, const RenderOptions& options) {
  return Raster(scene, camera, options).run();
}

}  // namespace dlfl
