// dlfl info MESH: one JSON object describing the mesh.

#include <iostream>
#include <nlohmann/json.hpp>

#include "commands.h"
#include "dlfl/mesh_hash.h"
#include "dlfl/statistics.h"
#include "dlfl/validate.h"
#include "io/mesh_io.h"

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

Action add_info(CLI::App& app) {
  auto* cmd = app.add_subcommand("info", "Print counts, topology, histograms, bounding box and hash as JSON");
  auto path = std::make_shared<std::string>();
  cmd->add_option("MESH", *path, "Mesh file (.obj, .off, .ply)")->required();
  return [path] {
    std::cout << describe(read_mesh(*path)).dump(2) << "\n";
    return ok;
  };
}

}  // namespace dlfl::tool
