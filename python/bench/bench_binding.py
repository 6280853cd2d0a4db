"""Benchmark of the Python binding against its targets (docs/python.md, "Speed"):

- Mesh.from_arrays of a 1M-face closed quad mesh (a 1000 x 1000 torus) in under 0.5 s;
- mesh.positions of a 1M-vertex mesh in under 1 ms (a view, not a copy);
- a Python loop of 100,000 ed.insert_edge calls within 20x the same calls from C++, measured in the same run
  by build/bin/dlfl_bench_binding_baseline on the same torus (the diagonal of face f: corners 4f and 4f + 2).

The baseline program also times build_mesh on the 1M-face torus, the C++ share of Mesh.from_arrays, so that
a loaded machine shows in both figures.

Usage: PYTHONPATH=build/python python3 python/bench/bench_binding.py [build/bin] [runs=5]
Prints the best and median of the runs; the best is the cleanest figure on a shared machine.
"""

import pathlib
import statistics
import subprocess
import sys
import time

import numpy as np

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parents[1] / "tests"))
from meshes import torus_arrays  # noqa: E402 (the tests' torus, laid out as bench/bench_meshes.h's)

import dlfl  # noqa: E402

BIN = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else "build/bin")
RUNS = int(sys.argv[2]) if len(sys.argv) > 2 else 5


def timed(f, runs=RUNS):
    seconds = []
    for _ in range(runs):
        start = time.perf_counter()
        f()
        seconds.append(time.perf_counter() - start)
    return min(seconds), statistics.median(seconds)


def seconds(s):
    return f"{s * 1e6:9.2f} us" if s < 1e-3 else f"{s:9.4f} s "


def report(what, best, median, target=None):
    verdict = "" if target is None else f"  target < {seconds(target).strip()}: {'met' if best < target else 'MISSED'}"
    print(f"{what:50s} best {seconds(best)}  median {seconds(median)}{verdict}")




def baseline(*args):
    """Best and median seconds of build/bin/dlfl_bench_binding_baseline ARGS RUNS."""
    done = subprocess.run([str(BIN / "dlfl_bench_binding_baseline"), *map(str, args), str(RUNS)],
                          capture_output=True, text=True, check=True)
    words = done.stdout.split()
    return float(words[words.index("best") + 1]), float(words[words.index("median") + 1])


positions, faces = torus_arrays(1000, 1000)
best, median = timed(lambda: dlfl.Mesh.from_arrays(positions, faces))
report("Mesh.from_arrays, 1M quads ((F, 4) int64)", best, median, 0.5)
offsets = np.arange(0, 4 * len(faces) + 1, 4)
best, median = timed(lambda: dlfl.Mesh.from_arrays(positions, (offsets, faces.ravel())))
report("Mesh.from_arrays, 1M quads (offsets, indices)", best, median, 0.5)
report("  for scale: C++ build_mesh of the same polygons", *baseline("build", 1000, 1000))

mesh = dlfl.Mesh.from_arrays(positions, faces)
assert mesh.num_vertices == 1_000_000 and np.shares_memory(mesh.positions, mesh.positions)
reads = 1000
best, median = timed(lambda: [mesh.positions for _ in range(reads)])
report(f"mesh.positions, 1M vertices (per read, of {reads})", best / reads, median / reads, 1e-3)
best, median = timed(lambda: mesh.positions.sum())
report("  for scale: summing those positions", best, median)

calls, n, m = 100_000, 400, 250
torus = dlfl.Mesh.from_arrays(*torus_arrays(n, m))


def python_loop():
    ed = dlfl.Editor(torus)
    start = time.perf_counter()
    for f in range(calls):
        ed.insert_edge(4 * f, 4 * f + 2)
    elapsed = time.perf_counter() - start
    assert ed.mesh.num_edges == torus.num_edges + calls
    return elapsed


loop = sorted(python_loop() for _ in range(RUNS))
report(f"Python: {calls} ed.insert_edge calls", loop[0], statistics.median(loop))
cpp_best, cpp_median = baseline("insert_edge", calls, n, m)
report(f"C++:    {calls} Editor::insert_edge calls", cpp_best, cpp_median)
ratio = loop[0] / cpp_best
print(f"{'Python / C++ (best runs)':50s} {ratio:.1f}x  target within 20x: {'met' if ratio <= 20 else 'MISSED'}")
