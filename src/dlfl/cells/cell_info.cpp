#include <dlfl/cells/cell_info.h>

#include <glm/common.hpp>
#include <nlohmann/json.hpp>

namespace dlfl {

std::string cell_complex_info_json(const CellComplex& complex, int indent) {
  std::size_t per_dimension[4] = {0, 0, 0, 0};
  for (std::size_t i = 0; i < complex.num_cells(); ++i) {
    const int d = complex.dimension(i);
    if (d >= 0) ++per_dimension[d];  // a cell of another size fails check_cell_complex; not counted here
  }
  glm::dvec3 lo(0.0), hi(0.0);
  for (std::size_t v = 0; v < complex.positions.size(); ++v) {
    lo = v == 0 ? complex.positions[v] : glm::min(lo, complex.positions[v]);
    hi = v == 0 ? complex.positions[v] : glm::max(hi, complex.positions[v]);
  }
  nlohmann::ordered_json j;
  j["vertices"] = complex.positions.size();
  j["cells"] = complex.num_cells();
  j["cells_by_dimension"] = {
      {"0", per_dimension[0]}, {"1", per_dimension[1]}, {"2", per_dimension[2]}, {"3", per_dimension[3]}};
  j["bbox"] = {{lo.x, lo.y, lo.z}, {hi.x, hi.y, hi.z}};
  return j.dump(indent);
}

}  // namespace dlfl
