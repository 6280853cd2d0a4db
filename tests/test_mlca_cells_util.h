#pragma once
// Cell complexes and independent re-derivations of the MLCA paper's formulas, shared by the MLCA cell tests.

#include <doctest/doctest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <functional>
#include <glm/geometric.hpp>
#include <random>
#include <vector>

#include <dlfl/cells/cell_complex.h>
#include <dlfl/cells/mlca_subdivide.h>

namespace dlfl::test {

/// Vertex (i, j, k) of an (nx+1) x (ny+1) x (nz+1) lattice.
inline std::uint32_t lattice_index(int nx, int ny, int i, int j, int k) {
  return std::uint32_t(i + (nx + 1) * (j + (ny + 1) * k));
}

/// An nx x ny x nz grid of hexahedra; vertex (i,j,k) at `place(i,j,k)`, hexahedron corner b at vertex
/// (i + b0, j + b1, k + b2) (tensor-product order, bits of b).
inline CellComplex hex_grid(int nx, int ny, int nz, const std::function<glm::dvec3(int, int, int)>& place) {
  CellComplex c;
  for (int k = 0; k <= nz; ++k) {
    for (int j = 0; j <= ny; ++j) {
      for (int i = 0; i <= nx; ++i) c.positions.push_back(place(i, j, k));
    }
  }
  for (int k = 0; k < nz; ++k) {
    for (int j = 0; j < ny; ++j) {
      for (int i = 0; i < nx; ++i) {
        std::vector<std::uint32_t> hex;
        for (int b = 0; b < 8; ++b)
          hex.push_back(lattice_index(nx, ny, i + (b & 1), j + (b >> 1 & 1), k + (b >> 2)));
        c.add_cell(hex);
      }
    }
  }
  return c;
}

/// Lattice positions with a deterministic random perturbation, so that no rule holds by symmetry alone.
inline std::function<glm::dvec3(int, int, int)> jittered_lattice(unsigned seed, double amount = 0.2) {
  return [seed, amount](int i, int j, int k) {
    std::mt19937 rng(seed + 7919u * unsigned(i) + 104729u * unsigned(j) + 1299709u * unsigned(k));
    std::uniform_real_distribution<double> u(-amount, amount);
    return glm::dvec3(i + u(rng), j + u(rng), k + u(rng));
  };
}

/// The cubic B-spline refinement weights of fine index I on the coarse indices: even I = 2i gives
/// (1/8, 3/4, 1/8) on i-1, i, i+1; odd I = 2i+1 gives (1/2, 1/2) on i, i+1. Returns (coarse index, weight).
inline std::vector<std::pair<int, double>> bspline_refinement(int fine) {
  if (fine % 2 == 0) return {{fine / 2 - 1, 0.125}, {fine / 2, 0.75}, {fine / 2 + 1, 0.125}};
  return {{fine / 2, 0.5}, {fine / 2 + 1, 0.5}};
}

/// One MLCA step as a matrix: entry [out][in] is the weight of input vertex `in` in output vertex `out`, read
/// off by running the code on unit vectors (positions e_in in the x coordinate).
inline std::vector<std::vector<double>> subdivision_matrix(const CellComplex& complex,
                                                           const std::vector<std::uint32_t>& out_rows,
                                                           const std::vector<std::uint32_t>& in_cols) {
  std::vector<std::vector<double>> s(out_rows.size(), std::vector<double>(in_cols.size(), 0.0));
  CellComplex unit = complex;
  for (std::size_t j = 0; j < in_cols.size(); ++j) {
    for (auto& p : unit.positions) p = glm::dvec3(0.0);
    unit.positions[in_cols[j]] = glm::dvec3(1.0, 0.0, 0.0);
    const CellComplex out = mlca_subdivide(unit);
    for (std::size_t i = 0; i < out_rows.size(); ++i) s[i][j] = out.positions[out_rows[i]].x;
  }
  return s;
}

/// Formula (2) of the paper, re-derived from the definitions for a complex of d-cubes: the weight of u in the
/// new position of v is 3^(d - dim[u,v]) val[u,v] / (4^d val[v]), where val[u,v] counts the cells holding
/// both and dim[u,v] is the dimension of the smallest face of such a cell holding both (the number of axes on
/// which their tensor-product positions differ). Returns the weight of every vertex (0 outside ring[v]).
inline std::vector<double> formula2_weights(const CellComplex& complex, std::uint32_t v) {
  std::vector<double> val_uv(complex.positions.size(), 0.0);
  std::vector<int> dim_uv(complex.positions.size(), -1);
  int d = -1;
  double val_v = 0;
  for (std::size_t i = 0; i < complex.num_cells(); ++i) {
    const auto cell = complex.cell(i);
    int kv = -1;
    for (std::size_t k = 0; k < cell.size(); ++k) {
      if (cell[k] == v) kv = int(k);
    }
    if (kv < 0) continue;
    d = complex.dimension(i);
    val_v += 1;
    for (std::size_t k = 0; k < cell.size(); ++k) {
      val_uv[cell[k]] += 1;
      dim_uv[cell[k]] = std::popcount(unsigned(k) ^ unsigned(kv));
    }
  }
  std::vector<double> w(complex.positions.size(), 0.0);
  for (std::size_t u = 0; u < w.size(); ++u) {
    if (val_uv[u] > 0) w[u] = std::pow(3.0, d - dim_uv[u]) * val_uv[u] / (std::pow(4.0, d) * val_v);
  }
  return w;
}

/// The index of the vertex at `p` (to 1e-12); fails the test unless there is exactly one.
inline std::uint32_t vertex_at(const CellComplex& complex, const glm::dvec3& p) {
  std::uint32_t found = 0, count = 0;
  for (std::size_t v = 0; v < complex.positions.size(); ++v) {
    if (glm::length(complex.positions[v] - p) < 1e-12) {
      found = std::uint32_t(v);
      ++count;
    }
  }
  REQUIRE(count == 1);
  return found;
}

}  // namespace dlfl::test
