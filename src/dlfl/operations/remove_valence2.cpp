// remove_valence2: see remove_valence2.h.

#include <dlfl/operations/remove_valence2.h>

#include <vector>

#include <dlfl/operations/detail/operation_table.h>
#include <dlfl/operations/detail/valence2_join.h>

namespace dlfl {

std::size_t remove_valence2(Transaction& tx) {
  const std::vector<VertexId> all(tx.mesh().vertices().begin(), tx.mesh().vertices().end());
  return detail::join_valence2_vertices(tx, all);
}

std::vector<OperationSpec> detail::remove_valence2_operation_specs() {
  return {counting_operation(
      "remove_valence2",
      "joins the two edges of every vertex of valence 2 (unless that would make a self-loop "
      "or a double edge with no 2-gon between)",
      "V-k, E-k, F+0 for k vertices joined", "vertices_removed", &remove_valence2)};
}
}  // namespace dlfl
