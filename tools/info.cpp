// dlfl info MESH: one JSON object describing the mesh.

#include <glm/common.hpp>
#include <iostream>
#include <nlohmann/json.hpp>

#include <dlfl/analysis/convex_polyhedron.h>
#include <dlfl/analysis/polyhedron_angles.h>
#include <dlfl/cells/cell_io.h>
#include <dlfl/errors.h>
#include <dlfl/io/mesh_io.h>
#include <dlfl/mesh_hash.h>
#include <dlfl/statistics.h>
#include <dlfl/validate.h>
#include "commands.h"

namespace dlfl::tool {

nlohmann::ordered_json describe(const Mesh& mesh) {
  const MeshStatistics stats = statistics(mesh);
  const ValidationReport report = validate(mesh);
  // Counts of the open surface, as files hold it (holes left out; see MeshStatistics).
  nlohmann::ordered_json j;
  j["vertices"] = stats.vertices;
  j["edges"] = stats.edges;
  j["faces"] = stats.faces;
  j["corners"] = stats.corners;
  j["holes"] = stats.holes;
  j["point_spheres"] = stats.point_spheres;
  j["components"] = report.components.size();
  // Of the surface as the user sees it, holes open: V - E + F with F the polygons.
  j["euler_characteristic"] = long(stats.vertices) - long(stats.edges) + long(stats.faces);
  auto genus = nlohmann::ordered_json::array();
  for (const auto& c : report.components) genus.push_back(c.genus);
  j["genus"] = genus;
  j["valid"] = report.valid();
  auto histogram = [](const std::map<std::uint32_t, std::size_t>& h) {
    nlohmann::ordered_json o = nlohmann::ordered_json::object();
    for (auto [k, n] : h) o[std::to_string(k)] = n;
    return o;
  };
  j["face_sizes"] = histogram(stats.face_sizes);
  j["valences"] = histogram(stats.valences);
  j["bbox"] = {{stats.bbox_min.x, stats.bbox_min.y, stats.bbox_min.z},
               {stats.bbox_max.x, stats.bbox_max.y, stats.bbox_max.z}};
  j["hash"] = mesh_hash(mesh);
  return j;
}

// The angle measurements of Meng and Prautzsch (definition 2.3), in degrees, and the convexity check around
// the vertex centroid.
nlohmann::ordered_json describe_angles(const Mesh& mesh) {
  constexpr double degrees = 180.0 / 3.14159265358979323846;
  const PolyhedronAngles a = polyhedron_angles(mesh);
  auto summary = [](const AngleSummary& s) {
    return nlohmann::ordered_json{{"max", s.max * degrees}, {"mean", s.mean * degrees}};
  };
  nlohmann::ordered_json j;
  j["unit"] = "degree";
  j["edge"] = summary(a.edge);
  j["vertex"] = summary(a.vertex);
  j["face"] = summary(a.face);
  const auto violation = convexity_violation(mesh, vertex_centroid(mesh));
  j["convex"] = !violation.has_value();
  if (violation) j["not_convex_because"] = violation->message;
  return j;
}

// A cell complex: vertices, cells per dimension and bounding box.
nlohmann::ordered_json describe_cells(const CellComplex& complex) {
  std::size_t per_dimension[4] = {0, 0, 0, 0};
  for (std::size_t i = 0; i < complex.num_cells(); ++i) ++per_dimension[complex.dimension(i)];
  glm::dvec3 lo(0.0), hi(0.0);
  for (std::size_t v = 0; v < complex.positions.size(); ++v) {
    lo = v == 0 ? complex.positions[v] : glm::min(lo, complex.positions[v]);
    hi = v == 0 ? complex.positions[v] : glm::max(hi, complex.positions[v]);
  }
  nlohmann::ordered_json j;
  j["vertices"] = complex.positions.size();
  j["cells"] = complex.num_cells();
  j["cells_by_dimension"] = {
      {"0", per_dimension[0]}, {"1", per_dimension[1]}, {"2", per_dimension[2]}, {"3", per_dimension[3]}};
  j["bbox"] = {{lo.x, lo.y, lo.z}, {hi.x, hi.y, hi.z}};
  return j;
}

Action add_info(CLI::App& app) {
  auto* cmd = app.add_subcommand("info", "Print counts, topology, histograms, bounding box and hash as JSON");
  struct Args {
    std::string path;
    bool angles = false;
  };
  auto a = std::make_shared<Args>();
  cmd->add_option("MESH", a->path,
                  "Mesh file (.obj, .off, .ply, .json), or cell complex (.vtk, .obj with p or l lines)")
      ->required();
  cmd->add_flag(
      "--angles", a->angles,
      "Add \"angles\": max and mean edge, vertex and face angles (degrees, Meng-Prautzsch definition "
      "2.3) and whether the mesh is a strictly convex polyhedron around its vertex centroid");
  return [a] {
    if (is_cell_complex_file(a->path)) {
      if (a->angles) throw InvalidArgument("--angles measures polyhedra; " + a->path + " is a cell complex");
      std::cout << describe_cells(read_cell_complex(a->path)).dump(2) << "\n";
      return ok;
    }
    const Mesh mesh = read_mesh(a->path);
    nlohmann::ordered_json j = describe(mesh);
    if (a->angles) j["angles"] = describe_angles(mesh);
    std::cout << j.dump(2) << "\n";
    return ok;
  };
}

}  // namespace dlfl::tool
