#!/usr/bin/env bash
# Runs the three main benchmarks of two builds side by side, alternating, on the same machine: the figures a
# change's "before/after" needs. Outputs go to OUT (default a new mktemp -d), one file per run.
#
#   bench/compare_builds.sh BEFORE_BIN AFTER_BIN [ROUNDS]
#
# BEFORE_BIN and AFTER_BIN are folders holding dlfl_bench_kernel, dlfl_bench_honeycomb, dlfl_bench_schemes
# (build/bin of each build). Run it on a quiet machine; each round runs before, then after.
set -euo pipefail
before=$1
after=$2
rounds=${3:-2}
out=${OUT:-$(mktemp -d "${TMPDIR:-/tmp}/dlfl-compare.XXXXXX")}
mkdir -p "$out"
for round in $(seq "$rounds"); do
  for side in before after; do
    if [ "$side" = before ]; then bin=$before; else bin=$after; fi
    "$bin/dlfl_bench_kernel" 1000000 5 >"$out/kernel_${side}_$round.txt" 2>&1
    "$bin/dlfl_bench_honeycomb" 7 >"$out/honeycomb_${side}_$round.txt" 2>&1
    "$bin/dlfl_bench_schemes" 7 >"$out/schemes_${side}_$round.txt" 2>&1
  done
done
echo "outputs in $out"
