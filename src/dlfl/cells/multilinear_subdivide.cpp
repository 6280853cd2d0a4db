#include <dlfl/cells/multilinear_subdivide.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <limits>
#include <span>
#include <string>

#include <dlfl/cells/detail/vertex_set_map.h>
#include <dlfl/detail/block_cache.h>
#include <dlfl/detail/large_allocator.h>
#include <dlfl/errors.h>

namespace dlfl {

namespace {

// `v.reserve(n)` with a huge-page hint on the fresh buffer before anything is written to it: a
// million-cell result is otherwise faulted in 4 KiB at a time, which costs more than the subdivision.
template <class T>
void reserve_huge(std::vector<T>& v, std::size_t n) {
  v.reserve(n);
  detail::advise_huge_pages(v.data(), v.capacity() * sizeof(T));
}

// The 3^d grid of a split d-cube. Grid point g has coordinates c_i = (g / 3^i) % 3; its level is the number
// of coordinates equal to 1 (0: a corner of the cube, 1: an edge midpoint, 2: a face centre, 3: the centre),
// and it stands for the sub-face spanned by the corners k with bit i of k = c_i / 2 wherever c_i != 1.
struct GridPoint {
  std::uint8_t level = 0;
  std::uint8_t corners = 0;  // bit k set: corner k of the cube belongs to the sub-face
  std::uint8_t corner = 0;   // level 0: the corner itself
};

struct Grid {
  int points = 1;                                         // 3^d
  std::array<GridPoint, 27> point{};                      // by grid index
  std::array<std::array<std::uint8_t, 8>, 8> sub_cell{};  // [s][k]: grid index of corner k of sub-cell s
};

constexpr Grid make_grid(int d) {
  Grid grid;
  for (int i = 0; i < d; ++i) grid.points *= 3;
  for (int g = 0; g < grid.points; ++g) {
    GridPoint p;
    int fixed_bits = 0, free_mask = 0;
    for (int i = 0, rest = g; i < d; ++i, rest /= 3) {
      const int c = rest % 3;
      if (c == 1) {
        free_mask |= 1 << i;
        ++p.level;
      } else if (c == 2) {
        fixed_bits |= 1 << i;
      }
    }
    for (int k = 0; k < (1 << d); ++k) {
      if ((k & ~free_mask) == fixed_bits) p.corners = std::uint8_t(p.corners | (1 << k));
    }
    p.corner = std::uint8_t(fixed_bits);
    grid.point[g] = p;
  }
  for (int s = 0; s < (1 << d); ++s) {
    for (int k = 0; k < (1 << d); ++k) {
      int g = 0;
      for (int i = 0, stride = 1; i < d; ++i, stride *= 3) g += (((s >> i) & 1) + ((k >> i) & 1)) * stride;
      grid.sub_cell[s][k] = std::uint8_t(g);
    }
  }
  return grid;
}

constexpr std::array<Grid, 4> grids{make_grid(0), make_grid(1), make_grid(2), make_grid(3)};

// The corners of a cell sorted by vertex index, so that the sorted vertex set of any sub-face is a filter.
struct SortedCell {
  std::array<std::uint32_t, 8> vertex{};
  std::array<std::uint8_t, 8> corner{};
  int size = 0;

