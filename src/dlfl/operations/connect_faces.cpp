// connect_faces: the tube between two faces, and its registered operation.
//
// The Euler sequence. After the merging edge l_0 (from corner1's vertex P_0 to its partner's Q_0), the merged
// face is walked as a frontier: X, the corner at the face2 end of the last long edge (its edge is that long
// edge), and Y = next(X), the corner at its face1 end. Each next long edge is inserted from prev(X) or X (as
// the schedule advances on face2 or not) to next(Y) or Y (on face1 or not); that cuts the tube face between
// the two long edges off, and the new edge's corner at its face2 end is the next X. The last tube face is
// what is left. With segments s > 1, each long edge is subdivided at its s - 1 ring points, then each tube
// face is split by the ring edges, from face1's end up.

#include <cmath>
#include <string>

#include <dlfl/errors.h>
#include <dlfl/geometry.h>
#include <dlfl/operations/connect_faces.h>
#include <dlfl/operations/detail/operation_table.h>
#include <dlfl/operations/detail/tube_correspondence.h>
#include <dlfl/operations/detail/tube_rings.h>

namespace dlfl {
namespace {

constexpr int max_segments = 1024;

[[noreturn]] void refuse(const char* param, const std::string& what) {
  throw ParameterError(std::string("connect_faces: parameter ") + param + ": " + what, param);
}

void require_end_face(const Mesh& m, FaceId f, const char* param) {
  if (!m.is_alive(f)) refuse(param, to_string(f) + " is not a live face");
  if (m.size(f) < 2)
    refuse(param, to_string(f) + " is a point sphere's face: it has no edge to start a tube");
}

void require_number(double x, const char* param) {
  if (!std::isfinite(x) || x < 0) refuse(param, "must be a finite number >= 0, not " + std::to_string(x));
}

std::uint32_t mod(std::int64_t x, std::uint32_t n) {
  const std::int64_t r = x % std::int64_t(n);
  return static_cast<std::uint32_t>(r < 0 ? r + n : r);
}

// The position of corner c in the face's corner list, checking it belongs there.
std::uint32_t position_in(const Mesh& m, const std::vector<CornerId>& corners, CornerId c, FaceId f,
                          const char* param, const char* face_param) {
  if (!m.is_alive(c)) refuse(param, to_string(c) + " is not a live corner");
  for (std::uint32_t i = 0; i < corners.size(); ++i) {
    if (corners[i] == c) return i;
  }
  refuse(param, to_string(c) + " is not a corner of " + face_param + " (" + to_string(f) + ")");
}

// Everything the tube is built from, resolved and checked.
struct TubePlan {
  detail::TubeEndCorners ends;
  std::uint32_t start1 = 0;  // corner1's position in face1
  std::uint32_t base2 = 0;   // corner2's position in face2
  std::uint32_t start2 = 0;  // its partner's, the twist applied
};

TubePlan plan_tube(const Mesh& m, FaceId face1, FaceId face2, const ConnectFacesOptions& o) {
  require_end_face(m, face1, "face1");
  require_end_face(m, face2, "face2");
  if (face1 == face2) refuse("face2", to_string(face2) + " is face1: a tube needs two faces");
  if (o.segments < 1 || o.segments > max_segments) {
    refuse("segments",
           "must be in [1, " + std::to_string(max_segments) + "], not " + std::to_string(o.segments));
  }
  require_number(o.weight1, "weight1");
  require_number(o.weight2, "weight2");
  require_number(o.pinch, "pinch");
  require_number(o.bubble, "bubble");

  TubePlan plan;
  plan.ends = detail::tube_end_corners(m, face1, face2);
  std::optional<std::uint32_t> given1, given2;
  if (o.corner1.valid()) given1 = position_in(m, plan.ends.face1, o.corner1, face1, "corner1", "face1");
  if (o.corner2.valid()) given2 = position_in(m, plan.ends.face2, o.corner2, face2, "corner2", "face2");
  const auto n2 = static_cast<std::uint32_t>(plan.ends.face2.size());
  const std::uint32_t shift = mod(o.twist, n2);
  const std::optional<detail::TubeStart> start = detail::best_tube_start(m, plan.ends, given1, given2, shift);
  if (!start) {
    if (given1 && given2) {
      const VertexId v = detail::self_joined_vertex(m, plan.ends, *given1, (*given2 + shift) % n2);
      refuse("corner2", "the tube from corner1 " + to_string(o.corner1) + " to corner2 " +
                            to_string(o.corner2) + " (twist " + std::to_string(o.twist) +
                            ") would join vertex " + to_string(v) + ", which both faces share, to itself");
    }
    if (given1 || given2) {
      const char* param = given2 ? "corner2" : "corner1";
      refuse(param, "every tube from it (twist " + std::to_string(o.twist) +
                        ") would join a vertex that both faces share to itself");
    }
    refuse("face2", "every pairing of the corners of face1 and face2 (twist " + std::to_string(o.twist) +
                        ") would join a vertex that both faces share to itself");
  }
  plan.start1 = start->start1;
  plan.base2 = start->base2;
  plan.start2 = (start->base2 + shift) % n2;
  return plan;
}

// The corners of a subdivided long edge's ring vertex: `in_face` (next towards face1's end) lies in the tube
// face that runs along this long edge from face2 to face1; `in_previous` in the other.
struct RingCorners {
  CornerId in_face;
  CornerId in_previous;
};

RingCorners ring_corners(const Mesh& m, VertexId v, VertexId towards_face1) {
  const CornerId c = m.corner(v);
  const CornerId other = m.next_around_vertex(c);
  if (m.vertex(m.next(c)) == towards_face1) return {c, other};
  return {other, c};
}

}  // namespace

TubeEnds check_connect_faces(const Mesh& m, FaceId face1, FaceId face2, const ConnectFacesOptions& options) {
  const TubePlan plan = plan_tube(m, face1, face2, options);
  return {plan.ends.face1[plan.start1], plan.ends.face2[plan.base2]};
}

ConnectFacesResult connect_faces(Transaction& tx, FaceId face1, FaceId face2, const ConnectFacesOptions& o) {
  const Mesh& m = tx.mesh();
  const TubePlan plan = plan_tube(m, face1, face2, o);
  const detail::TubeSchedule schedule = plan.ends.schedule();
  const std::uint32_t n = schedule.edges();
  const auto s = static_cast<std::uint32_t>(o.segments);

  // The long edges' ends, and every position, read before anything changes.
  std::vector<CornerId> end1(n), end2(n);
  detail::TubeRingsInput rings;
  for (std::uint32_t k = 0; k < n; ++k) {
    end1[k] = plan.ends.face1[(plan.start1 + schedule.a(k)) % schedule.n1];
    end2[k] = plan.ends.face2[mod(std::int64_t(plan.start2) - schedule.b(k), schedule.n2)];
    rings.ends1.push_back(m.position(m.vertex(end1[k])));
    rings.ends2.push_back(m.position(m.vertex(end2[k])));
  }
  rings.centroid1 = face_centroid(m, face1);
  rings.centroid2 = face_centroid(m, face2);
  rings.normal1 = face_normal(m, face1);
  rings.normal2 = face_normal(m, face2);
  rings.segments = o.segments;
  rings.curve = o.curve;
  rings.weight1 = o.weight1;
  rings.weight2 = o.weight2;
  rings.pinch = o.pinch;
  rings.bubble = o.bubble;
  const std::vector<glm::dvec3> ring_points = detail::tube_ring_positions(rings);

  ConnectFacesResult result;
  result.corner1 = plan.ends.face1[plan.start1];
  result.corner2 = plan.ends.face2[plan.base2];

  // The merge, then the splits along the frontier.
  std::vector<EdgeId> long_edges(n);
  std::vector<CornerId> tube_face_corner(n);  // a corner of each tube face, while s = 1
  const InsertEdgeResult merge = tx.insert_edge(end1[0], end2[0]);
  long_edges[0] = result.edge = merge.edge;
  // The merged face has the larger face's flag; the tube is surface whatever its ends were.
  if (m.is_hole(m.face(end1[0]))) tx.set_hole(m.face(end1[0]), false);
  CornerId x = m.corner(merge.edge, 1);
  CornerId y = m.next(x);
  for (std::uint32_t k = 0; k + 1 < n; ++k) {
    const CornerId from2 = schedule.b(k + 1) != schedule.b(k) ? m.prev(x) : x;
    const CornerId from1 = schedule.a(k + 1) != schedule.a(k) ? m.next(y) : y;
    const EdgeId e = tx.insert_edge(from2, from1).edge;
    long_edges[k + 1] = e;
    tube_face_corner[k] = from2;  // in the part cut off: tube face k
    x = m.corner(e, 0);
    y = from1;
  }
  tube_face_corner[n - 1] = x;

  if (s == 1) {
    for (CornerId c : tube_face_corner) result.faces.push_back(m.face(c));
    return result;
  }

  // Rings: subdivide each long edge at its points, nearest to the edge's far end first, so that the edge
  // itself keeps the part at its start.
  std::vector<RingCorners> ring(std::size_t(n) * (s - 1));  // ring (j - 1) n + k
  result.vertices.resize(ring.size());
  for (std::uint32_t k = 0; k < n; ++k) {
    const EdgeId e = long_edges[k];
    const VertexId p = m.vertex(end1[k]);
    const bool from_face1 = m.from(e) == p;
    for (std::uint32_t i = 0; i + 1 < s; ++i) {
      const std::uint32_t j = from_face1 ? s - 1 - i : i + 1;
      result.vertices[(j - 1) * n + k] = tx.subdivide_edge(e, ring_points[(j - 1) * n + k]);
    }
    for (std::uint32_t j = 1; j < s; ++j) {
      const VertexId below = j == 1 ? p : result.vertices[(j - 2) * n + k];
      ring[(j - 1) * n + k] = ring_corners(m, result.vertices[(j - 1) * n + k], below);
    }
  }
  // Tube face k lies between long edges k and k + 1: ring edges from k's ring vertices to k + 1's.
  result.faces.resize(std::size_t(n) * s);
  for (std::uint32_t k = 0; k < n; ++k) {
    const std::uint32_t next_k = (k + 1) % n;
    for (std::uint32_t j = 1; j < s; ++j) {
      const CornerId from = ring[(j - 1) * n + k].in_face;
      const CornerId to = ring[(j - 1) * n + next_k].in_previous;
      tx.insert_edge(from, to);  // cuts off the face between rings j - 1 and j
    }
    for (std::uint32_t j = 1; j < s; ++j)
      result.faces[(j - 1) * n + k] = m.face(ring[(j - 1) * n + k].in_face);
    result.faces[(s - 1) * n + k] = m.face(ring[(s - 2) * n + next_k].in_previous);
  }
  return result;
}

namespace detail {
namespace {

ConnectFacesOptions options_of(const Params& p) {
  ConnectFacesOptions o;
  if (p.has("corner1")) o.corner1 = p.handle<CornerId>("corner1");
  if (p.has("corner2")) o.corner2 = p.handle<CornerId>("corner2");
  o.segments = static_cast<int>(p.integer("segments"));
  const std::string& curve = p.text("curve");
  o.curve = curve == "hermite" ? TubeCurve::hermite : curve == "bezier" ? TubeCurve::bezier : TubeCurve::line;
  o.weight1 = p.number("weight1");
  o.weight2 = p.number("weight2");
  o.twist = p.integer("twist");
  o.pinch = p.number("pinch");
  o.bubble = p.number("bubble");
  return o;
}

}  // namespace

std::vector<OperationSpec> connect_faces_operation_specs() {
  const std::string chosen =
      "with the other corner, the closest pair (one in each face) joining no vertex to itself";
  return {edit_operation(
      "connect_faces",
      "a tube from face1 to face2 (TopMod's add hole/handle): one INSERTEDGE merges the faces, more split "
      "the "
      "merged face into the tube; adds a handle on one component, joins two components",
      {param("face1", ParamType::face, "one end of the tube"),
       param("face2", ParamType::face, "the other end (a hole face too: bridges two boundary loops)"),
       param("corner1", ParamType::corner, "the corner of face1 where the first edge starts")
           .optional(chosen),
       param("corner2", ParamType::corner, "the corner of face2 that corner1 pairs with, before the twist")
           .optional(chosen),
       param("segments", ParamType::integer, 1,
             "faces along the tube: rings of new vertices between the ends")
           .in(1, max_segments),
       param("curve", ParamType::text, "line",
             "the path of the rings: line (straight), hermite (leaving and entering along the face normals), "
             "bezier (a cubic per ring vertex)")
           .one_of({"line", "hermite", "bezier"}),
       param("weight1", ParamType::number, 1.0, "hermite and bezier: the tangent at face1, in chord lengths")
           .at_least(0),
       param("weight2", ParamType::number, 1.0, "hermite and bezier: the tangent at face2, in chord lengths")
           .at_least(0),
       param("twist", ParamType::integer, 0,
             "turns the correspondence of the corners by this many positions"),
       param("pinch", ParamType::number, 1.0, "scales the middle rings (1: unchanged, 0: closed to a point)")
           .at_least(0),
       param("bubble", ParamType::number, 0.0,
             "pushes the middle rings outward by this many mean end radii (a round bulge)")
           .at_least(0)},
      "V+m(s-1), E+ms+m(s-1), F-2+ms (m = max(n1, n2), s = segments)",
      [](Transaction& tx, const Params& p) {
        const ConnectFacesResult r =
            connect_faces(tx, p.handle<FaceId>("face1"), p.handle<FaceId>("face2"), options_of(p));
        return Params{{"faces", r.faces}, {"vertices", r.vertices}, {"edge", r.edge}};
      },
      [](const Mesh& m, Params& p) {
        const TubeEnds ends =
            check_connect_faces(m, p.handle<FaceId>("face1"), p.handle<FaceId>("face2"), options_of(p));
        // The log records the corners in force, so a replay needs no search.
        p["corner1"] = ends.corner1;
        p["corner2"] = ends.corner2;
      })};
}

}  // namespace detail
}  // namespace dlfl
