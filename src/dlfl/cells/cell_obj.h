#pragma once
// Wavefront OBJ for cell complexes: `v` positions, `p` points (0-cells), `l` polylines (split into 1-cells)
// and `f` quads (2-cells). See docs/mlca_formats.md.

#include <iosfwd>
#include <string>
#include <string_view>

#include <dlfl/cells/cell_complex.h>

namespace dlfl {

/// Parses OBJ text held in memory (`name` is used in error messages). `v x y z` adds a position (further
/// values on the line are ignored); `p i j ...` adds one 0-cell per index; `l i j k ...` adds the segments
/// (i,j), (j,k), ...; `f a b c d` adds a quad, its cyclic order mapped to tensor order (a, b, d, c). Indices
/// start at 1, may be negative (relative to the vertices read so far) and may carry `/vt/vn` suffixes; other
/// statements are ignored. Throws IoError with the file and line for a face without exactly 4 vertices (a
/// cell complex holds quads; split polygons on the DLFL side), a line with fewer than 2 vertices, an empty
/// `p`, an index out of range, a vertex repeated within a cell and a bad or non-finite number.
CellComplex parse_cell_obj(std::string_view text, const std::string& name);

/// Writes `v` lines (shortest decimals that read back bit-identical), then one statement per cell in order:
/// `p i`, `l i j`, or `f a b d c` for the tensor-ordered quad (a, b, c, d). Throws IoError before writing
/// anything if the complex has a hexahedron (OBJ has no volume element; write .vtk), InvalidArgument if
/// `check_cell_complex` fails.
void write_cell_obj(std::ostream& out, const CellComplex& complex);

/// True if the OBJ text has a `p` or `l` statement: a curve network or a complex with creases, which the
/// DLFL (a 2-manifold of polygons) cannot hold.
bool obj_has_cell_statements(std::string_view text);

}  // namespace dlfl
