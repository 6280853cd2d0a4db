// multi_connect: the hub is planned on its own mesh (the hull of the scaled vertices), copied in through the
// transaction, and joined to each face by connect_faces.

#include <dlfl/operations/multi_connect.h>

#include <cmath>
#include <limits>
#include <string>

#include <dlfl/build_mesh.h>
#include <dlfl/format.h>
#include <dlfl/operations/connect_faces.h>
#include <dlfl/operations/detail/convex_hull_3d.h>
#include <dlfl/operations/detail/extrusion_faces.h>
#include <dlfl/operations/detail/mesh_copy.h>
#include <dlfl/operations/detail/operation_table.h>
#include <dlfl/operations/detail/refusal.h>

namespace dlfl {
namespace {

constexpr std::string_view op_name = "multi_connect";
constexpr std::uint32_t none = std::numeric_limits<std::uint32_t>::max();

// The hub as it will be added, and where each selected face's copy is in it.
struct HubPlan {
  Mesh hub;
  std::vector<CornerId> copy_corner;  // per face: the corner of its copy at the copy of its first vertex
};

// The hub's points: per selected face, its corners' indices into `vertices` (first seen first).
struct HubPoints {
  std::vector<VertexId> vertices;
  std::vector<std::vector<std::uint32_t>> faces;
};

HubPoints hub_points(const Mesh& m, std::span<const FaceId> faces) {
  HubPoints out;
  std::vector<std::uint32_t> index(m.vertex_capacity(), none), seen_in(m.vertex_capacity(), none);
  for (std::uint32_t k = 0; k < faces.size(); ++k) {
    std::vector<std::uint32_t>& face = out.faces.emplace_back();
    for (CornerId c : m.corners(faces[k])) {
      const VertexId v = m.vertex(c);
      if (seen_in[v.index()] == k) {
        detail::refuse(
            op_name, "faces",
            to_string(faces[k]) + " passes " + to_string(v) + " twice: its copy cannot be a face of the hub");
      }
      seen_in[v.index()] = k;
      if (index[v.index()] == none) {
        index[v.index()] = static_cast<std::uint32_t>(out.vertices.size());
        out.vertices.push_back(v);
      }
      face.push_back(index[v.index()]);
    }
  }
  return out;
}

// The corner of `hull` at the vertex cycle[0] whose face runs through `cycle` (forward, or backward from its
// first element); invalid if there is none.
CornerId find_copy(const Mesh& hull, const std::vector<std::uint32_t>& cycle, bool backward) {
  const std::size_t n = cycle.size();
  for (CornerId c : hull.corners(VertexId(cycle[0]))) {
    if (hull.size(hull.face(c)) != n) continue;
    bool same = true;
    CornerId d = c;
    for (std::size_t i = 0; i < n && same; ++i, d = hull.next(d)) {
      same = hull.vertex(d).index() == cycle[backward ? (n - i) % n : i];
    }
    if (same) return c;
  }
  return CornerId();
}

HubPlan plan_hub(const Mesh& m, std::span<const FaceId> faces, const MultiConnectOptions& o) {
  detail::check_surface_faces(op_name, m, faces, "faces");
  if (faces.size() < 3) {
    detail::refuse(op_name, "faces",
                   "joins at least 3 faces through a hub, not " + detail::count_of(faces.size(), "face") +
                       " (connect_faces joins two)");
  }
  if (!std::isfinite(o.scale) || !(o.scale > 0.0) || !(o.scale < 1.0)) {
    detail::refuse(op_name, "scale", "must be in (0, 1), not " + format_number(o.scale));
  }
  const HubPoints points = hub_points(m, faces);
  glm::dvec3 centroid(0.0);
  for (VertexId v : points.vertices) centroid += m.position(v) / double(points.vertices.size());
  std::vector<glm::dvec3> scaled;
  for (VertexId v : points.vertices) scaled.push_back(centroid + o.scale * (m.position(v) - centroid));
  detail::HullOutcome hull = detail::hull_of_points(
      scaled, [&](std::uint32_t i) { return "the copy of " + to_string(points.vertices[i]); });
  const std::string hub = "the hub (the convex hull of the faces' vertices scaled by " +
                          format_number(o.scale) + " toward their centroid)";
  if (!hull.refusal.empty()) detail::refuse(op_name, "faces", hub + " would be degenerate: " + hull.refusal);
  // Its vertices are the points in order, each a corner (source is increasing): hull vertex i is point i.
  for (std::uint32_t i = 0; i < scaled.size(); ++i) {
    if (i >= hull.hull.source.size() || hull.hull.source[i] != i) {
      detail::refuse(op_name, "faces",
                     to_string(points.vertices[i]) + " would not be a corner of " + hub +
                         ": it is inside, or on a face or an edge of, the hull of the faces' vertices");
    }
  }
  // Each face's copy, running as the face (the face faces away from the hub) or against it.
  const Mesh& h = hull.hull.mesh;
  FaceId away, toward;  // the first face that faces away from the hub, and toward it
  for (std::size_t k = 0; k < faces.size(); ++k) {
    if (find_copy(h, points.faces[k], false).valid()) {
      if (!away.valid()) away = faces[k];
    } else if (find_copy(h, points.faces[k], true).valid()) {
      if (!toward.valid()) toward = faces[k];
    } else {
      detail::refuse(op_name, "faces",
                     to_string(faces[k]) + " has no copy among the faces of " + hub +
                         ": it is not a planar, strictly convex face on the hull of the faces' vertices, or "
                         "lies in one plane with vertices of another face");
    }
  }
  if (away.valid() && toward.valid()) {
    detail::refuse(op_name, "faces",
                   to_string(away) + " faces away from the hub and " + to_string(toward) +
                       " toward it: the tubes would cross their faces");
  }
  HubPlan plan;
  if (away.valid()) {
    // Turned inside out, so that each copy runs against its face, as a tube from it needs.
    PolygonSoup soup = to_polygons(h);
    PolygonSoup reversed;
    reversed.positions = soup.positions;
    for (std::size_t f = 0; f < soup.num_faces(); ++f) {
      std::vector<std::uint32_t> face(soup.face(f).rbegin(), soup.face(f).rend());
      reversed.add_face(face);
    }
    plan.hub = build_mesh(reversed);
  } else {
    plan.hub = std::move(hull.hull.mesh);
  }
  for (std::size_t k = 0; k < faces.size(); ++k)
    plan.copy_corner.push_back(find_copy(plan.hub, points.faces[k], true));
  return plan;
}

}  // namespace

MultiConnectResult multi_connect(Transaction& tx, std::span<const FaceId> faces,
                                 const MultiConnectOptions& options) {
  const HubPlan plan = plan_hub(tx.mesh(), faces, options);
  const Mesh& m = tx.mesh();
  const detail::MeshCopy copy = detail::add_mesh_copy(tx, plan.hub);
  MultiConnectResult result;
  for (VertexId v : plan.hub.vertices()) result.hub_vertices.push_back(copy.vertices[v.index()]);
  // A tube changes only its two faces: the other faces and copies stay as they are for the tubes after it.
  for (std::size_t k = 0; k < faces.size(); ++k) {
    ConnectFacesOptions o;
    o.corner1 = m.first_corner(faces[k]);
    o.corner2 = copy.corner(m, plan.hub, plan.copy_corner[k]);
    const ConnectFacesResult tube = connect_faces(tx, faces[k], m.face(o.corner2), o);
    result.tube_faces.insert(result.tube_faces.end(), tube.faces.begin(), tube.faces.end());
  }
  return result;
}

void check_multi_connect(const Mesh& mesh, std::span<const FaceId> faces,
                         const MultiConnectOptions& options) {
  plan_hub(mesh, faces, options);
}

std::vector<OperationSpec> detail::multi_connect_operation_specs() {
  return {edit_operation(
      "multi_connect",
      "joins k faces through one hub, their scaled convex hull (TopMod's multi-face handle): k - 1 handles",
      {param("faces", ParamType::faces, "the faces to join (at least 3)"),
       param("method", ParamType::text, "hull", "how the hub is made: hull (the only method)")
           .one_of({"hull"}),
       param("scale", ParamType::number, 0.5,
             "the hub's size: its points at this fraction of the way from "
             "the vertices' centroid to the vertices")
           .in_open(0, 1)},
      "V+V_h, E+E_h+sum n, F+F_h+sum n-2k (the hub: V_h vertices, F_h faces, E_h = V_h+F_h-2)",
      [](Transaction& tx, const Params& p) {
        const MultiConnectResult r = multi_connect(tx, p.handles<FaceId>("faces"), {p.number("scale")});
        return Params{{"vertices", r.hub_vertices}, {"faces", r.tube_faces}};
      },
      [](const Mesh& mesh, Params& p) {
        check_multi_connect(mesh, p.handles<FaceId>("faces"), {p.number("scale")});
      })};
}

}  // namespace dlfl
