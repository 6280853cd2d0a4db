#include <dlfl/cells/convert.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <string>
#include <vector>

#include <dlfl/cells/detail/vertex_set_map.h>
#include <dlfl/dense_mesh.h>
#include <dlfl/errors.h>

namespace dlfl {

namespace {

void check_soup(const PolygonSoup& soup) {
  const std::size_t nv = soup.positions.size();
  for (std::size_t v = 0; v < nv; ++v) {
    const glm::dvec3& p = soup.positions[v];
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z)) {
      throw InvalidArgument("polygons to quads: vertex " + std::to_string(v) +
                            " has a non-finite coordinate");
    }
  }
  if (soup.offsets.empty() || soup.offsets.front() != 0 || soup.offsets.back() != soup.indices.size()) {
    throw InvalidArgument("polygons to quads: offsets do not describe the index list");
  }
  for (std::size_t f = 0; f < soup.num_faces(); ++f) {  // all ranges first, before any face is read
    if (soup.offsets[f + 1] < soup.offsets[f] || soup.offsets[f + 1] > soup.indices.size()) {
      throw InvalidArgument("polygons to quads: offsets decrease or run past the index list at face " +
                            std::to_string(f));
    }
  }
  // last_face[v] = 1 + the last face that used v: finds a repeated vertex in O(face size).
  std::vector<std::uint32_t> last_face(nv, 0);
  for (std::size_t f = 0; f < soup.num_faces(); ++f) {
    if (soup.offsets[f + 1] < soup.offsets[f] + 3) {
      throw InvalidArgument("polygons to quads: face " + std::to_string(f) + " has fewer than 3 vertices");
    }
    const auto stamp = static_cast<std::uint32_t>(f + 1);
    for (std::uint32_t v : soup.face(f)) {
      if (v >= nv) {
        throw InvalidArgument("polygons to quads: face " + std::to_string(f) + " uses vertex " +
                              std::to_string(v) + " but there are " + std::to_string(nv) + " vertices");
      }
      if (last_face[v] == stamp) {
        throw InvalidArgument("polygons to quads: face " + std::to_string(f) + " uses vertex " +
                              std::to_string(v) + " twice");
      }
      last_face[v] = stamp;
    }
  }
}

}  // namespace

CellComplex polygons_to_quads(const PolygonSoup& soup) {
  check_soup(soup);
  const std::size_t nv = soup.positions.size();
  const std::size_t nf = soup.num_faces();
  const std::size_t corners = soup.indices.size();
  if (nv + corners + nf > 0xFFFFFFFFu || 4 * corners > 0xFFFFFFFFu) {
    throw InvalidArgument("polygons to quads: the result would not fit 32-bit indices");
  }

  // Edge midpoints, shared through the unordered vertex pair.
  std::vector<std::uint32_t> starts_with(nv, 0);
  for (std::size_t f = 0; f < nf; ++f) {
    const auto face = soup.face(f);
    for (std::size_t j = 0; j < face.size(); ++j) {
      ++starts_with[std::min(face[j], face[(j + 1) % face.size()])];
    }
  }
  detail::VertexSetMap<2> edges(starts_with);
  CellComplex out;
  out.positions.reserve(nv + corners + nf);
  out.positions.assign(soup.positions.begin(), soup.positions.end());
  std::vector<std::uint32_t> midpoint(corners);  // of the edge leaving each corner
  for (std::size_t f = 0; f < nf; ++f) {
    const auto face = soup.face(f);
    for (std::size_t j = 0; j < face.size(); ++j) {
      const std::uint32_t a = face[j], b = face[(j + 1) % face.size()];
      const auto next = static_cast<std::uint32_t>(out.positions.size());
      const std::uint32_t found = edges.insert({std::min(a, b), std::max(a, b)}, next);
      if (found == next) out.positions.push_back(0.5 * (soup.positions[a] + soup.positions[b]));
      midpoint[soup.offsets[f] + j] = found;
    }
  }
  const auto centroid_base = static_cast<std::uint32_t>(out.positions.size());
  for (std::size_t f = 0; f < nf; ++f) {
    glm::dvec3 sum(0.0);
    for (std::uint32_t v : soup.face(f)) sum += soup.positions[v];
    out.positions.push_back(sum / double(soup.face(f).size()));
  }

  out.offsets.resize(corners + 1);
  out.indices.resize(4 * corners);
  for (std::size_t k = 0; k <= corners; ++k) out.offsets[k] = static_cast<std::uint32_t>(4 * k);
  for (std::size_t f = 0; f < nf; ++f) {
    const std::uint32_t first = soup.offsets[f], n = soup.offsets[f + 1] - first;
    for (std::uint32_t j = 0; j < n; ++j) {
      std::uint32_t* quad = out.indices.data() + 4 * std::size_t(first + j);
      quad[0] = soup.indices[first + j];
      quad[1] = midpoint[first + j];
      quad[2] = midpoint[first + (j + n - 1) % n];
      quad[3] = centroid_base + static_cast<std::uint32_t>(f);
    }
  }
  return out;
}

