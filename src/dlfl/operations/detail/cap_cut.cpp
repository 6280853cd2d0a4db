// The cap cut of truncate_vertex, chamfer_edge and cut_face. Planned on the unchanged mesh, so that every
// refusal comes before the first change; then three passes of Euler operators (cut, section, delete), each
// of which leaves the corners the next pass uses where the plan found them.

#include <dlfl/operations/detail/cap_cut.h>

#include <algorithm>
#include <cmath>
#include <unordered_map>
#include <unordered_set>

#include <dlfl/errors.h>
#include <dlfl/format.h>
#include <dlfl/operations/detail/handle_selection.h>
#include <dlfl/operations/detail/refusal.h>

namespace dlfl::detail {
namespace {

bool finite(const glm::dvec3& p) { return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z); }

// A point to put on an edge leaving the cap: on edge(corner), which leaves the cap vertex vertex(corner).
struct PlannedCut {
  CornerId corner;
  glm::dvec3 position;
};

// A run of the cap along one face: from `entry` (whose previous edge leaves the cap) along inner edges to
// `exit` (whose edge leaves the cap). Its section edge joins the cut points before entry and after exit.
struct PlannedRun {
  CornerId entry;
  CornerId exit;
};

struct PlannedCap {
  std::vector<PlannedCut> cuts;
  std::vector<PlannedRun> runs;
  bool hole = false;
};

struct Plan {
  std::vector<PlannedCap> caps;
  CapCounts counts;
};

Plan plan_caps(const Mesh& m, std::string_view op, std::string_view parameter, std::span<const Cap> caps,
               double offset) {
  if (!std::isfinite(offset) || !(offset > 0.0 && offset < 0.5)) {
    refuse_worded(op, "offset",
                  " = " + format_number(offset) +
                      " is outside (0, 0.5): it is a share of each edge's length, and two cuts on one edge "
                      "must not meet");
  }
  if (caps.empty()) refuse_empty(op, parameter);
  // Which cap each vertex belongs to; a vertex in two caps would be cut twice.
  std::unordered_map<std::uint32_t, std::size_t> cap_of;
  std::unordered_map<std::string_view, std::size_t> label_seen;
  for (std::size_t i = 0; i < caps.size(); ++i) {
    if (!label_seen.emplace(caps[i].label, i).second)
      refuse(op, parameter, caps[i].label + " is listed twice");
    for (VertexId v : caps[i].vertices) {
      const auto [at, fresh] = cap_of.emplace(v.index(), i);
      if (!fresh && at->second != i) {
        refuse(op, parameter,
               caps[at->second].label + " and " + caps[i].label + " share " + to_string(v) +
                   ": their cuts would meet");
      }
    }
  }
  Plan plan;
  plan.caps.resize(caps.size());
  for (std::size_t i = 0; i < caps.size(); ++i) {
    const Cap& cap = caps[i];
    PlannedCap& out = plan.caps[i];
    const std::unordered_set<std::uint32_t> inner = [&] {
      std::unordered_set<std::uint32_t> s;
      for (EdgeId e : cap.inner_edges) s.insert(e.index());
      return s;
    }();
    const auto is_inner = [&](CornerId c) { return inner.count(m.edge(c).index()) != 0; };
    for (VertexId v : cap.vertices) {
      for (CornerId c : m.corners(v)) {
        out.hole = out.hole || m.is_hole(m.face(c));
        if (!m.edge(c).valid() || is_inner(c)) continue;
        const VertexId w = m.vertex(m.next(c));
        const auto other = cap_of.find(w.index());
        if (other != cap_of.end() && other->second == i) {
          refuse(op, parameter,
                 to_string(m.edge(c)) + " leaves " + cap.label + " and comes back to it (" + to_string(v) +
                     " to " + to_string(w) + "), so the cut would meet itself");
        }
        const glm::dvec3 p = m.position(v) + offset * (m.position(w) - m.position(v));
        if (!finite(p))
          refuse(op, parameter, "the cut point on " + to_string(m.edge(c)) + " would not be finite");
        out.cuts.push_back({c, p});
      }
    }
    if (out.cuts.size() < 2) {
      refuse(op, parameter,
             cap.label + " has " + count_of(out.cuts.size(), "edge") +
                 " leaving it; a cut needs at least 2 (the new face needs two sides)");
    }
    for (VertexId v : cap.vertices) {
      for (CornerId c : m.corners(v)) {
        if (is_inner(m.prev(c))) continue;
        CornerId exit = c;
        while (is_inner(exit)) exit = m.next(exit);
        if (m.edge(exit) == m.edge(m.prev(c))) {
          refuse(op, parameter,
                 "the cut of " + cap.label + " in " + to_string(m.face(c)) + " would join the cut point on " +
                     to_string(m.edge(exit)) + " to itself");
        }
        out.runs.push_back({c, exit});
      }
    }
    const long mcount = static_cast<long>(out.cuts.size());
    plan.counts.vertices += mcount - static_cast<long>(cap.vertices.size());
    plan.counts.edges += mcount - static_cast<long>(cap.inner_edges.size());
    plan.counts.faces += 1 - cap.inner_faces;
  }
  return plan;
}

}  // namespace

