#!/usr/bin/env bash
# Runs the named fuzzers (default: every one with a seed corpus) built in BUILD for SECONDS each, starting from the committed seed corpus (copied
# into BUILD/fuzz-corpus, where the corpus grows between runs without touching the tree). Any crash,
# property violation, leak, timeout (>10 s per input) or out-of-memory (>2 GiB) fails the run; the
# input that caused it is kept under BUILD/fuzz-artifacts/<target>/. Prints the executions per target.
set -euo pipefail
build=${1:?usage: run_fuzzers.sh BUILD SECONDS [TARGET...]}
seconds=${2:?usage: run_fuzzers.sh BUILD SECONDS [TARGET...]}
here=$(cd "$(dirname "$0")" && pwd)
shift 2
targets=("$@")
[ ${#targets[@]} -gt 0 ] || for d in "$here"/corpus/fuzz_*; do targets+=("$(basename "$d")"); done
status=0
for target in "${targets[@]}"; do
  seeds="$here/corpus/$target"
  exe="$build/tests/fuzz/$target"
  [ -x "$exe" ] || { echo "fuzz: $target is not built in $build" >&2; exit 1; }
  corpus="$build/fuzz-corpus/$target"
  artifacts="$build/fuzz-artifacts/$target"
  mkdir -p "$corpus" "$artifacts"
  cp -n "$seeds"/* "$corpus"/ 2>/dev/null || true
  log="$build/fuzz-artifacts/$target.log"
  if "$exe" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 -print_final_stats=1 \
       -artifact_prefix="$artifacts/" "$corpus" >"$log" 2>&1; then
    runs=$(grep -o 'stat::number_of_executed_units: *[0-9]*' "$log" | grep -o '[0-9]*$' || echo '?')
    echo "fuzz: $target: $runs executions in ${seconds}s, no failure"
  else
    echo "fuzz: $target: FAILED (input kept in $artifacts); the end of its log:" >&2
    tail -n 30 "$log" >&2
    status=1
  fi
done
exit $status
