#!/usr/bin/env bash
# Builds the libFuzzer harnesses (in build-fuzz, configured if needed) and runs each for SECONDS (default 30)
# on its seed corpus and regression inputs, with a fresh output corpus outside the repository. Prints each
# harness's executions (libFuzzer's final stat::number_of_executed_units, -print_final_stats=1) and fails if
# any harness finds something.
#
#   tests/fuzz/run_fuzzers.sh [SECONDS] [HARNESS ...]
#
# Environment: DLFL_FUZZ_BUILD (build folder, default build-fuzz), DLFL_FUZZ_OUT (output folder, default a
# new mktemp -d), DLFL_FUZZ_JOBS (harnesses run at the same time, default 1: each takes one core). New inputs
# are left in OUT/NAME/ for merging by hand (docs/fuzzing.md); a finding leaves OUT/NAME-crash-...,
# -timeout-... or -oom-... and the log OUT/NAME.log.
set -euo pipefail
cd "$(dirname "$0")/../.."
seconds=${1:-30}
shift || true
build=${DLFL_FUZZ_BUILD:-build-fuzz}
if [ ! -f "$build/CMakeCache.txt" ]; then
  # -O1, as libFuzzer's documentation builds its examples: the instrumented library compiles in far less time
  # than at -O3, and runs about as fast.
  cmake -S . -B "$build" -DCMAKE_CXX_COMPILER=clang++-14 -DDLFL_FUZZ=ON -DDLFL_SANITIZE=address,undefined \
    -DCMAKE_BUILD_TYPE=Release "-DCMAKE_CXX_FLAGS_RELEASE=-O1 -DNDEBUG" -DDLFL_BUILD_TESTS=OFF \
    -DDLFL_BUILD_TOOLS=OFF -DDLFL_BUILD_BENCH=OFF -DDLFL_BUILD_EXAMPLES=OFF
fi
cmake --build "$build" -j2
out=${DLFL_FUZZ_OUT:-$(mktemp -d "${TMPDIR:-/tmp}/dlfl-fuzz.XXXXXX")}
mkdir -p "$out"
if [ $# -gt 0 ]; then
  harnesses="$*"
else
  harnesses=$(cd tests/fuzz && ls -- *.cpp | sed 's/\.cpp$//')
fi

# The largest input of each harness (the harness itself skips longer ones; docs/fuzzing.md, "Caps").
max_len() {
  case $1 in
    oplog) echo 16384 ;;
    scheme_params | edit_op) echo 4096 ;;
    mhp_pattern) echo 1024 ;;
    *) echo 65536 ;;
  esac
}

# Runs one harness; its result line goes to OUT/NAME.result.
run_one() {
  local h=$1
  rm -rf "${out:?}/$h"
  mkdir -p "$out/$h"
  local inputs=("$out/$h" "tests/fuzz/corpus/$h")  # the first folder receives the new inputs
  [ -d "tests/fuzz/regressions/$h" ] && inputs+=("tests/fuzz/regressions/$h")
  local options=(-max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 -max_len="$(max_len "$h")"
                 -print_final_stats=1 -artifact_prefix="$out/$h-")
  [ -f "tests/fuzz/$h.dict" ] && options+=(-dict="tests/fuzz/$h.dict")
  local start status=0 executions
  start=$(date +%s)
  "$build/bin/dlfl_fuzz_$h" "${options[@]}" "${inputs[@]}" >"$out/$h.log" 2>&1 || status=$?
  executions=$(sed -n 's/^stat::number_of_executed_units: *//p' "$out/$h.log" | tail -1)
  {
    printf '%-14s %12s %8s' "$h" "${executions:-?}" "$(($(date +%s) - start))"
    if [ $status -ne 0 ]; then
      printf '  FAILED (exit %s): see %s\n' "$status" "$out/$h.log"
      grep -E 'ERROR|SUMMARY|dlfl fuzz finding|terminate called|Test unit written' "$out/$h.log" | head -5 || true
    else
      printf '\n'
    fi
  } >"$out/$h.result"
  return $status
}

# DLFL_FUZZ_JOBS harnesses at a time (default 1); each is one process on one core.
jobs=${DLFL_FUZZ_JOBS:-1}
running=0
for h in $harnesses; do
  rm -f "$out/$h.result"
  run_one "$h" &
  running=$((running + 1))
  if [ "$running" -ge "$jobs" ]; then
    wait -n || true
    running=$((running - 1))
  fi
done
wait || true

failed=""
printf '%-14s %12s %8s\n' harness executions seconds
for h in $harnesses; do
  cat "$out/$h.result"
  grep -q FAILED "$out/$h.result" && failed="$failed $h"
done
echo "output corpus and logs: $out"
if [ -n "$failed" ]; then
  echo "fuzzing found something in:$failed"
  exit 1
fi
