#!/usr/bin/env bash
# run_on_gpu.sh: runs inside a bundle made by tests/gpu/pack_bundle.sh, on a machine with a Vulkan ICD (an
# NVIDIA driver) and none of the Vulkan packages. Writes everything under $OUT (default ./gpu-out):
#   run.log            progress, as printed
#   env.txt            machine, driver (nvidia-smi), environment, library checks (preflight)
#   info.log/.json     `hairpipe info`; loader_debug.log: the loader's driver and layer search
#   bench/*.json       `hairpipe bench` (compute path, 20k/136k/1M strands at 1920x1080, 136k at 1280x720)
#                      and the suites sim, strands, opacity, instances; bench/*.log their stderr/stdout;
#                      bench/peer/: vkhr's setting on straight models of 10k and 136k strands (vkhr_setting.sh)
#   tests/results.tsv  suite, test, PASS|FAIL|TIMEOUT|SKIP|NOTRUN, exit code, seconds; tests/logs/SUITE/TEST.log
#   steps.tsv          each step: name, status, exit code, seconds
#   summary.txt/.json  passed/failed counts, the failed tests, the steps; ends with "N passed, N failed"
#   performance_rows.md  markdown rows for docs/PERFORMANCE.md: frame ms and the main passes per case
# Every part has a timeout taken from one budget (HP_GPU_BUDGET_S, default 450 s: the benches may use up
# to HP_GPU_BENCH_BUDGET_S of it, default 240 s, the tests the rest); one part failing never stops the others.
# Each test runs in its own process, HP_GPU_JOBS (8) at a time: one failing test cannot take others with it,
# and the tests run in parallel (a whole suite in one process runs since headless contexts share one
# instance; before, the NVIDIA driver refused the 30th instance of a process).
#
# Settings (environment):
#   OUT                  output folder (created)
#   HP_GPU_QUICK=1       tiny sizes, a few tests, short timeouts: for trying the bundle on lavapipe
#   HP_ICD               the ICD JSON (default /usr/local/nvidia/share/vulkan/icd.d/nvidia_icd.json)
#   HP_DRIVER_LIB_DIRS   the driver's library folders, ':'-separated (default /usr/local/nvidia/lib64:/usr/local/nvidia/lib)
#   HP_GPU_BUDGET_S, HP_GPU_BENCH_BUDGET_S, HP_GPU_TEST_TIMEOUT_S (per test), HP_GPU_JOBS
#   HP_GPU_TEST_FILTER   extended regex on "suite<TAB>Test.Name" lines: only these run
#   HP_GPU_TEST_EXCLUDE  extended regex of tests left out (default: the tests that start `hairpipe view` under
#                        Xvfb, which the GPU machine does not have: CliView.* and
#                        CliCharacterMesh.AClipPlaysInRenderSimulateAndView)
#   HP_GPU_SKIP_BENCH=1, HP_GPU_SKIP_TESTS=1   leave a part out
#   HP_GPU_EXTRA         a bash file sourced after the benches, before the tests (profiling runs): it may call
#                        `step NAME CAP DEADLINE STDOUT_FILE CMD...` and use $H (hairpipe), $W (the unpacked
#                        bundle: bin/ holds any HP_PACK_EXTRA_BINS), $OUT, $BENCH_DEADLINE and $DEADLINE. It runs
#                        in this shell under `set -u`: an unset variable or an `exit` in it ends the whole run
#                        (no tests, no summary). tests/gpu/compare_binaries.sh is one.
#   HP_WORK              where the bundle is unpacked (default $TMPDIR or /tmp, hairpipe-gpu-PID; removed at the end
#                        unless HP_KEEP_WORK=1)
#   HP_FORCE_FALLBACK=1  use the bundled libstdc++/libgcc_s even where the machine's are new enough
set -u
set -o pipefail

BUNDLE=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
OUT=${OUT:-$PWD/gpu-out}
mkdir -p "$OUT" && OUT=$(cd "$OUT" && pwd)
QUICK=${HP_GPU_QUICK:-0}
START=$(date +%s)
if [ "$QUICK" = 1 ]; then
  BUDGET=${HP_GPU_BUDGET_S:-900}; BENCH_BUDGET=${HP_GPU_BENCH_BUDGET_S:-420}
  TEST_TIMEOUT=${HP_GPU_TEST_TIMEOUT_S:-240}; JOBS=${HP_GPU_JOBS:-2}
