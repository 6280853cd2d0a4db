#include <dlfl/validate.h>

#include <iterator>
#include <numeric>

#include <dlfl/detail/enum_names.h>

namespace dlfl {

const char* to_string(ViolationCode code) {
  static constexpr const char* names[] = {
      "removed_reference", "next_prev",      "corner_face",  "face_size", "edge_corner",         "edge_sides",
      "vertex_corner",     "pinched_vertex", "point_sphere", "counts",    "euler_characteristic"};
  static_assert(std::size(names) == std::size_t(ViolationCode::euler_characteristic) + 1,
                "a name per enumerator, in order");
  return detail::name_at(code, names, "unknown");
}

namespace {

class Checker {
 public:
  Checker(const Mesh& m, std::size_t max) : m_(m), max_(max) {}

  template <class H>
  void report(ViolationCode code, H element, std::string message) {
    report_named(code, to_string(element), std::move(message));
  }
  void report_named(ViolationCode code, std::string element, std::string message) {
    ++report_.violation_count;
    if (report_.violations.size() < max_)
      report_.violations.push_back({code, std::move(element), std::move(message)});
  }

  ValidationReport run() {
    check_corners();
    check_faces();
    check_edges();
    if (report_.valid()) check_vertices();  // rotation needs sound corners and edges
    check_counts();
    if (report_.valid()) components();
    return std::move(report_);
  }

 private:
  void check_corners() {
    corners_at_.assign(m_.vertex_capacity(), 0);
    for (CornerId c : m_.corners()) {
      ++live_corners_;
      const VertexId v = m_.vertex(c);
      const FaceId f = m_.face(c);
      const CornerId n = m_.next(c);
      const CornerId p = m_.prev(c);
      const EdgeId e = m_.edge(c);
      if (!m_.is_alive(v) || !m_.is_alive(f) || !m_.is_alive(n) || !m_.is_alive(p) ||
          (e.valid() && !m_.is_alive(e))) {
        report(ViolationCode::removed_reference, c, "corner refers to a removed element");
        continue;
      }
      ++corners_at_[v.index()];
      if (m_.prev(n) != c || m_.next(p) != c)
        report(ViolationCode::next_prev, c, "next/prev links are not mutual");
      if (m_.face(n) != f) report(ViolationCode::corner_face, c, "next corner belongs to another face");
      if (e.valid()) {
        if (m_.corner(e, 0) != c && m_.corner(e, 1) != c) {
          report(ViolationCode::edge_corner, c, "its edge " + to_string(e) + " does not list it as a side");
        }
        if (n == c) report(ViolationCode::point_sphere, c, "a corner with an edge is its own next");
      } else {
        ++point_spheres_;
        if (n != c || p != c || m_.size(f) != 1) {
          report(ViolationCode::point_sphere, c, "corner without an edge is not the only corner of its face");
        }
      }
    }
  }

  void check_faces() {
    std::size_t total = 0;
    for (FaceId f : m_.faces()) {
      ++live_faces_;
      live_hole_faces_ += m_.is_hole(f);
      const CornerId first = m_.first_corner(f);
      if (!m_.is_alive(first)) {
        report(ViolationCode::removed_reference, f, "first corner " + to_string(first) + " does not exist");
        continue;
      }
      if (m_.face(first) != f) {
        report(ViolationCode::corner_face, f,
               "first corner " + to_string(first) + " belongs to another face");
        continue;
      }
      // Walk at most size+1 steps so a broken cycle cannot loop forever.
      std::uint64_t steps = 0;
      const std::uint64_t limit = std::uint64_t(m_.size(f)) + 1;
      CornerId c = first;
      do {
        c = m_.next(c);
        ++steps;
      } while (c != first && steps <= limit && m_.is_alive(c));
      if (c != first || steps != m_.size(f)) {
        report(
            ViolationCode::face_size, f,
            "stores size " + std::to_string(m_.size(f)) + " but its corner cycle does not have that length");
      }
      total += m_.size(f);
    }
    if (total != live_corners_) {
      report_named(ViolationCode::face_size, "mesh",
                   "face sizes add up to " + std::to_string(total) + " but there are " +
                       std::to_string(live_corners_) + " corners (a corner is off its face's cycle)");
    }
  }

