#!/usr/bin/env bash
# Regenerates the README's pictures in docs/images/ with the dlfl tool (build it first:
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

ls -l "$out"