CellComplex polyhedron_to_hexahedra(const Mesh& input) {
  // Checked on the input, so that messages name its handles.
  for (FaceId f : input.faces()) {
    if (input.is_hole(f)) {
      throw TopologyError("polyhedron to hexahedra: " + to_string(f) +
                          " is a hole (the mesh is open); a closed polyhedron is needed");
    }
  }
  for (VertexId v : input.vertices()) {
    const std::uint32_t valence = input.valence(v);
    if (valence != 3) {
      throw TopologyError("polyhedron to hexahedra: " + to_string(v) + " has valence " +
                          std::to_string(valence) + "; the split needs every vertex 3-valent");
    }
  }
  std::optional<Mesh> storage;
  const Mesh& m = dense_mesh(input, storage);
  const auto [nv, ne, nf, nc] = dense_counts(m);

  // Components, by a walk over the edges; each one gets its own centroid and must be a sphere.
  constexpr std::uint32_t unset = 0xFFFFFFFFu;
  std::vector<std::uint32_t> component(nv, unset);
  std::vector<std::uint32_t> stack;
  std::vector<glm::dvec3> centroid;
  std::vector<std::uint32_t> first_vertex;
  std::vector<std::int64_t> euler;  // V - E + F per component
  for (std::uint32_t start = 0; start < nv; ++start) {
    if (component[start] != unset) continue;
    const auto c = static_cast<std::uint32_t>(centroid.size());
    centroid.emplace_back(0.0);
    first_vertex.push_back(start);
    std::int64_t count = 0;
    component[start] = c;
    stack.push_back(start);
    while (!stack.empty()) {
      const std::uint32_t v = stack.back();
      stack.pop_back();
      centroid[c] += m.position(VertexId(v));
      ++count;
      for (CornerId corner : m.corners(VertexId(v))) {
        const std::uint32_t w = m.vertex(m.next(corner)).index();
        if (component[w] == unset) {
          component[w] = c;
          stack.push_back(w);
        }
      }
    }
    centroid[c] /= double(count);
    euler.push_back(count);
  }
  for (std::uint32_t e = 0; e < ne; ++e) --euler[component[m.from(EdgeId(e)).index()]];
  for (std::uint32_t f = 0; f < nf; ++f) ++euler[component[m.vertex(m.first_corner(FaceId(f))).index()]];
  for (std::size_t c = 0; c < euler.size(); ++c) {
    if (euler[c] != 2) {
      throw TopologyError("polyhedron to hexahedra: the component of " +
                          to_string(VertexId(first_vertex[c])) + " has Euler characteristic " +
                          std::to_string(euler[c]) + ", not 2: it is not a polyhedron (a sphere)");
    }
  }

  if (std::uint64_t(nv) + ne + nf + centroid.size() > 0xFFFFFFFEu || 8 * std::uint64_t(nv) > 0xFFFFFFFEu) {
    throw InvalidArgument("polyhedron to hexahedra: the result would need more than 32-bit indices");
  }
  const std::uint32_t edge_base = nv, face_base = nv + ne, centroid_base = nv + ne + nf;
  CellComplex out;
  out.positions.reserve(std::size_t(centroid_base) + centroid.size());
  for (std::uint32_t v = 0; v < nv; ++v) out.positions.push_back(m.position(VertexId(v)));
  for (std::uint32_t e = 0; e < ne; ++e) {
    out.positions.push_back(0.5 * (m.position(m.from(EdgeId(e))) + m.position(m.to(EdgeId(e)))));
  }
  for (std::uint32_t f = 0; f < nf; ++f) {  // the vertex average, not a Zhang-Wang control point
    glm::dvec3 sum(0.0);
    for (CornerId c : m.corners(FaceId(f))) sum += m.position(m.vertex(c));
    out.positions.push_back(sum / double(m.size(FaceId(f))));
  }
  for (const glm::dvec3& c : centroid) out.positions.push_back(c);

  out.offsets.resize(std::size_t(nv) + 1);
  out.indices.resize(8 * std::size_t(nv));
  for (std::uint32_t v = 0; v < nv; ++v) {
    out.offsets[v + 1] = 8 * (v + 1);
    const CornerId c0 = m.corner(VertexId(v));
    const CornerId c1 = m.next_around_vertex(c0);
    const CornerId c2 = m.next_around_vertex(c1);
    if (m.face(c0) == m.face(c1) || m.face(c1) == m.face(c2) || m.face(c0) == m.face(c2)) {
      throw TopologyError("polyhedron to hexahedra: a face meets " + to_string(VertexId(v)) +
                          " at two corners; the split needs three distinct faces at every vertex");
    }
    std::uint32_t* hex = out.indices.data() + 8 * std::size_t(v);
    hex[0] = v;
    hex[1] = edge_base + m.edge(c0).index();
    hex[2] = edge_base + m.edge(c1).index();
    hex[3] = face_base + m.face(c1).index();
    hex[4] = edge_base + m.edge(c2).index();
    hex[5] = face_base + m.face(c0).index();
    hex[6] = face_base + m.face(c2).index();
    hex[7] = centroid_base + component[v];
  }
  return out;
}

}  // namespace dlfl