else
  BUDGET=${HP_GPU_BUDGET_S:-450}; BENCH_BUDGET=${HP_GPU_BENCH_BUDGET_S:-240}
  TEST_TIMEOUT=${HP_GPU_TEST_TIMEOUT_S:-120}; JOBS=${HP_GPU_JOBS:-8}
fi
DEADLINE=$((START + BUDGET))
BENCH_DEADLINE=$((START + BENCH_BUDGET))
ICD=${HP_ICD:-/usr/local/nvidia/share/vulkan/icd.d/nvidia_icd.json}
DRIVER_LIBS=${HP_DRIVER_LIB_DIRS-/usr/local/nvidia/lib64:/usr/local/nvidia/lib}
EXCLUDE=${HP_GPU_TEST_EXCLUDE-$'\t(CliView\\.|CliCharacterMesh\\.AClipPlaysInRenderSimulateAndView$)'}
mkdir -p "$OUT/bench" "$OUT/tests/logs"
: >"$OUT/run.log"
printf 'step\tstatus\trc\tseconds\n' >"$OUT/steps.tsv"

log() { printf '[%4ds] %s\n' "$(($(date +%s) - START))" "$*" | tee -a "$OUT/run.log"; }
since() { echo $(($(date +%s) - $1)); }

# --- unpack ------------------------------------------------------------------------------------------
W=${HP_WORK:-${TMPDIR:-/tmp}/hairpipe-gpu-$$}
CREATED_LINKS=()
cleanup() {
  local l
  for l in "${CREATED_LINKS[@]}"; do [ -L "$l" ] && rm -f "$l"; done
  [ "${HP_KEEP_WORK:-0}" = 1 ] || rm -rf "$W"
}
trap cleanup EXIT
trap 'log "interrupted"; exit 130' INT TERM

