# compare_binaries.sh: a profiling script for run_on_gpu.sh (HP_GPU_EXTRA=.../compare_binaries.sh, sourced
# there: it uses its `step`, $H, $W, $OUT and $DEADLINE). It benches the bundle's hairpipe against
# bin/hairpipe_base, an older build packed beside it (HP_PACK_EXTRA_BINS="hairpipe_base=PATH"), in one
# run: one warm-up case first (a GPU's first case may run at low clocks), then the two binaries
# alternately for HP_COMPARE_ROUNDS rounds (2) at 136,320 and 1,000,000 strands at 1920x1080, and once each
# at 136,320 strands at 1280x720. Reports: bench/ab_{base,new}_ROUND.json, bench/ab720_{base,new}.json.
if [ ! -x "$W/bin/hairpipe_base" ]; then
  log "compare_binaries: no bin/hairpipe_base in the bundle (HP_PACK_EXTRA_BINS); nothing to compare"
  FAILED_STEPS+=("compare_binaries")
else
  step compare/warmup 60 "$DEADLINE" - "$H" bench --raster compute --strands 136320 --resolution 1920x1080 --frames 30
  for round in $(seq 1 "${HP_COMPARE_ROUNDS:-2}"); do
    for who in base new; do
      exe=$H; [ $who = base ] && exe=$W/bin/hairpipe_base
      step compare/ab_${who}_${round} 90 "$DEADLINE" - "$exe" bench --raster compute --strands 136320,1000000 \
        --resolution 1920x1080 --frames 20 --json "$OUT/bench/ab_${who}_${round}.json"
    done
  done
  for who in base new; do
    exe=$H; [ $who = base ] && exe=$W/bin/hairpipe_base
    step compare/ab720_${who} 60 "$DEADLINE" - "$exe" bench --raster compute --strands 136320 --resolution 1280x720 \
      --frames 20 --json "$OUT/bench/ab720_${who}.json"
  done
fi
