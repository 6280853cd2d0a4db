// menger: the skeleton (detail/shell_copy.h's mirrored copy), the cells from the shared cuts of
// detail/fractal_cuts.h, then one tunnel (connect_faces) from each centre face to its twin.

#include <dlfl/operations/menger.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <glm/geometric.hpp>
#include <iterator>
#include <limits>
#include <span>
#include <vector>

#include <dlfl/format.h>
#include <dlfl/geometry.h>
#include <dlfl/operations/connect_faces.h>
#include <dlfl/operations/detail/fractal_cuts.h>
#include <dlfl/operations/detail/operation_table.h>
#include <dlfl/operations/detail/refusal.h>
#include <dlfl/operations/detail/shell_copy.h>

namespace dlfl {
namespace {

constexpr std::string_view op_name = "menger";

// Everything menger builds, decided on the unchanged mesh.
struct Plan {
  // The cuts at (1 - scale) / 2 from each end of each edge.
  detail::EdgeCuts cuts;
  // The faces with edges, and where each one's corners start in `corners`.
  std::vector<FaceId> faces;
  std::vector<std::size_t> face_start;
  std::vector<CornerId> corners;
  // Per corner index: its corner of the centre face.
  std::vector<glm::dvec3> centre;
  // Per vertex index: its copy in the skeleton.
  std::vector<glm::dvec3> skeleton;
};

double mean_edge_length(const Mesh& m, FaceId f) {
  double sum = 0.0;
  for (CornerId c : m.corners(f))
    sum += glm::length(m.position(m.vertex(m.next(c))) - m.position(m.vertex(c)));
  return sum / double(m.size(f));
}

Plan planned(const Mesh& m, const MengerOptions& o) {
  detail::require_share(
      op_name, "scale", o.scale, 1.0,
      "it is the centre face's share of each face, and the two cuts of an edge must not meet");
  if (!std::isfinite(o.depth) || !(o.depth > 0.0)) {
    detail::refuse_worded(op_name, "depth", " = " + format_number(o.depth) + " must be finite and > 0");
  }
  detail::refuse_dangling_edges(m, op_name, "scale");
  Plan plan;
  std::vector<glm::dvec3> cells;
  plan.cuts = detail::plan_edge_cuts(m, (1.0 - o.scale) / 2.0, cells);
  // The skeleton: per vertex, the sums of the tunnels' straight ends over its corners in surface faces, and
  // over all its corners (for a vertex with hole faces only).
  plan.centre.resize(m.corner_capacity());
  std::vector<glm::dvec3> surface_sum(m.vertex_capacity(), glm::dvec3(0.0)), any_sum = surface_sum;
  std::vector<int> surface_count(m.vertex_capacity(), 0), any_count = surface_count;
  for (FaceId f : m.faces()) {
    if (!m.edge(m.first_corner(f)).valid()) continue;
    plan.faces.push_back(f);
    plan.face_start.push_back(plan.corners.size());
    const glm::dvec3 centroid = face_centroid(m, f);
    const glm::dvec3 down = o.depth * mean_edge_length(m, f) * face_normal(m, f);
    for (CornerId c : m.corners(f)) {
      plan.corners.push_back(c);
      const glm::dvec3 w = centroid + o.scale * (m.position(m.vertex(c)) - centroid);
      plan.centre[c.index()] = w;
      cells.push_back(w);
      const std::uint32_t v = m.vertex(c).index();
      any_sum[v] += w - down;
      ++any_count[v];
      if (!m.is_hole(f)) {
        surface_sum[v] += w - down;
        ++surface_count[v];
      }
    }
  }
  plan.face_start.push_back(plan.corners.size());
  plan.skeleton.assign(m.vertex_capacity(), glm::dvec3(0.0));
  for (VertexId v : m.vertices()) {
    const std::uint32_t i = v.index();
    if (surface_count[i] > 0) plan.skeleton[i] = surface_sum[i] / double(surface_count[i]);
    if (surface_count[i] == 0 && any_count[i] > 0) plan.skeleton[i] = any_sum[i] / double(any_count[i]);
  }
  detail::require_finite_positions(op_name, "scale", cells, "cells' corners");
  detail::require_finite_positions(op_name, "depth", plan.skeleton, "skeleton's vertices");
  return plan;
}

// Cuts the cells of one face, given as its old corners c_i (at v_i), once every edge is cut in three (a_i
// after v_i, b_i before v_{i+1}). `at_w` is room for the corners at the centre's vertices. Returns the
// centre face's corner at w_0.
CornerId cut_cells(Transaction& tx, const Plan& plan, std::span<const CornerId> corners,
                   std::vector<CornerId>& at_w) {
  const Mesh& m = tx.mesh();
  const std::size_t n = corners.size();
  // At each corner: the cap (b_{i-1}, v_i, a_i), then its cut edge's new vertex w_i: the corner cell
  // (b_{i-1}, v_i, a_i, w_i). The edge's side 1 then starts at w_i in the rest, which runs ..., w_i, a_i,
  // b_i, w_{i+1}, ...
  at_w.assign(n, CornerId());
  for (std::size_t i = 0; i < n; ++i) {
    const EdgeId cut = detail::cut_corner(tx, corners[i]);
    tx.subdivide_edge(cut, plan.centre[corners[i].index()]);
    at_w[i] = m.corner(cut, 1);
  }
  // From w_{i+1} to w_i cuts off the edge cell (w_i, a_i, b_i, w_{i+1}); w_{i+1}'s corner stays in the rest,
  // w_i's becomes the new edge's side 1. What is left is the centre, w_0 ... w_{n-1}, and at_w[i] its
  // corners (the last split keeps at_w[0], updated by the first).
  for (std::size_t i = 0; i < n; ++i) at_w[i] = m.corner(tx.insert_edge(at_w[(i + 1) % n], at_w[i]).edge, 1);
  return at_w[0];
}

}  // namespace

std::vector<VertexId> menger(Transaction& tx, const MengerOptions& options) {
  const Mesh& m = tx.mesh();
  const Plan plan = planned(m, options);
  const std::size_t faces = plan.faces.size();
  std::vector<bool> hole(faces);
  std::vector<CornerId> twins(faces);
  for (std::size_t i = 0; i < faces; ++i) hole[i] = m.is_hole(plan.faces[i]);
  const detail::MirroredCopy copy = detail::add_mirrored_copy(tx, plan.skeleton, false);
  // The twins, found while the old faces are as they were (a twin lies on the copy, which nothing else
  // touches until its tunnel).
  for (std::size_t i = 0; i < faces; ++i) twins[i] = copy.twin(m, plan.corners[plan.face_start[i]]);
  detail::cut_edges(tx, plan.cuts);
  std::vector<CornerId> at_w;
  for (std::size_t i = 0; i < faces; ++i) {
    const std::span<const CornerId> corners(plan.corners.data() + plan.face_start[i],
                                            plan.face_start[i + 1] - plan.face_start[i]);
    ConnectFacesOptions tunnel;
    tunnel.corner1 = cut_cells(tx, plan, corners, at_w);
    tunnel.corner2 = twins[i];
    const ConnectFacesResult r = connect_faces(tx, m.face(tunnel.corner1), m.face(tunnel.corner2), tunnel);
    if (hole[i]) {
      for (FaceId f : r.faces) tx.set_hole(f, true);
    }
  }
  std::vector<VertexId> skeleton;
  std::copy_if(copy.vertices.begin(), copy.vertices.end(), std::back_inserter(skeleton),
               [](VertexId v) { return v.valid(); });
  return skeleton;
}

void check_menger(const Mesh& mesh, const MengerOptions& options) { planned(mesh, options); }

std::vector<OperationSpec> detail::menger_operation_specs() {
  return {edit_operation(
      "menger",
      "a Menger-sponge cut of every face: a frame of cells, a tunnel from each to a skeleton inside",
      {param("scale", ParamType::number, 1.0 / 3.0, "the centre face's size, as a share of its face's")
           .in_open(0.0, 1.0),
       param("depth", ParamType::number, 1.0 / 3.0,
             "how deep the tunnels go, in mean edge lengths of their faces")
           .range(0.0, std::numeric_limits<double>::infinity(), true, false)},
      "V'=2V+4E, E'=12E, F'=6E (Euler characteristic 2V-2E)",
      [](Transaction& tx, const Params& p) {
        return Params{{"vertices", menger(tx, {p.number("scale"), p.number("depth")})}};
      },
      [](const Mesh& mesh, Params& p) {
        planned(mesh, {p.number("scale"), p.number("depth")});
      })};
}
}  // namespace dlfl
