#!/usr/bin/env bash
# Regenerates the pictures of the README and the docs in docs/images/ with the dlfl tool (build it first:
# cmake --build build -j2 --target dlfl_tool). Usage: docs/make_images.sh [path/to/dlfl]
set -euo pipefail
cd "$(dirname "$0")/.."
dlfl=${1:-build/bin/dlfl}
out=docs/images
scratch=$(mktemp -d)
trap 'rm -rf "$scratch"' EXIT

# The dodecahedron through three honeycomb steps: pentagons stay, everything else turns into hexagons.
"$dlfl" render data/dodecahedron.obj -s honeycomb -n 3 --size 260x260 -o "$out/dodecahedron_honeycomb.png"

# A modelling session, one picture per logged operation: a cube, an extrusion, three handles, Catmull-Clark.
"$dlfl" render data/genus3_handles.log.json --steps --size 260x260 -o "$out/genus3_handles.png"

# The modelling examples (issue 12): the rind lantern (a shell with six windows, genus 5) and the wireframe
# dodecahedron (its edges as rounded beams, genus 11), each replayed from its log.
"$dlfl" replay data/rind_lantern.log.json -o "$scratch/rind_lantern.json"
"$dlfl" render "$scratch/rind_lantern.json" --size 400x400 -o "$out/rind_lantern.png"
"$dlfl" replay data/wireframe_dodecahedron.log.json -o "$scratch/wireframe_dodecahedron.json"
"$dlfl" render "$scratch/wireframe_dodecahedron.json" --size 400x400 -o "$out/wireframe_dodecahedron.png"

# Meng-Prautzsch MHP (honeycomb then corner pushing) on the dodecahedron, two applications.
"$dlfl" render data/dodecahedron.obj -s mhp -n 2 --size 260x260 -o "$out/dodecahedron_mhp.png"

# MLCA on a hexahedral volume: an L-shaped block of three hexahedra, two steps (its boundary quads drawn).
cat > "$scratch/l_block.vtk" <<'VTK'
# vtk DataFile Version 3.0
an L-shaped block of three hexahedra
ASCII
DATASET UNSTRUCTURED_GRID
POINTS 18 double
0 0 0
1 0 0
2 0 0
0 1 0
1 1 0
2 1 0
0 2 0
1 2 0
2 2 0
0 0 1
1 0 1
2 0 1
0 1 1
1 1 1
2 1 1
0 2 1
1 2 1
2 2 1
CELLS 3 27
8 0 1 4 3 9 10 13 12
8 1 2 5 4 10 11 14 13
8 3 4 7 6 12 13 16 15
CELL_TYPES 3
12
12
12
VTK
"$dlfl" render "$scratch/l_block.vtk" -s mlca -n 2 --size 260x260 -o "$out/l_block_mlca.png"

# The lateral artifacts (docs/lateral_artifacts.md): the hexagonal prism of radius 1 and height 3 with 3 rows
# of quads per side (y up), after 4 honeycomb steps, plain, with planarize=1, and after hexagonalize; the
# faces beside a concave edge in red (--color-by concave).
awk 'BEGIN { n = 6; rows = 3; pi = atan2(0, -1)
  for (z = 0; z <= rows; ++z) for (i = 0; i < n; ++i) printf "v %.17g %.17g %.17g\n", sin(2*pi*i/n), 3*z/rows, cos(2*pi*i/n)
  printf "f"; for (i = n; i >= 1; --i) printf " %d", i; printf "\n"
  printf "f"; for (i = 1; i <= n; ++i) printf " %d", rows*n + i; printf "\n"
  for (z = 0; z < rows; ++z) for (i = 0; i < n; ++i)
    printf "f %d %d %d %d\n", z*n + i + 1, z*n + (i+1)%n + 1, (z+1)*n + (i+1)%n + 1, (z+1)*n + i + 1 }' > "$scratch/prism.obj"
"$dlfl" edit "$scratch/prism.obj" -o "$scratch/prism_hex.json" --op hexagonalize
lateral=(--size 240x300 --azimuth 15 --elevation 10 --color-by concave)
"$dlfl" subdivide "$scratch/prism.obj" -s honeycomb -n 4 -o "$scratch/plain.json"
"$dlfl" render "$scratch/plain.json" "${lateral[@]}" -o "$out/lateral_plain.png"
"$dlfl" subdivide "$scratch/prism.obj" -s honeycomb -n 4 --param planarize=1 -o "$scratch/planarized.json"
"$dlfl" render "$scratch/planarized.json" "${lateral[@]}" -o "$out/lateral_planarize.png"
"$dlfl" subdivide "$scratch/prism_hex.json" -s honeycomb -n 4 -o "$scratch/hexagonalized.json"
"$dlfl" render "$scratch/hexagonalized.json" "${lateral[@]}" -o "$out/lateral_hexagonalize.png"

ls -l "$out"