CapCounts check_caps(const Mesh& mesh, std::string_view op, std::string_view parameter,
                     std::span<const Cap> caps, double offset) {
  return plan_caps(mesh, op, parameter, caps, offset).counts;
}

CutResult cut_caps(Transaction& tx, std::string_view op, std::string_view parameter,
                   std::span<const Cap> caps, double offset) {
  const Plan plan = plan_caps(tx.mesh(), op, parameter, caps, offset);
  const Mesh& m = tx.mesh();
  CutResult result;
  // 1. A point on every edge leaving a cap. edge(corner) is always the piece next to the cap vertex, also
  // when the far end was cut first.
  for (const PlannedCap& cap : plan.caps) {
    for (const PlannedCut& cut : cap.cuts)
      result.vertices.push_back(tx.subdivide_edge(m.edge(cut.corner), cut.position));
  }
  // 2. The section edges. Each splits off the piece (cut point, run, cut point) and adds corners only before
  // cut points that no other run uses, so every planned corner stays where it was.
  std::vector<EdgeId> first_section(plan.caps.size());
  for (std::size_t i = 0; i < plan.caps.size(); ++i) {
    for (const PlannedRun& run : plan.caps[i].runs) {
      const CornerId after = m.next(run.exit), before = m.prev(run.entry);
      if (m.face(after) != m.face(before))
        throw TopologyError(std::string(op) + ": a section edge would join two faces");
      const EdgeId section = tx.insert_edge(after, before).edge;
      if (!first_section[i].valid()) first_section[i] = section;
    }
  }
  // 3. The cap: every edge at its vertices (stubs and inner edges), then the vertices, left as point spheres.
  // The pieces and inner faces merge into the face on side 0 of the section edges.
  for (const Cap& cap : caps) {
    for (VertexId v : cap.vertices) {
      while (!m.is_point_sphere(v)) tx.delete_edge(m.edge(m.corner(v)));
      tx.delete_vertex(v);
    }
  }
  for (std::size_t i = 0; i < plan.caps.size(); ++i) {
    const FaceId f = m.face(m.corner(first_section[i], 0));
    if (m.is_hole(f) != plan.caps[i].hole) tx.set_hole(f, plan.caps[i].hole);
    result.faces.push_back(f);
  }
  return result;
}

ParamSpec offset_param() {
  return param("offset", ParamType::number, 0.25,
               "where each edge leaving the cut element is cut, as a share of its length from that element")
      .in_open(0.0, 0.5);
}

Params cut_outputs(const CutResult& cut, bool one_element) {
  Params out;
  out["faces"] = cut.faces;
  out["vertices"] = cut.vertices;
  if (one_element) out["face"] = cut.faces.front();
  return out;
}

}  // namespace dlfl::detail
