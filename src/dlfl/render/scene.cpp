#include <dlfl/render/scene.h>

#include <algorithm>
#include <array>

#include <dlfl/errors.h>

namespace dlfl {

namespace {

void add_polygon(RenderScene& scene, std::span<const std::uint32_t> cycle, Rgba color) {
  scene.indices.insert(scene.indices.end(), cycle.begin(), cycle.end());
  scene.offsets.push_back(static_cast<std::uint32_t>(scene.indices.size()));
  scene.polygon_colors.push_back(color);
}

// Each undirected pair once, as (smaller, larger), in order.
void add_unique_pairs(std::vector<std::uint32_t>& out, std::vector<std::array<std::uint32_t, 2>>& pairs) {
  for (auto& p : pairs) p = {std::min(p[0], p[1]), std::max(p[0], p[1])};
  std::sort(pairs.begin(), pairs.end());
  pairs.erase(std::unique(pairs.begin(), pairs.end()), pairs.end());
  for (const auto& p : pairs) out.insert(out.end(), {p[0], p[1]});
}

}  // namespace

glm::dvec3 polygon_newell(const RenderScene& scene, std::size_t f) {
  glm::dvec3 n(0.0);
  const std::uint32_t begin = scene.offsets[f], end = scene.offsets[f + 1];
  for (std::uint32_t k = begin; k < end; ++k) {
    const glm::dvec3& p = scene.positions[scene.indices[k]];
    const glm::dvec3& q = scene.positions[scene.indices[k + 1 < end ? k + 1 : begin]];
    n += glm::dvec3((p.y - q.y) * (p.z + q.z), (p.z - q.z) * (p.x + q.x), (p.x - q.x) * (p.y + q.y));
  }
  return n;
}

RenderScene mesh_scene(const Mesh& mesh, const ColorBy& color_by) {
  const std::vector<Rgba> colors = face_colors(mesh, color_by);
  RenderScene scene;
  std::vector<std::uint32_t> index(mesh.vertex_capacity());
  scene.positions.reserve(mesh.num_vertices());
  for (VertexId v : mesh.vertices()) {
    index[v.index()] = static_cast<std::uint32_t>(scene.positions.size());
    if (mesh.is_point_sphere(v)) scene.points.push_back(index[v.index()]);
    scene.positions.push_back(mesh.position(v));
  }
  scene.offsets.reserve(mesh.num_surface_faces() + 1);
  scene.indices.reserve(mesh.num_corners());
  scene.polygon_colors.reserve(mesh.num_surface_faces());
  for (FaceId f : mesh.faces()) {
    if (mesh.is_hole(f) || mesh.size(f) < 3) continue;
    for (CornerId c : mesh.corners(f)) scene.indices.push_back(index[mesh.vertex(c).index()]);
    scene.offsets.push_back(static_cast<std::uint32_t>(scene.indices.size()));
    scene.polygon_colors.push_back(colors[f.index()]);
  }
  scene.edges.reserve(2 * mesh.num_edges());
  for (EdgeId e : mesh.edges()) {
    if (mesh.is_hole(mesh.face(e, 0)) && mesh.is_hole(mesh.face(e, 1))) continue;
    scene.edges.insert(scene.edges.end(), {index[mesh.from(e).index()], index[mesh.to(e).index()]});
  }
  scene.closed = mesh.num_hole_faces() == 0;
  return scene;
}

RenderScene cell_scene(const CellComplex& complex, const ColorBy& color_by) {
  if (color_by.mode != ColorBy::Mode::none && color_by.mode != ColorBy::Mode::face_size) {
    throw ParameterError("color_by: a cell complex is coloured by none or face-size only", "color_by");
  }
  check_cell_complex(complex);
  const Rgba color = color_by.mode == ColorBy::Mode::none ? plain_color : face_size_color(4);
  RenderScene scene;
  scene.oriented = false;
  scene.closed = false;
  scene.positions = complex.positions;
  // The faces of a hexahedron in tensor-product order, as cycles turning outward for a positive one.
  static constexpr std::uint32_t hex_faces[6][4] = {{0, 4, 6, 2}, {1, 3, 7, 5}, {0, 1, 5, 4},
                                                    {2, 6, 7, 3}, {0, 2, 3, 1}, {4, 5, 7, 6}};
  struct HexFace {
    std::array<std::uint32_t, 4> key;  // sorted vertex indices
    std::uint32_t cell, face;
  };
  std::vector<HexFace> hex_quads;
  std::vector<std::array<std::uint32_t, 2>> sides;
  auto add_quad = [&](const std::array<std::uint32_t, 4>& cycle) {
    add_polygon(scene, cycle, color);
    for (int i = 0; i < 4; ++i) sides.push_back({cycle[i], cycle[(i + 1) % 4]});
  };
  for (std::size_t i = 0; i < complex.num_cells(); ++i) {
    const auto cell = complex.cell(i);
    switch (cell.size()) {
      case 1:
        scene.points.push_back(cell[0]);
        break;
      case 2:
        scene.curves.insert(scene.curves.end(), {cell[0], cell[1]});
        break;
      case 4:
        add_quad({cell[0], cell[1], cell[3], cell[2]});
        break;
      default:
        for (std::uint32_t k = 0; k < 6; ++k) {
          std::array<std::uint32_t, 4> key;
          for (int j = 0; j < 4; ++j) key[j] = cell[hex_faces[k][j]];
          std::sort(key.begin(), key.end());
          hex_quads.push_back({key, static_cast<std::uint32_t>(i), k});
        }
    }
  }
  std::sort(hex_quads.begin(), hex_quads.end(),
            [](const HexFace& a, const HexFace& b) { return a.key < b.key; });
  for (std::size_t i = 0; i < hex_quads.size();) {
    std::size_t j = i;
    while (j < hex_quads.size() && hex_quads[j].key == hex_quads[i].key) ++j;
    if (j == i + 1) {  // on the boundary: one hexahedron only
      const auto cell = complex.cell(hex_quads[i].cell);
      std::array<std::uint32_t, 4> cycle;
      for (int k = 0; k < 4; ++k) cycle[k] = cell[hex_faces[hex_quads[i].face][k]];
      add_quad(cycle);
    }
    i = j;
  }
  add_unique_pairs(scene.edges, sides);
  return scene;
}

}  // namespace dlfl