log "hairpipe GPU run: bundle $BUNDLE, output $OUT, budget ${BUDGET}s (benches up to ${BENCH_BUDGET}s), quick=$QUICK"
if ! { rm -rf "$W" && mkdir -p "$W" && cp -R "$BUNDLE/." "$W/" &&
        find "$W/bin" "$W/lib" "$W/layer" -name '*.gz' -exec gunzip -f {} + && chmod +x "$W"/bin/*; }; then
  log "FATAL: could not unpack the bundle into $W"; exit 1
fi
# shellcheck disable=SC1091
. "$W/bundle.env"
log "unpacked into $W ($(du -sm "$W" | cut -f1) MiB): commit $HP_BUNDLE_COMMIT, $HP_BUNDLE_BUILD_TYPE build packed $HP_BUNDLE_PACKED"

# --- environment ---------------------------------------------------------------------------------------
if [ ! -f "$ICD" ]; then
  for c in /usr/share/vulkan/icd.d/nvidia_icd.json /etc/vulkan/icd.d/nvidia_icd.json /usr/local/share/vulkan/icd.d/nvidia_icd.json; do
    [ -f "$c" ] && { log "note: $ICD is missing; using $c"; ICD=$c; break; }
  done
fi
[ -f "$ICD" ] || log "WARNING: no ICD JSON at $ICD: every Vulkan step will fail"
# libstdc++/libgcc_s: the machine's when it has every GLIBCXX version the bundled one has (Ubuntu 24.04's
# GCC 14 runtime does), so that a driver library built against a newer one is never handed an older one.
sys_cxx=""
for d in /usr/lib/x86_64-linux-gnu /lib/x86_64-linux-gnu /usr/lib64 /lib64; do
  [ -e "$d/libstdc++.so.6" ] && { sys_cxx=$(readlink -f "$d/libstdc++.so.6"); break; }
done
sys_gcc_s=""
for d in /usr/lib/x86_64-linux-gnu /lib/x86_64-linux-gnu /usr/lib64 /lib64; do
  [ -e "$d/libgcc_s.so.1" ] && { sys_gcc_s=$d/libgcc_s.so.1; break; }
done
LIBS=$W/lib
if [ "${HP_FORCE_FALLBACK:-0}" = 1 ] || [ -z "$sys_cxx" ] || [ -z "$sys_gcc_s" ] ||
   ! grep -a -q "$HP_BUNDLE_GLIBCXX" "$sys_cxx"; then
  LIBS=$LIBS:$W/lib/fallback
  log "libstdc++: the bundled one (machine's: ${sys_cxx:-none}, lacks $HP_BUNDLE_GLIBCXX or forced)"
else
  log "libstdc++: the machine's $sys_cxx (has $HP_BUNDLE_GLIBCXX)"
fi
export LD_LIBRARY_PATH=$LIBS${DRIVER_LIBS:+:$DRIVER_LIBS}${LD_LIBRARY_PATH:+:$LD_LIBRARY_PATH}
export VK_DRIVER_FILES=$ICD VK_ICD_FILENAMES=$ICD  # the second for loaders older than 1.3.207
export VK_LAYER_PATH=$W/layer
export PATH=$W/bin:$PATH  # the bundled spirv-val
# The NVIDIA driver's shader cache, in a folder every process can write: the test processes share it.
export __GL_SHADER_DISK_CACHE=1 __GL_SHADER_DISK_CACHE_PATH=$W/shader-cache __GL_SHADER_DISK_CACHE_SKIP_CLEANUP=1
mkdir -p "$W/shader-cache"
unset VK_ADD_DRIVER_FILES VK_INSTANCE_LAYERS VK_LOADER_LAYERS_ENABLE VK_LOADER_LAYERS_DISABLE
H=$W/bin/hairpipe

# The tests look for their data and for the tool at the source and build paths compiled in: make them
# exist (links into this bundle) when they do not; leave them alone when they do.
link_compiled_path() {  # PATH TARGET
  local p=$1 target=$2
  if [ -e "$p" ]; then
    if [ -d "$target" ] || cmp -s "$p" "$target"; then log "compiled-in path $p exists"; else
      log "WARNING: compiled-in path $p exists and differs from the bundle's $(basename "$target"); the tests use it"; fi
    return 0
  fi
  if mkdir -p "$(dirname "$p")" 2>/dev/null && ln -s "$target" "$p" 2>/dev/null; then
    CREATED_LINKS+=("$p"); log "linked compiled-in path $p -> $target"; return 0
  fi
  log "WARNING: cannot create the compiled-in path $p (not root?)"; return 1
}
link_compiled_path "$HP_COMPILED_DATA_DIR" "$W/data" || true
CLI_OK=1
link_compiled_path "$HP_COMPILED_CLI_PATH" "$H" || CLI_OK=0

{
  echo "== date"; date -u
  echo "== uname"; uname -a
  echo "== os"; head -4 /etc/os-release 2>/dev/null
  echo "== glibc"; ldd --version 2>&1 | head -1; echo "bundle needs $HP_BUNDLE_GLIBC_NEEDED"
  echo "== cpus"; nproc; grep -m1 'model name' /proc/cpuinfo
  echo "== nvidia-smi"
  smi=$(command -v nvidia-smi || ls /usr/local/nvidia/bin/nvidia-smi 2>/dev/null)
  if [ -n "$smi" ]; then timeout 20 "$smi" 2>&1; else echo "(none)"; fi
  echo "== ICD $ICD"; cat "$ICD" 2>&1
  echo "== environment"; env | grep -E '^(LD_LIBRARY_PATH|VK_|HAIRPIPE_|HP_|__GL_)' | sort
  echo "== ldd hairpipe (with this LD_LIBRARY_PATH)"; ldd "$H" 2>&1
  echo "== unresolved libraries (none expected)"
  for f in "$W"/bin/* "$W"/lib/*.so* "$W"/layer/*.so; do ldd "$f" 2>&1 | grep 'not found' | sed "s|^|$(basename "$f"): |"; done
  icd_lib=$(sed -n 's/.*"library_path"[[:space:]]*:[[:space:]]*"\([^"]*\)".*/\1/p' "$ICD" 2>/dev/null | head -1)
  if [ -n "$icd_lib" ]; then
    echo "== the ICD's library $icd_lib"
    p=$icd_lib
    case "$icd_lib" in /*) ;; *) for d in ${LD_LIBRARY_PATH//:/ }; do [ -e "$d/$icd_lib" ] && { p=$d/$icd_lib; break; }; done ;; esac
    if [ -e "$p" ]; then ldd "$p" 2>&1 | grep -E 'not found|GL|vulkan' ; echo "found at $p"; else echo "NOT FOUND on LD_LIBRARY_PATH"; fi
  fi
} >"$OUT/env.txt" 2>&1
grep -q 'not found' <(sed -n '/== unresolved/,/== the ICD/p' "$OUT/env.txt") &&
  log "WARNING: unresolved libraries (env.txt)"

# --- steps -----------------------------------------------------------------------------------------------
FAILED_STEPS=()
# step NAME CAP DEADLINE STDOUT_FILE CMD...: runs CMD with a timeout of min(CAP, DEADLINE - now), stderr (and
# stdout when STDOUT_FILE is -) into $OUT/NAME.log; records the outcome; never fails the script.
step() {
  local name=$1 cap=$2 deadline=$3 stdout=$4; shift 4
  local left=$((deadline - $(date +%s))) t=$cap s rc status logf=$OUT/$name.log
  [ "$left" -lt "$t" ] && t=$left
  mkdir -p "$(dirname "$logf")"
  if [ "$t" -lt 5 ]; then
    log "SKIP $name: no time left in the budget"
    printf '%s\tSKIP\t-\t0\n' "$name" >>"$OUT/steps.tsv"; FAILED_STEPS+=("$name(no time)"); return 0
  fi
  log "RUN  $name (timeout ${t}s): ${*/#$W/\$B}"
  s=$(date +%s)
  if [ "$stdout" = - ]; then timeout -k 10 "$t" "$@" >"$logf" 2>&1; else timeout -k 10 "$t" "$@" >"$stdout" 2>"$logf"; fi
  rc=$?
  case $rc in 0) status=OK ;; 124|137) status=TIMEOUT ;; *) status=FAIL ;; esac
  printf '%s\t%s\t%s\t%s\n' "$name" "$status" "$rc" "$(since "$s")" >>"$OUT/steps.tsv"
  log "$status $name (rc $rc, $(since "$s")s)"
  [ "$status" = OK ] || { FAILED_STEPS+=("$name"); tail -n 8 "$logf" | sed 's/^/    | /' | tee -a "$OUT/run.log"; }
  return 0
}