  explicit SortedCell(std::span<const std::uint32_t> cell) : size(int(cell.size())) {
    for (int k = 0; k < size; ++k) {  // insertion sort: at most 8 entries
      int j = k;
      for (; j > 0 && vertex[j - 1] > cell[k]; --j) {
        vertex[j] = vertex[j - 1];
        corner[j] = corner[j - 1];
      }
      vertex[j] = cell[k];
      corner[j] = std::uint8_t(k);
    }
  }
  std::uint32_t smallest(std::uint8_t corners) const {
    for (int j = 0;; ++j) {
      if ((corners >> corner[j]) & 1) return vertex[j];
    }
  }
  template <std::size_t K>
  std::array<std::uint32_t, K> key(std::uint8_t corners) const {
    std::array<std::uint32_t, K> key{};
    for (int j = 0, n = 0; j < size; ++j) {
      if ((corners >> corner[j]) & 1) key[n++] = vertex[j];
    }
    return key;
  }
};

[[noreturn]] void too_large(const char* what, std::uint64_t count) {
  throw InvalidArgument("multilinear subdivision: the result would have " + std::to_string(count) + " " +
                        what + ", more than 32-bit indices can address");
}

}  // namespace

CellComplex multilinear_subdivide(const CellComplex& complex) {
  check_cell_complex(complex);
  return detail::multilinear_subdivide_unchecked(complex);
}

CellComplex detail::multilinear_subdivide_unchecked(const CellComplex& in) {
  const std::size_t nv = in.positions.size();
  const std::size_t nc = in.num_cells();

  // Pass 1: the output size, and for each level how many sub-face occurrences start with each vertex (this
  // sizes the hash of that level).
  std::array<LargeVector<std::uint32_t>, 3> starts_with;
  int max_dimension = 0;
  for (std::size_t i = 0; i < nc; ++i) max_dimension = std::max(max_dimension, in.dimension(i));
  for (int level = 1; level <= max_dimension; ++level) starts_with[level - 1].assign(nv, 0);
  std::uint64_t out_cells = 0, out_indices = 0, occurrences = 0;
  for (std::size_t i = 0; i < nc; ++i) {
    const auto cell = in.cell(i);
    const int d = in.dimension(i);
    out_cells += std::uint64_t(1) << d;
    out_indices += std::uint64_t(1) << (2 * d);
    if (d == 0) continue;
    const SortedCell sorted(cell);
    const Grid& grid = grids[d];
    for (int g = 0; g < grid.points; ++g) {
      const GridPoint& p = grid.point[g];
      if (p.level == 0) continue;
      ++starts_with[p.level - 1][sorted.smallest(p.corners)];
      ++occurrences;
    }
  }
  constexpr std::uint64_t limit = std::numeric_limits<std::uint32_t>::max();
  if (out_indices > limit) too_large("cell vertex indices", out_indices);
  if (nv + occurrences > limit) too_large("vertices (at most)", nv + occurrences);

  detail::VertexSetMap<2> edges(starts_with[0]);
  detail::VertexSetMap<4> faces(starts_with[1]);
  detail::VertexSetMap<8> cubes(starts_with[2]);

  CellComplex out;
  reserve_huge(out.positions, nv + occurrences);  // an upper bound: shared sub-faces count once per cell
  out.positions.assign(in.positions.begin(), in.positions.end());
  reserve_huge(out.offsets, out_cells + 1);
  out.offsets.resize(out_cells + 1);
  reserve_huge(out.indices, out_indices);
  out.indices.resize(out_indices);

  // Pass 2: the vertex of every grid point of every cell (new ones at the first meeting), then the sub-cells.
  std::uint32_t* offset = out.offsets.data();
  std::uint32_t* index = out.indices.data();
  *offset++ = 0;
  std::uint32_t written = 0;
  for (std::size_t i = 0; i < nc; ++i) {
    const auto cell = in.cell(i);
    const int d = in.dimension(i);
    const Grid& grid = grids[d];
    const SortedCell sorted(cell);
    std::array<std::uint32_t, 27> vertex_at;
    for (int g = 0; g < grid.points; ++g) {
      const GridPoint& p = grid.point[g];
      if (p.level == 0) {
        vertex_at[g] = cell[p.corner];
        continue;
      }
      const auto next = static_cast<std::uint32_t>(out.positions.size());
      glm::dvec3 sum(0.0);
      std::uint32_t found = 0;
      if (p.level == 1) {
        const auto key = sorted.key<2>(p.corners);
        found = edges.insert(key, next);
        if (found == next) sum = in.positions[key[0]] + in.positions[key[1]];
      } else if (p.level == 2) {
        const auto key = sorted.key<4>(p.corners);
        found = faces.insert(key, next);
        if (found == next) {
          for (std::uint32_t v : key) sum += in.positions[v];
        }
      } else {
        const auto key = sorted.key<8>(p.corners);
        found = cubes.insert(key, next);
        if (found == next) {
          for (std::uint32_t v : key) sum += in.positions[v];
        }
      }
      if (found == next) out.positions.push_back(sum / double(1 << p.level));
      vertex_at[g] = found;
    }
    const int n = 1 << d;
    for (int s = 0; s < n; ++s) {
      for (int k = 0; k < n; ++k) *index++ = vertex_at[grid.sub_cell[s][k]];
      written += static_cast<std::uint32_t>(n);
      *offset++ = written;
    }
  }
  return out;
}

}  // namespace dlfl
