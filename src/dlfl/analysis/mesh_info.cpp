#include <dlfl/analysis/mesh_info.h>

#include <nlohmann/json.hpp>

#include <dlfl/analysis/concave_edges.h>
#include <dlfl/analysis/convex_polyhedron.h>
#include <dlfl/analysis/polyhedron_angles.h>
#include <dlfl/mesh_hash.h>
#include <dlfl/statistics.h>
#include <dlfl/validate.h>

namespace dlfl {
namespace {

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

}  // namespace

std::string mesh_info_json(const Mesh& mesh, const MeshInfoOptions& options) {
  nlohmann::ordered_json j = describe(mesh);
  if (options.angles) j["angles"] = describe_angles(mesh);
  if (options.shape && j["holes"] == 0) {
    const ConcaveEdges c = concave_edges(mesh);
    j["concave_edges"] = c.concave;
    j["worst_concave_degrees"] = c.worst_concave_degrees;
  }
  return j.dump(options.indent);
}

}  // namespace dlfl
