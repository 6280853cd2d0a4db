#include <dlfl/operations/detail/vertex_merge.h>

#include <algorithm>

#include <dlfl/navigation.h>
#include <dlfl/operations/detail/refusal.h>

namespace dlfl::detail {

std::vector<VertexId> common_neighbours(const Mesh& mesh, VertexId u, VertexId v) {
  std::vector<VertexId> around_u;
  for (VertexId w : neighbours(mesh, u)) around_u.push_back(w);
  std::sort(around_u.begin(), around_u.end());
  std::vector<VertexId> common;
  for (VertexId w : neighbours(mesh, v)) {
    if (w != u && std::binary_search(around_u.begin(), around_u.end(), w)) common.push_back(w);
  }
  std::sort(common.begin(), common.end());
  common.erase(std::unique(common.begin(), common.end()), common.end());  // parallel edges name w twice
  return common;
}

std::string doubled_edges(const std::vector<VertexId>& common, const std::vector<VertexId>& apexes,
                          const char* ends) {
  if (common.size() <= apexes.size()) return {};
  const auto extra = std::find_if(common.begin(), common.end(), [&](VertexId w) {
    return std::find(apexes.begin(), apexes.end(), w) == apexes.end();
  });
  return std::string(ends) + " share " + count_of(common.size(), "neighbour") +
         ", the link condition allows " + std::to_string(apexes.size()) + "; the edges to " +
         to_string(*extra) + " would double up";
}

void append_hole_flags(const Mesh& mesh, CornerId first, CornerId stop, std::vector<bool>& flags) {
  for (CornerId c = first; c != stop; c = mesh.next_around_vertex(c))
    flags.push_back(mesh.is_hole(mesh.face(c)));
}

std::size_t hole_runs(const std::vector<bool>& cyclic_flags) {
  std::size_t runs = 0;
  const std::size_t n = cyclic_flags.size();
  for (std::size_t i = 0; i < n; ++i) runs += cyclic_flags[i] && !cyclic_flags[(i + n - 1) % n];
  return runs;
}

std::size_t hole_runs(const Mesh& mesh, VertexId v) {
  std::vector<bool> flags;
  for (CornerId c : mesh.corners(v)) flags.push_back(mesh.is_hole(mesh.face(c)));
  return hole_runs(flags);
}

}  // namespace dlfl::detail
