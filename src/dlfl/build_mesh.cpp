#include <dlfl/build_mesh.h>

#include <algorithm>
#include <cmath>

#include <dlfl/detail/edge_map.h>
#include <dlfl/statistics.h>

namespace dlfl {

// Writes the mesh arrays directly: building through insert_edge would relabel faces on every merge.
class MeshBuilder {
 public:
  static Mesh build(const PolygonSoup& soup, const SoupNumbering& numbering);
  static PolygonSoup polygons(const Mesh& mesh);
};

namespace {
constexpr std::uint32_t none = 0xFFFFFFFFu;

// Messages number vertices and faces as the soup's file does; the handle follows where the two differ.
struct Complaint {
  const SoupNumbering& numbering;

  std::string vertex(std::uint32_t k) const {
    return std::to_string(std::uint64_t{k} + numbering.first_vertex);
  }
  [[noreturn, gnu::cold, gnu::noinline]] void face(std::size_t f, const std::string& what) const {
    std::string name = "face " + std::to_string(f + numbering.first_face);
    if (numbering.first_face != 0) name += " (f" + std::to_string(f) + ")";
    throw PolygonError(PolygonError::Element::face, f, name + ": " + what);
  }
  [[noreturn, gnu::cold, gnu::noinline]] void vertex_fails(std::size_t v, const std::string& what) const {
    std::string name = "vertex " + std::to_string(v + numbering.first_vertex);
    if (numbering.first_vertex != 0) name += " (v" + std::to_string(v) + ")";
    throw PolygonError(PolygonError::Element::vertex, v, name + ": " + what);
  }
};
}  // namespace

Mesh MeshBuilder::build(const PolygonSoup& soup, const SoupNumbering& numbering) {
  const Complaint fail{numbering};
  const std::size_t nv = soup.positions.size();
  const std::size_t nf = soup.num_faces();
  const std::size_t nc = soup.indices.size();
  if (soup.offsets.empty() || soup.offsets.front() != 0 || soup.offsets.back() != nc) {
    throw InvalidArgument("build_mesh: face offsets do not match the index list");
  }
  if (nv >= none || nc >= none / 2) throw InvalidArgument("build_mesh: too many elements for 32-bit handles");
  for (std::size_t i = 0; i < nv; ++i) {
    const auto& p = soup.positions[i];
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
      fail.vertex_fails(i, "coordinate is not finite");
  }
  for (std::size_t f = 0; f < nf; ++f) {
    if (soup.offsets[f + 1] < soup.offsets[f])
      throw InvalidArgument("build_mesh: face offsets decrease at face " + std::to_string(f));
    auto face = soup.face(f);
    if (face.size() < 3)
      fail.face(f, "has " + std::to_string(face.size()) + " vertices; at least 3 are needed");
    std::uint32_t previous = face.back();
    for (std::uint32_t k : face) {
      if (k >= nv) {
        fail.face(f, "vertex index " + fail.vertex(k) + " is out of range (there are " + std::to_string(nv) +
                         " vertices)");
      }
      if (k == previous) fail.face(f, "uses vertex " + fail.vertex(k) + " twice in a row");
      previous = k;
    }
  }

  Mesh m;
  m.corners_.resize(nc);
  m.faces_.resize(nf);
  // Corners of the soup's faces, linked around each face.
  for (std::uint32_t f = 0; f < nf; ++f) {
    const std::uint32_t begin = soup.offsets[f], end = soup.offsets[f + 1];
    for (std::uint32_t k = begin; k < end; ++k) {
      auto& c = m.corners_[k];
      c.vertex = VertexId(soup.indices[k]);
      c.face = FaceId(f);
      c.next = CornerId(k + 1 == end ? begin : k + 1);
      c.prev = CornerId(k == begin ? end - 1 : k - 1);
    }
    m.faces_[f] = {CornerId(begin), end - begin, true, false};
  }
  auto target = [&](std::uint32_t k) { return m.corners_[m.corners_[k].next.index()].vertex.index(); };

  // Directed edges: one entry each; a second use of the same direction is an error. A vertex has as many
  // outgoing half-edges as corners.
  std::vector<std::uint32_t> corners_at(nv, 0);
  for (std::uint32_t k : soup.indices) ++corners_at[k];
  detail::EdgeMap directed(corners_at);
  for (std::uint32_t k = 0; k < nc; ++k) {
    const std::uint32_t a = m.corners_[k].vertex.index(), b = target(k);
    const std::uint32_t first = directed.insert(a, b, k);
    if (first != k) {
      fail.face(m.corners_[k].face.index(),
                "edge " + fail.vertex(a) + "-" + fail.vertex(b) +
                    " is also used in the same direction by face " +
                    std::to_string(std::uint64_t{m.corners_[first].face.index()} + numbering.first_face) +
                    " (an edge of more than two faces, or faces with opposite orientation)");
    }
  }

  // Pair each half-edge with its twin; unpaired ones border a hole. Edge side 0 is the smaller corner.
  std::vector<std::uint32_t> boundary;  // corners whose edge has no twin among the faces
  m.edges_.reserve(nc / 2 + 1);
  for (std::uint32_t k = 0; k < nc; ++k) {
    if (m.corners_[k].edge.valid()) continue;
    const std::uint32_t twin = directed.find(target(k), m.corners_[k].vertex.index());
    if (twin == detail::EdgeMap::none) {
      boundary.push_back(k);
      continue;
    }
    const EdgeId e(static_cast<std::uint32_t>(m.edges_.size()));
    m.edges_.push_back({{CornerId(k), CornerId(twin)}});
    m.corners_[k].edge = e;
    m.corners_[twin].edge = e;
  }

  // Hole faces. The hole corner of boundary half-edge k (a -> b) sits at b and runs back to a; the hole walk
  // goes on at a with the hole corner of the one boundary half-edge that arrives at a.
  std::size_t hole_faces = 0;
  if (!boundary.empty()) {
    std::vector<std::uint32_t> arriving(nv, none);  // vertex -> boundary slot of the half-edge arriving there
    for (std::uint32_t s = 0; s < boundary.size(); ++s) {
      const std::uint32_t b = target(boundary[s]);
      if (arriving[b] != none)
        fail.vertex_fails(b, "non-manifold: it lies on the boundary of more than one fan of faces");
      arriving[b] = s;
    }
    const std::uint32_t hole_base = static_cast<std::uint32_t>(nc);
    m.corners_.resize(nc + boundary.size());
    for (std::uint32_t s = 0; s < boundary.size(); ++s) {
      const std::uint32_t k = boundary[s];
      const std::uint32_t h = hole_base + s;
      const std::uint32_t a = m.corners_[k].vertex.index();
      const std::uint32_t next_hole = hole_base + arriving[a];
      auto& c = m.corners_[h];
      c.vertex = VertexId(target(k));
      c.next = CornerId(next_hole);
      m.corners_[next_hole].prev = CornerId(h);
      const EdgeId e(static_cast<std::uint32_t>(m.edges_.size()));
      m.edges_.push_back({{CornerId(k), CornerId(h)}});
      m.corners_[k].edge = e;
      c.edge = e;
    }
    for (std::uint32_t s = 0; s < boundary.size(); ++s) {
      const std::uint32_t h = hole_base + s;
      if (m.corners_[h].face.valid()) continue;
      const FaceId f(static_cast<std::uint32_t>(m.faces_.size()));
      std::uint32_t size = 0;
      std::uint32_t c = h;
      do {
        m.corners_[c].face = f;
        ++size;
        c = m.corners_[c].next.index();
      } while (c != h);
      m.faces_.push_back({CornerId(h), size, true, true});
      ++hole_faces;
    }
  }

  // Vertices: the first corner at each; unused vertices become point spheres.
  m.positions_.assign(soup.positions.begin(), soup.positions.end());
  m.vertex_corner_.assign(nv, CornerId());
  for (std::uint32_t k = 0; k < m.corners_.size(); ++k) {
    auto& anchor = m.vertex_corner_[m.corners_[k].vertex.index()];
    if (!anchor.valid()) anchor = CornerId(k);
  }
  for (std::uint32_t k = static_cast<std::uint32_t>(nc); k < m.corners_.size(); ++k) {
    ++corners_at[m.corners_[k].vertex.index()];  // hole corners
  }
  for (std::uint32_t v = 0; v < nv; ++v) {
    if (m.vertex_corner_[v].valid()) continue;
    const CornerId c(static_cast<std::uint32_t>(m.corners_.size()));
    const FaceId f(static_cast<std::uint32_t>(m.faces_.size()));
    m.corners_.push_back({VertexId(v), f, c, c, EdgeId()});
    m.faces_.push_back({c, 1, true, false});
    m.vertex_corner_[v] = c;
    corners_at[v] = 1;
  }
  m.live_vertices_ = nv;
  m.live_edges_ = m.edges_.size();
  m.live_faces_ = m.faces_.size();
  m.live_hole_faces_ = hole_faces;
  m.live_corners_ = m.corners_.size();

  // A manifold vertex has all its corners on one rotation cycle; more than one cycle is a pinch (two cones
  // touching at their tips, say).
  for (std::uint32_t v = 0; v < nv; ++v) {
    const CornerId first = m.vertex_corner_[v];
    std::uint32_t count = 0;
    CornerId c = first;
    do {
      c = m.next_around_vertex(c);
      ++count;
    } while (c != first && count <= corners_at[v]);
    if (count != corners_at[v]) {
      fail.vertex_fails(v, "non-manifold: its faces form more than one fan around it");
    }
  }
  return m;
}

PolygonSoup MeshBuilder::polygons(const Mesh& m) {
  PolygonSoup soup;
  std::vector<std::uint32_t> index(m.vertex_capacity(), none);
  soup.positions.reserve(m.num_vertices());
  bool any_hole = false;
  for (FaceId f : m.faces()) any_hole = any_hole || m.is_hole(f);
  for (VertexId v : m.vertices()) {
    // The inner vertices of a hole covered by several hole faces are not part of the surface.
    if (any_hole && !is_surface_vertex(m, v)) continue;
    index[v.index()] = static_cast<std::uint32_t>(soup.positions.size());
    soup.positions.push_back(m.position(v));
  }
  // Two edges between one pair of vertices would turn into one directed edge used twice. Key: (lower,
  // higher).
  std::vector<std::uint32_t> lower_degree(m.vertex_capacity(), 0);
  auto written = [&](EdgeId e) { return !m.is_hole(m.face(e, 0)) || !m.is_hole(m.face(e, 1)); };
  for (EdgeId e : m.edges()) {
    if (written(e)) ++lower_degree[std::min(m.from(e).index(), m.to(e).index())];
  }
  detail::EdgeMap pairs(lower_degree);
  for (EdgeId e : m.edges()) {
    if (!written(e)) continue;
    std::uint32_t a = m.from(e).index(), b = m.to(e).index();
    if (a > b) std::swap(a, b);
    if (pairs.insert(a, b, e.index()) != e.index()) {
      throw TopologyError("to_polygons: " + to_string(EdgeId(pairs.find(a, b))) + " and " + to_string(e) +
                          " both join " + to_string(VertexId(a)) + " and " + to_string(VertexId(b)) +
                          "; an indexed polygon file cannot hold that (use the native JSON format)");
    }
  }
  soup.offsets.reserve(m.num_faces() + 1);
  soup.indices.reserve(m.num_corners());
  for (FaceId f : m.faces()) {
    if (m.is_hole(f) || m.size(f) == 1) continue;
    if (m.size(f) == 2) {
      throw TopologyError(
          "to_polygons: " + to_string(f) +
          " has 2 corners; an indexed polygon file cannot hold it (use the native JSON format)");
    }
    for (CornerId c : m.corners(f)) soup.indices.push_back(index[m.vertex(c).index()]);
    soup.offsets.push_back(static_cast<std::uint32_t>(soup.indices.size()));
  }
  return soup;
}

Mesh build_mesh(const PolygonSoup& soup, const SoupNumbering& numbering) {
  return MeshBuilder::build(soup, numbering);
}
PolygonSoup to_polygons(const Mesh& mesh) { return MeshBuilder::polygons(mesh); }

}  // namespace dlfl
