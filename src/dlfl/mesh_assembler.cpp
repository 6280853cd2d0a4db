#include <dlfl/mesh_assembler.h>

#include <dlfl/detail/parallel_for.h>
#include <dlfl/errors.h>

#include <atomic>
#include <cstdint>
#include <string>

namespace dlfl {

namespace {
[[noreturn]] void too_many(const std::string& count) {
  throw InvalidArgument("MeshAssembler: " + count + " do not fit 32-bit handles (at most " +
                        std::to_string(MeshAssembler::max_count) + ")");
}
}  // namespace

void MeshAssembler::check_counts(std::size_t num_vertices, std::size_t num_faces, std::size_t num_corners) {
  if (num_vertices > max_count) too_many(std::to_string(num_vertices) + " vertices");
  if (num_faces > max_count) too_many(std::to_string(num_faces) + " faces");
  if (num_corners > max_count) too_many(std::to_string(num_corners) + " corners");
}

MeshAssembler::MeshAssembler(std::size_t num_vertices, std::span<const std::uint32_t> offsets) {
  if (offsets.empty() || offsets.front() != 0)
    throw InvalidArgument("MeshAssembler: offsets must start at 0");
  const std::size_t nf = offsets.size() - 1;
  const std::size_t nc = offsets.back();
  allocate(num_vertices, nf, nc);
  for (std::uint32_t f = 0; f < nf; ++f) {
    const std::uint32_t begin = offsets[f], end = offsets[f + 1];
    if (end <= begin + 1)
      throw InvalidArgument("MeshAssembler: face " + std::to_string(f) + " has < 2 corners");
    if (end > nc) {  // an offset past the last one would write beyond the corners
      throw InvalidArgument("MeshAssembler: face " + std::to_string(f) + " ends at corner " +
                            std::to_string(end) + ", past the " + std::to_string(nc) + " corners");
    }
    set_face(f, begin, end);
  }
}

MeshAssembler::MeshAssembler(std::size_t num_vertices, std::size_t num_faces, std::uint32_t face_size) {
  if (face_size < 2) throw InvalidArgument("MeshAssembler: faces need at least 2 corners");
  if (num_faces > SIZE_MAX / face_size) {  // the corner count itself would wrap
    too_many(std::to_string(num_faces) + " faces of " + std::to_string(face_size) + " corners");
  }
  const std::size_t nc = num_faces * face_size;
  allocate(num_vertices, num_faces, nc);
  detail::parallel_for(num_faces, [&](std::size_t f) {
    set_face(std::uint32_t(f), std::uint32_t(f * face_size), std::uint32_t((f + 1) * face_size));
  });
}

void MeshAssembler::allocate(std::size_t num_vertices, std::size_t num_faces, std::size_t num_corners) {
  check_counts(num_vertices, num_faces, num_corners);
  mesh_.positions_.resize(num_vertices);
  mesh_.vertex_corner_.assign(num_vertices, CornerId());
  mesh_.corners_.resize(num_corners);
  mesh_.faces_.resize(num_faces);
  twin_.resize(num_corners);
}

Mesh MeshAssembler::finish() {
  Mesh& m = mesh_;
  const std::size_t nc = m.corners_.size();
  // Edges are numbered in order of their smaller corner: each chunk of corners counts the edges it starts,
  // the counts are summed in chunk order, and each chunk then numbers its own; the result is the serial
  // numbering whatever the threads.
  const std::size_t chunks = detail::chunk_count(nc);
  std::vector<std::uint32_t> first_edge(chunks + 1, 0);
  const auto pairs_back = [&](std::size_t k) {
    const std::uint32_t t = twin_[k];
    return t < nc && twin_[t] == k && t != k;
  };
  std::atomic<bool> unpaired = false;
  detail::parallel_chunks(nc, detail::parallel_grain, [&](std::size_t begin, std::size_t end) {
    std::uint32_t count = 0;
    for (std::size_t k = begin; k < end; ++k) {
      if (!pairs_back(k)) {
        unpaired = true;
        return;
      }
      count += twin_[k] > k;
    }
    first_edge[begin / detail::parallel_grain + 1] = count;
  });
  if (unpaired) {  // the first such corner, found serially so that the message does not depend on threads
    for (std::uint32_t k = 0; k < nc; ++k) {
      if (!pairs_back(k)) {
        throw InvalidArgument("MeshAssembler: the twin of corner " + std::to_string(k) +
                              " does not pair back");
      }
    }
  }
  for (std::size_t c = 0; c < chunks; ++c) first_edge[c + 1] += first_edge[c];
  m.edges_.resize(first_edge[chunks]);
  detail::parallel_chunks(nc, detail::parallel_grain, [&](std::size_t begin, std::size_t end) {
    std::uint32_t e = first_edge[begin / detail::parallel_grain];
    for (std::size_t k = begin; k < end; ++k) {
      const std::uint32_t t = twin_[k];
      if (t < k) continue;  // the edge is made at its smaller corner
      m.edges_[e] = {{CornerId(std::uint32_t(k)), CornerId(t)}};
      m.corners_[k].edge = EdgeId(e);
      m.corners_[t].edge = EdgeId(e);
      ++e;
    }
  });
  // Each vertex's anchor is its smallest corner: a minimum, which no order of the threads changes.
  detail::parallel_for(nc, [&](std::size_t k) {
    std::atomic_ref<CornerId> anchor(m.vertex_corner_[m.corners_[k].vertex.index()]);
    CornerId seen = anchor.load(std::memory_order_relaxed);
    while ((!seen.valid() || seen.index() > k) &&
           !anchor.compare_exchange_weak(seen, CornerId(std::uint32_t(k)), std::memory_order_relaxed)) {
    }
  });
  for (std::size_t v = 0; v < m.vertex_corner_.size(); ++v) {
    if (!m.vertex_corner_[v].valid()) {
      throw InvalidArgument("MeshAssembler: vertex " + std::to_string(v) + " has no corner");
    }
  }
  m.live_vertices_ = m.positions_.size();
  m.live_edges_ = m.edges_.size();
  m.live_faces_ = m.faces_.size();
  m.live_hole_faces_ = hole_faces_;
  m.live_corners_ = nc;
  twin_.clear();
  return std::move(m);
}

}  // namespace dlfl