step info 30 "$DEADLINE" - "$H" info
sed 's/^/    /' "$OUT/info.log"
step info_json 30 "$DEADLINE" "$OUT/info.json" "$H" info --json
VK_LOADER_DEBUG=error,warn,driver,layer step loader_debug 30 "$DEADLINE" - "$H" info
# The packaged applications (their own instance and device through the loader, hairpipe's public API,
# synchronization validation; they fail on any message: embed by its own messenger, hello_hair, which has
# no validation code, by the layer's log on stdout checked here), when the bundle has them.
if [ -x "$W/bin/hairpipe_embed" ]; then
  for raster in graphics compute; do
    step apps/embed_$raster 60 "$DEADLINE" - "$W/bin/hairpipe_embed" --validation --frames 8 --raster $raster \
      --out "$OUT/embed_$raster.png"
  done
fi
[ -x "$W/bin/hello_hair" ] && step apps/hello_hair 60 "$DEADLINE" - sh -c "cd '$OUT' &&
  VK_INSTANCE_LAYERS=VK_LAYER_KHRONOS_validation VK_LAYER_ENABLES=VK_VALIDATION_FEATURE_ENABLE_SYNCHRONIZATION_VALIDATION_EXT \
  VK_LAYER_REPORT_FLAGS=error,warn,perf '$W/bin/hello_hair' >hello_hair.log 2>&1; rc=\$?; cat hello_hair.log;
  [ \$rc = 0 ] && ! grep -qE 'Validation (Error|Warning|Performance Warning)' hello_hair.log"

