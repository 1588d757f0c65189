#!/usr/bin/env bash
# Runs the named fuzzers (default: every one with a seed corpus) built in BUILD for SECONDS each, starting from the committed seed corpus (copied
# into BUILD/fuzz-corpus, where the corpus grows between runs without touching the tree). Any crash,
# property violation, leak, timeout (>10 s per input) or out-of-memory (>2 GiB) fails the run; the
# input that caused it is kept under BUILD/fuzz-artifacts/<target>/. Prints the executions per target.
# FUZZ_JOBS targets (default: the number of cores) run at once, each on its own core.
set -euo pipefail
build=${1:?usage: run_fuzzers.sh BUILD SECONDS [TARGET...]}
seconds=${2:?usage: run_fuzzers.sh BUILD SECONDS [TARGET...]}
here=$(cd "$(dirname "$0")" && pwd)
shift 2
targets=("$@")
[ ${#targets[@]} -gt 0 ] || for d in "$here"/corpus/fuzz_*; do targets+=("$(basename "$d")"); done
# One target: prepare its corpus, run it, report. Returns non-zero on a failure.
run_one() {
  local target=$1
  local seeds="$here/corpus/$target"
  local exe="$build/tests/fuzz/$target"
  [ -x "$exe" ] || { echo "fuzz: $target is not built in $build" >&2; return 1; }
  local corpus="$build/fuzz-corpus/$target"
  local artifacts="$build/fuzz-artifacts/$target"
  mkdir -p "$corpus" "$artifacts"
  cp -n "$seeds"/* "$corpus"/ 2>/dev/null || true
  local log="$build/fuzz-artifacts/$target.log"
  if "$exe" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 -print_final_stats=1 \
       -artifact_prefix="$artifacts/" "$corpus" >"$log" 2>&1; then
    local runs
    runs=$(grep -o 'stat::number_of_executed_units: *[0-9]*' "$log" | grep -o '[0-9]*$' || echo '?')
    echo "fuzz: $target: $runs executions in ${seconds}s, no failure"
  else
    echo "fuzz: $target: FAILED (input kept in $artifacts); the end of its log:" >&2
    tail -n 30 "$log" >&2
    return 1
  fi
}

jobs=${FUZZ_JOBS:-$(nproc)}
status=0
pids=()
for target in "${targets[@]}"; do
  run_one "$target" &
  pids+=($!)
  if [ ${#pids[@]} -ge "$jobs" ]; then
    wait "${pids[0]}" || status=1
    pids=("${pids[@]:1}")
  fi
done
for pid in "${pids[@]}"; do wait "$pid" || status=1; done
exit $status