  void check_edges() {
    for (EdgeId e : m_.edges()) {
      ++live_edges_;
      const CornerId a = m_.corner(e, 0);
      const CornerId b = m_.corner(e, 1);
      if (!m_.is_alive(a) || !m_.is_alive(b)) {
        report(ViolationCode::removed_reference, e, "a side corner does not exist");
        continue;
      }
      if (a == b) {
        report(ViolationCode::edge_sides, e, "both sides are the same corner");
        continue;
      }
      if (m_.edge(a) != e || m_.edge(b) != e) {
        report(ViolationCode::edge_corner, e, "a side corner does not leave along this edge");
        continue;
      }
      if (!m_.is_alive(m_.next(a)) || !m_.is_alive(m_.next(b))) continue;  // reported with the corners
      if (m_.vertex(b) != m_.vertex(m_.next(a)) || m_.vertex(a) != m_.vertex(m_.next(b))) {
        report(ViolationCode::edge_corner, e, "the other side does not start where this side ends");
      }
      if (m_.vertex(a) == m_.vertex(b)) report(ViolationCode::edge_sides, e, "self-loop");
    }
  }

  void check_vertices() {
    for (VertexId v : m_.vertices()) {
      const CornerId first = m_.corner(v);
      if (!m_.is_alive(first) || m_.vertex(first) != v) {
        report(ViolationCode::vertex_corner, v, "representative corner is not at this vertex");
        continue;
      }
      std::uint64_t count = 0;
      const std::uint64_t limit = std::uint64_t(corners_at_[v.index()]) + 1;
      CornerId c = first;
      do {
        c = m_.next_around_vertex(c);
        ++count;
      } while (c != first && count <= limit && m_.vertex(c) == v);
      if (c != first || count != corners_at_[v.index()]) {
        report(ViolationCode::pinched_vertex, v,
               "its " + std::to_string(corners_at_[v.index()]) + " corners do not form one rotation cycle");
      }
    }
  }

  void check_counts() {
    std::size_t live_vertices = 0;
    for ([[maybe_unused]] VertexId v : m_.vertices()) ++live_vertices;
    if (live_vertices != m_.num_vertices() || live_edges_ != m_.num_edges() ||
        live_faces_ != m_.num_faces() || live_hole_faces_ != m_.num_hole_faces() ||
        live_corners_ != m_.num_corners()) {
      report_named(ViolationCode::counts, "mesh", "live element counts are out of date");
    }
    if (2 * live_edges_ + point_spheres_ != live_corners_) {
      report_named(ViolationCode::counts, "mesh", "corners != 2 * edges + point spheres");
    }
  }

  std::uint32_t find(std::uint32_t x) {
    while (parent_[x] != x) {
      parent_[x] = parent_[parent_[x]];
      x = parent_[x];
    }
    return x;
  }

  void components() {
    parent_.resize(m_.vertex_capacity());
    std::iota(parent_.begin(), parent_.end(), 0u);
    for (EdgeId e : m_.edges()) {
      std::uint32_t a = find(m_.from(e).index());
      std::uint32_t b = find(m_.to(e).index());
      if (a != b) parent_[std::max(a, b)] = std::min(a, b);  // the root is the smallest vertex
    }
    // Dense component numbers in order of each component's smallest vertex; reuse parent_ as the map.
    auto& out = report_.components;
    std::vector<std::uint32_t>& component = corners_at_;  // no longer needed: holds vertex -> component
    for (VertexId v : m_.vertices()) {
      const std::uint32_t r = find(v.index());
      if (r == v.index()) {
        component[r] = static_cast<std::uint32_t>(out.size());
        out.emplace_back();
      } else {
        component[v.index()] = component[r];
      }
      ++out[component[v.index()]].vertices;
    }
    for (EdgeId e : m_.edges()) ++out[component[m_.from(e).index()]].edges;
    for (FaceId f : m_.faces()) {
      auto& info = out[component[m_.vertex(m_.first_corner(f)).index()]];
      ++info.faces;
      info.holes += m_.is_hole(f);
    }
    for (std::size_t i = 0; i < out.size(); ++i) {
      auto& info = out[i];
      info.euler_characteristic = long(info.vertices) - long(info.edges) + long(info.faces);
      info.genus = (2 - info.euler_characteristic) / 2;
      if (info.euler_characteristic > 2 || info.euler_characteristic % 2 != 0) {
        report_named(ViolationCode::euler_characteristic, "component " + std::to_string(i),
                     "Euler characteristic " + std::to_string(info.euler_characteristic) +
                         " is not that of a closed orientable surface");
      }
    }
  }

  const Mesh& m_;
  std::size_t max_;
  ValidationReport report_;
  std::vector<std::uint32_t> corners_at_;
  std::vector<std::uint32_t> parent_;
  std::size_t live_corners_ = 0, live_faces_ = 0, live_hole_faces_ = 0, live_edges_ = 0, point_spheres_ = 0;
};

}  // namespace

ValidationReport validate(const Mesh& mesh, std::size_t max_violations) {
  return Checker(mesh, max_violations).run();
}

}  // namespace dlfl