if [ "${HP_GPU_SKIP_BENCH:-0}" != 1 ]; then
  # shellcheck disable=SC2054  # the commas are the CLI's list separators
  if [ "$QUICK" = 1 ]; then
    FRAME_STRANDS=500,2000; FRAME_RES=64x48; FRAME_N=2; SMALL_STRANDS=1000; SMALL_RES=96x54
    SIM=(--guides 100 300 --frames 2); STRANDS=(--strands 1000,4000 --frames 2 --walk strand,vertex)
    OPACITY=(--strands 1000 --resolutions 64 --frames 1); INSTANCES=(--instances 1,2 --strands 200 --frames 1)
    CAP_FRAME=200; CAP_SMALL=90; CAP_SUITE=90; PEER_STRANDS=1000
  else
    FRAME_STRANDS=20000,136320,1000000; FRAME_RES=1920x1080; FRAME_N=20; SMALL_STRANDS=136320; SMALL_RES=1280x720
    SIM=(--guides 1000 10000 100000 --frames 20); STRANDS=(--strands 10000,136320,1000000 --frames 10 --walk strand,vertex)
    OPACITY=(--strands 10000,100000,1000000 --resolutions 512,1024 --frames 5)
    INSTANCES=(--instances 1,4,16 --frames 10)
    CAP_FRAME=120; CAP_SMALL=45; CAP_SUITE=45; PEER_STRANDS=10000,136320
  fi
  step bench/frame_${FRAME_RES} "$CAP_FRAME" "$BENCH_DEADLINE" - "$H" bench --raster compute --strands "$FRAME_STRANDS" \
    --resolution "$FRAME_RES" --frames "$FRAME_N" --json "$OUT/bench/frame_${FRAME_RES}.json" --plot "$OUT/bench/frame_${FRAME_RES}.svg"
  sed 's/^/    /' "$OUT/bench/frame_${FRAME_RES}.log" 2>/dev/null | grep -E 'device:|strands, [0-9]+x|frame|fine|shade|opacity' | head -40
  step bench/frame_${SMALL_RES} "$CAP_SMALL" "$BENCH_DEADLINE" - "$H" bench --raster compute --strands "$SMALL_STRANDS" \
    --resolution "$SMALL_RES" --frames "$FRAME_N" --json "$OUT/bench/frame_${SMALL_RES}.json"
  sed 's/^/    /' "$OUT/bench/frame_${SMALL_RES}.log" 2>/dev/null | grep -E 'strands, [0-9]+x' | head
  step bench/sim "$CAP_SUITE" "$BENCH_DEADLINE" "$OUT/bench/sim.json" "$H" bench sim "${SIM[@]}" --json
  step bench/strands "$CAP_SUITE" "$BENCH_DEADLINE" "$OUT/bench/strands.json" "$H" bench strands "${STRANDS[@]}" --json
  step bench/opacity "$CAP_SUITE" "$BENCH_DEADLINE" "$OUT/bench/opacity.json" "$H" bench opacity "${OPACITY[@]}" --json
  step bench/instances "$CAP_SUITE" "$BENCH_DEADLINE" "$OUT/bench/instances.json" "$H" bench instances "${INSTANCES[@]}" --json
  # vkhr's published setting (straight hair, 1280x720) on hairpipe's own straight models (samples/peer/), last:
  # two models written and imported, two benches.
  step bench/peer_vkhr 90 "$BENCH_DEADLINE" - bash "$W/vkhr_setting.sh" "$H" "$OUT/bench/peer" "$PEER_STRANDS" \
    "$FRAME_N" "$SMALL_RES"
  grep -h 'strands (its own)' "$OUT"/bench/peer/bench_*.log 2>/dev/null | sed 's/^/    /'
fi

if [ -n "${HP_GPU_EXTRA:-}" ]; then
  if [ -f "$HP_GPU_EXTRA" ]; then
    log "EXTRA $HP_GPU_EXTRA"
    # shellcheck disable=SC1090
    . "$HP_GPU_EXTRA" || FAILED_STEPS+=("extra")
  else
    log "WARNING: HP_GPU_EXTRA=$HP_GPU_EXTRA is not a file"; FAILED_STEPS+=("extra")
  fi
fi

