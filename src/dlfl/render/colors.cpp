#include <dlfl/render/colors.h>

#include <algorithm>
#include <cmath>
#include <numeric>

#include <dlfl/analysis/concave_edges.h>
#include <dlfl/errors.h>

namespace dlfl {

namespace {

Rgba mix(Rgba a, Rgba b, double t) {
  auto channel = [t](std::uint8_t x, std::uint8_t y) {
    return static_cast<std::uint8_t>(std::lround(x + t * (double(y) - x)));
  };
  return {channel(a.r, b.r), channel(a.g, b.g), channel(a.b, b.b), 255};
}

// Union-find over vertex indices, for the components.
std::uint32_t root(std::vector<std::uint32_t>& parent, std::uint32_t v) {
  while (parent[v] != v) v = parent[v] = parent[parent[v]];
  return v;
}

std::vector<Rgba> component_colors(const Mesh& mesh) {
  std::vector<std::uint32_t> parent(mesh.vertex_capacity());
  std::iota(parent.begin(), parent.end(), 0u);
  for (EdgeId e : mesh.edges()) {
    const std::uint32_t a = root(parent, mesh.from(e).index()), b = root(parent, mesh.to(e).index());
    parent[std::max(a, b)] = std::min(a, b);
  }
  std::vector<Rgba> colors(mesh.face_capacity(), plain_color);
  std::vector<std::uint32_t> rank(mesh.vertex_capacity(), CornerId::invalid_index);
  std::uint32_t next = 0;
  for (FaceId f : mesh.faces()) {
    std::uint32_t& r = rank[root(parent, mesh.vertex(mesh.first_corner(f)).index())];
    if (r == CornerId::invalid_index) r = next++;
    colors[f.index()] = palette_color(r);
  }
  return colors;
}

std::vector<Rgba> hole_colors(const Mesh& mesh) {
  std::vector<Rgba> colors(mesh.face_capacity(), plain_color);
  std::vector<bool> taken(mesh.face_capacity(), false);
  std::size_t rank = 0;
  for (FaceId h : mesh.faces()) {
    if (!mesh.is_hole(h)) continue;
    for (CornerId c : mesh.corners(h)) {
      if (!mesh.edge(c).valid()) continue;
      const FaceId across = mesh.face(mesh.opposite(c));
      if (mesh.is_hole(across) || taken[across.index()]) continue;
      taken[across.index()] = true;
      colors[across.index()] = palette_color(rank);
    }
    ++rank;
  }
  return colors;
}

// Per face, the attribute's value as a number (NaN when it has none): face values directly, vertex values
// averaged over the face's corners.
template <class H, class T>
bool attribute_values(const Mesh& mesh, const std::string& name, std::vector<double>& values) {
  const auto attribute = mesh.find_attribute<H, T>(name);
  if (!attribute) return false;
  for (FaceId f : mesh.faces()) {
    if (mesh.is_hole(f)) continue;
    if constexpr (std::is_same_v<H, FaceId>) {
      values[f.index()] = static_cast<double>((*attribute)[f]);
    } else {
      double sum = 0;
      for (CornerId c : mesh.corners(f)) sum += static_cast<double>((*attribute)[mesh.vertex(c)]);
      values[f.index()] = sum / mesh.size(f);
    }
  }
  return true;
}

template <class H>
bool typed_values(const Mesh& mesh, const std::string& name, std::vector<double>& values) {
  const ElementKind kind = element_kind_v<H>;
  if (!mesh.has_attribute(kind, name)) return false;
  for (const AttributeInfo& info : mesh.attributes()) {
    if (info.kind != kind || info.name != name) continue;
    switch (info.type) {
      case AttributeType::boolean:
        return attribute_values<H, bool>(mesh, name, values);
      case AttributeType::integer:
        return attribute_values<H, int>(mesh, name, values);
      case AttributeType::number:
        return attribute_values<H, double>(mesh, name, values);
      case AttributeType::point:
        break;
    }
    throw ParameterError(
        "color_by: attribute " + name + " holds points; only numbers and booleans colour faces", "color_by");
  }
  return false;
}

std::vector<Rgba> attribute_colors(const Mesh& mesh, const std::string& name) {
  std::vector<double> values(mesh.face_capacity(), std::nan(""));
  if (!typed_values<FaceId>(mesh, name, values) && !typed_values<VertexId>(mesh, name, values)) {
    throw ParameterError("color_by: the mesh has no face or vertex attribute named '" + name + "'",
                         "color_by");
  }
  double low = INFINITY, high = -INFINITY;
  for (double v : values) {
    if (std::isfinite(v)) low = std::min(low, v), high = std::max(high, v);
  }
  std::vector<Rgba> colors(mesh.face_capacity(), plain_color);
  for (FaceId f : mesh.faces()) {
    const double v = values[f.index()];
    colors[f.index()] = ramp_color(high > low ? (v - low) / (high - low) : std::isnan(v) ? v : 0.5);
  }
  return colors;
}

}  // namespace

ColorBy parse_color_by(std::string_view text) {
  if (text == "none") return {ColorBy::Mode::none, {}};
  if (text == "face-size") return {ColorBy::Mode::face_size, {}};
  if (text == "component") return {ColorBy::Mode::component, {}};
  if (text == "hole") return {ColorBy::Mode::hole, {}};
  if (text == "concave") return {ColorBy::Mode::concave, {}};
  if (text.starts_with("attribute=") && text.size() > 10) {
    return {ColorBy::Mode::attribute, std::string(text.substr(10))};
  }
  throw ParameterError(
      "color_by: expected none, face-size, component, hole, concave or attribute=NAME, got '" +
          std::string(text) + "'",
      "color_by");
}

Rgba face_size_color(std::size_t size) {
  static constexpr Rgba by_size[] = {
      {210, 210, 210, 255},  // 0 to 2
      {111, 168, 220, 255},  // 3
      {147, 196, 125, 255},  // 4
      {246, 178, 107, 255},  // 5
      {243, 227, 181, 255},  // 6
      {224, 102, 102, 255},  // 7
      {142, 124, 195, 255},  // 8
      {118, 215, 196, 255},  // 9
      {194, 123, 160, 255},  // 10
      {120, 120, 120, 255},  // 11 and more
  };
  return by_size[std::clamp<std::size_t>(size, 2, 11) - 2];
}

Rgba palette_color(std::size_t index) {
  // HSV with s = 0.45, v = 0.92, the hue stepped by the golden angle so that neighbours in the sequence
  // differ; channel n of HSV is v - v s clamp(min(k, 4 - k), 0, 1) with k = (n + hue / 60) mod 6.
  const double hue = std::fmod(static_cast<double>(index) * 137.50776405, 360.0) / 60.0;
  auto channel = [hue](double n) {
    const double k = std::fmod(n + hue, 6.0);
    const double value = 0.92 - 0.92 * 0.45 * std::clamp(std::min(k, 4 - k), 0.0, 1.0);
    return static_cast<std::uint8_t>(std::lround(255 * value));
  };
  return {channel(5), channel(3), channel(1), 255};
}

Rgba ramp_color(double t) {
  static constexpr Rgba stops[] = {
      {44, 62, 145, 255}, {42, 157, 143, 255}, {233, 196, 106, 255}, {231, 111, 81, 255}};
  if (std::isnan(t)) return {128, 128, 128, 255};
  const double at = std::clamp(t, 0.0, 1.0) * (std::size(stops) - 1);
  const std::size_t i = std::min<std::size_t>(static_cast<std::size_t>(at), std::size(stops) - 2);
  return mix(stops[i], stops[i + 1], at - static_cast<double>(i));
}

std::vector<Rgba> face_colors(const Mesh& mesh, const ColorBy& color_by) {
  switch (color_by.mode) {
    case ColorBy::Mode::component:
      return component_colors(mesh);
    case ColorBy::Mode::hole:
      return hole_colors(mesh);
    case ColorBy::Mode::attribute:
      return attribute_colors(mesh, color_by.attribute);
    case ColorBy::Mode::concave: {
      std::vector<Rgba> colors(mesh.face_capacity(), plain_color);
      std::vector<bool> concave;
      concave_edges(mesh, 1e-9, &concave);
      for (EdgeId e : mesh.edges()) {
        if (!concave[e.index()]) continue;
        colors[mesh.face(e, 0).index()] = colors[mesh.face(e, 1).index()] = concave_color;
      }
      return colors;
    }
    case ColorBy::Mode::face_size: {
      std::vector<Rgba> colors(mesh.face_capacity(), plain_color);
      for (FaceId f : mesh.faces()) colors[f.index()] = face_size_color(mesh.size(f));
      return colors;
    }
    case ColorBy::Mode::none:
      break;
  }
  return std::vector<Rgba>(mesh.face_capacity(), plain_color);
}

}  // namespace dlfl