# --- tests, one per process ----------------------------------------------------------------------------------
RESULTS=$OUT/tests/results.tsv
printf 'suite\ttest\tstatus\trc\tseconds\n' >"$RESULTS"
run_one() {  # SUITE TEST (exported for xargs)
  local suite=$1 test=$2 left t s rc status safe=${2//\//_}
  local logf=$HP_OUT/tests/logs/$suite/$safe.log tmp=$HP_W/tmp/$suite/$safe
  left=$((HP_DEADLINE - $(date +%s)))
  if [ "$left" -lt 10 ]; then printf '%s\t%s\tNOTRUN\t-\t0\n' "$suite" "$test" >>"$HP_RESULTS"; return 0; fi
  t=$HP_TEST_TIMEOUT; [ "$left" -lt "$t" ] && t=$left
  mkdir -p "$tmp" "$(dirname "$logf")"
  s=$(date +%s%N)
  (cd "$tmp" && TMPDIR=$tmp timeout -k 5 "$t" "$HP_W/bin/$suite" --gtest_filter="$test" --gtest_color=no) >"$logf" 2>&1
  rc=$?
  if [ $rc = 124 ] || [ $rc = 137 ]; then status=TIMEOUT
  elif [ $rc != 0 ]; then status=FAIL
  elif grep -q '^\[  SKIPPED \] 1 test' "$logf"; then status=SKIP
  elif grep -q '^\[  PASSED  \] 1 test' "$logf"; then status=PASS
  else status=FAIL; fi  # the filter matched nothing
  local secs=$(( ($(date +%s%N) - s) / 1000000 ))
  secs=$((secs / 1000)).$(printf '%03d' $((secs % 1000)))
  printf '%s\t%s\t%s\t%s\t%s\n' "$suite" "$test" "$status" "$rc" "$secs" >>"$HP_RESULTS"
  printf '[%4ds] %-7s %s %s (%ss)\n' "$(($(date +%s) - HP_START))" "$status" "$suite" "$test" "$secs"
  if [ "$status" = FAIL ] || [ "$status" = TIMEOUT ]; then  # keep what it wrote (an actual image) for a look
    find "$tmp" -maxdepth 2 -type f -size -2048k \( -name '*.png' -o -name '*.json' -o -name '*.txt' \) 2>/dev/null |
      head -5 | while read -r f; do mkdir -p "$HP_OUT/tests/artifacts/$suite/$safe"; cp "$f" "$HP_OUT/tests/artifacts/$suite/$safe/"; done
  fi
  rm -rf "$tmp"
}
if [ "${HP_GPU_SKIP_TESTS:-0}" != 1 ]; then
  LIST=$OUT/tests/list.tsv
  : >"$LIST"
  for suite in $HP_BUNDLE_SUITES; do
    if [ "$suite" = cli_tests ] && [ "$CLI_OK" = 0 ]; then log "leaving cli_tests out: $HP_COMPILED_CLI_PATH cannot be made"; continue; fi
    timeout 60 "$W/bin/$suite" --gtest_list_tests >"$OUT/tests/list_$suite.txt" 2>&1 ||
      { log "WARNING: $suite --gtest_list_tests failed (rc $?)"; FAILED_STEPS+=("list:$suite"); continue; }
    awk -v s="$suite" '/^[^ ].*\.$/ { p = $1; next } /^  [^ ]/ { print s "\t" p $1 }' "$OUT/tests/list_$suite.txt" >>"$LIST"
  done
  all=$(wc -l <"$LIST")
  if [ -n "${HP_GPU_TEST_FILTER:-}" ]; then grep -E -- "$HP_GPU_TEST_FILTER" "$LIST" >"$LIST.f" || true; mv "$LIST.f" "$LIST"; fi
  if [ -n "$EXCLUDE" ]; then grep -v -E -- "$EXCLUDE" "$LIST" >"$LIST.f" || true; mv "$LIST.f" "$LIST"; fi
  if [ "$QUICK" = 1 ] && [ -z "${HP_GPU_TEST_FILTER:-}" ]; then
    # A few that cover a device with validation on, a provoked validation message, the data folder (the
    # golden image), the CPU references, and the CLI run by path with --validation (an OBJ from the data).
    grep -E $'\t(VulkanTest\\.(CreatesAVulkan13DeviceWithAGraphicsComputeQueue|ValidationCaptureReportsAnInvalidCall|DefaultHeadMatchesTheGoldenImage)|InterpolateTest\\.MatchesDoublePrecisionReferenceOnDefaultHead|CliInfo\\.ListsDevicesSelectionAndValidationLayerAsJson|CliHairInspect\\.ReportsAnObjScalp)$' \
      "$LIST" >"$LIST.f" || true
    mv "$LIST.f" "$LIST"
  fi
  log "TESTS $(wc -l <"$LIST") of $all tests, $JOBS at a time, ${TEST_TIMEOUT}s each, until $((DEADLINE - START))s"
  export -f run_one
  export HP_OUT=$OUT HP_W=$W HP_DEADLINE=$DEADLINE HP_TEST_TIMEOUT=$TEST_TIMEOUT HP_RESULTS=$RESULTS HP_START=$START
  s=$(date +%s)
  # Each worker stops starting tests 10 s before the deadline; the outer timeout is a backstop only.
  tr '\t' ' ' <"$LIST" | timeout -k 10 $((DEADLINE - $(date +%s) + 30)) xargs -P "$JOBS" -L 1 bash -c 'run_one "$@"' _ |
    tee -a "$OUT/run.log"
  log "tests done in $(since "$s")s"
  # Anything the backstop cut off never wrote a result: NOTRUN.
  while IFS=$'\t' read -r suite test; do
    grep -q -F "$suite	$test	" "$RESULTS" || printf '%s\t%s\tNOTRUN\t-\t0\n' "$suite" "$test" >>"$RESULTS"
  done <"$LIST"
fi

# --- summary ------------------------------------------------------------------------------------------------------
count() { awk -F'\t' -v s="$1" 'NR > 1 && $3 == s' "$RESULTS" | wc -l; }
passed=$(count PASS); failed=$(count FAIL); timedout=$(count TIMEOUT); skipped=$(count SKIP); notrun=$(count NOTRUN)

# Markdown rows from the frame benches (nlohmann's dump(2): one key per line, keys sorted).
rows() {  # JSON...: one row per result
  awk -v date="$(date -u +%Y-%m-%d)" -v commit="$HP_BUNDLE_COMMIT" '
    function ms(v) { if (v == "") return "-"; v += 0; if (v < 1) return sprintf("%.3f", v); if (v < 10) return sprintf("%.2f", v); if (v < 100) return sprintf("%.1f", v); return sprintf("%.0f", v) }
    function thousands(n,   s) { s = ""; n = n ""; while (length(n) > 3) { s = "," substr(n, length(n) - 2) s; n = substr(n, 1, length(n) - 3) } return n s }
    function kv(line) { key = line; sub(/^ *"/, "", key); sub(/".*/, "", key); val = line; sub(/^ *"[^"]*": */, "", val); sub(/,$/, "", val); gsub(/"/, "", val) }
    {
      ind = match($0, /[^ ]/) - 1
      if (ind == 2 && $0 ~ /"device":/) { kv($0); device = val }
      else if (ind == 4 && $0 ~ /^ *}/) {
        what = thousands(r["strands"])
        if (r["model"] != "" && r["model"] != "default") { m = r["model"]; sub(/.*\//, "", m); what = what " (" m ")" }
        printf "| %s | %s | %sx%s | %s | **%s** |", device, date, r["width"], r["height"], what, ms(p["frame"])
        n = split("simulate,tessellate,interpolate,opacity,head,head shadow,head bounce,raster project,raster bin,raster shade,strand bounce,raster fine,composite,tonemap", names, ",")
        for (i = 1; i <= n; ++i) printf " %s |", ms(p[names[i]])
        printf " %s | %s | %s |\n", thousands(r["raster_overflow"]), ms(r["host_frame_ms"]), commit
        split("", r); split("", p)
      }
      else if (ind == 6 && $0 ~ /^ *"/) { kv($0); r[key] = val }
      else if (ind == 8 && $0 ~ /": {$/) { kv($0); pass = key }
      else if (ind == 10 && $0 ~ /"median_ms"/) { kv($0); p[pass] = val }
    }' "$@"
}
{
  echo "<!-- hairpipe bench --raster compute, median of $([ "$QUICK" = 1 ] && echo 2 || echo 20) frames after one warm-up; GPU ms per pass (GpuProfiler timestamps); written by tests/gpu/run_on_gpu.sh -->"
  echo "| device | date | resolution | strands | frame ms | simulate | tessellate | interpolate | opacity | head | head shadow | head bounce | raster project | raster bin | raster shade | strand bounce | raster fine | composite | tonemap | tile entries dropped | host ms | commit |"
  echo "|---|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---|"
  for j in "$OUT"/bench/frame_*.json "$OUT"/bench/peer/bench_*.json; do [ -s "$j" ] && rows "$j"; done
} >"$OUT/performance_rows.md"

{
  echo "hairpipe GPU run, $(date -u +%Y-%m-%dT%H:%M:%SZ), commit $HP_BUNDLE_COMMIT, $(($(date +%s) - START)) s"
  sed -n 's/^\(\[[0-9]*\] .*<- selected\)$/device: \1/p; s/^ *driver /driver: /p' "$OUT/info.log" 2>/dev/null | head -2
  echo
  echo "tests: $passed passed, $failed failed, $timedout timed out, $skipped skipped, $notrun not run (of $(($(wc -l <"$RESULTS") - 1)))"
  if [ $((failed + timedout)) -gt 0 ]; then
    echo "failed tests:"
    awk -F'\t' 'NR > 1 && ($3 == "FAIL" || $3 == "TIMEOUT") { print "  " $3 " " $1 " " $2 " (rc " $4 ", " $5 " s)" }' "$RESULTS"
    echo "first failure lines (the logs: tests/logs/SUITE/TEST.log):"
    awk -F'\t' 'NR > 1 && ($3 == "FAIL" || $3 == "TIMEOUT") { print $1 "\t" $2 }' "$RESULTS" | head -10 |
      while IFS=$'\t' read -r suite test; do
        echo "  == $suite $test"
        grep -E -m 4 'Failure|rror|VUID|Expected|Which is|alidation' "$OUT/tests/logs/$suite/${test//\//_}.log" 2>/dev/null |
          cut -c1-200 | sed 's/^/     /'
      done
  fi
  echo "slowest tests:"; awk -F'\t' 'NR > 1 && $3 != "NOTRUN"' "$RESULTS" | sort -t$'\t' -k5,5gr | head -8 | awk -F'\t' '{ print "  " $5 " s  " $1 " " $2 " " $3 }'
  echo
  echo "steps:"; column -t -s $'\t' "$OUT/steps.tsv" 2>/dev/null || cat "$OUT/steps.tsv"
  [ ${#FAILED_STEPS[@]} -eq 0 ] || echo "steps not OK: ${FAILED_STEPS[*]}"
  echo
  echo "performance rows (docs/PERFORMANCE.md; all of it in performance_rows.md, the reports in bench/):"
  sed 1d "$OUT/performance_rows.md"
  echo
  echo "$passed passed, $((failed + timedout)) failed, $((skipped + notrun)) skipped"
} >"$OUT/summary.txt"
{
  printf '{\n  "commit": "%s",\n  "seconds": %s,\n  "quick": %s,\n' "$HP_BUNDLE_COMMIT" "$(($(date +%s) - START))" "$QUICK"
  printf '  "tests": {"passed": %s, "failed": %s, "timed_out": %s, "skipped": %s, "not_run": %s},\n' "$passed" "$failed" "$timedout" "$skipped" "$notrun"
  printf '  "failed_tests": ['
  awk -F'\t' 'NR > 1 && ($3 == "FAIL" || $3 == "TIMEOUT") { printf "%s\"%s %s\"", (n++ ? ", " : ""), $1, $2 }' "$RESULTS"
  printf '],\n  "steps": ['
  awk -F'\t' 'NR > 1 { printf "%s{\"name\": \"%s\", \"status\": \"%s\", \"rc\": \"%s\", \"seconds\": %s}", (n++ ? ", " : ""), $1, $2, $3, $4 }' "$OUT/steps.tsv"
  printf ']\n}\n'
} >"$OUT/summary.json"

echo
tee -a "$OUT/run.log" <"$OUT/summary.txt"
# 0: every step OK and every listed test ran and passed.
[ $((failed + timedout + notrun)) -eq 0 ] && [ ${#FAILED_STEPS[@]} -eq 0 ]
