# compare_binaries.sh: a profiling script for run_on_gpu.sh (HP_GPU_EXTRA=.../compare_binaries.sh, sourced
# there: it uses its `step`, $H, $W, $OUT and $DEADLINE). It benches the bundle's hairpipe against
# bin/hairpipe_base, an older build packed beside it (HP_PACK_EXTRA_BINS="hairpipe_base=PATH"), in one
# run: one warm-up case first (a GPU's first case may run at low clocks), then the two binaries
# alternately for HP_COMPARE_ROUNDS rounds (2) at 136,320 and 1,000,000 strands at 1920x1080, and once each
# at 136,320 strands at 1280x720, the new build's direct and staged fine walks (`bench --fine-walk`), and
# the new build with 1 and 3 shadowed lights (`bench --lights`: the sun alone, or the sun and the studio
# environment's two lights) and with the scenes' groom and without (`bench --groom scene,none`: the groomed
# interpolate walks per strand) (with HP_GPU_QUICK=1, tiny sizes for a try on lavapipe). HP_COMPARE_NEW_ARGS
# adds options to the new build's A/B runs (e.g. "--groom none" against a base from before the default groom,
# which draws the plain blend and does not know the option). Reports: bench/ab_{base,new}_ROUND.json,
# bench/ab720_{base,new}.json, bench/fine_walks.json, bench/lights.json, bench/groom.json.
if [ "$QUICK" = 1 ]; then
  CMP_STRANDS=500,1000; CMP_RES=64x48; CMP_SMALL=96x54; CMP_FRAMES=2
else
  CMP_STRANDS=136320,1000000; CMP_RES=1920x1080; CMP_SMALL=1280x720; CMP_FRAMES=20
fi
if [ ! -x "$W/bin/hairpipe_base" ]; then
  log "compare_binaries: no bin/hairpipe_base in the bundle (HP_PACK_EXTRA_BINS); nothing to compare"
  FAILED_STEPS+=("compare_binaries")
else
  step compare/warmup 60 "$DEADLINE" - "$H" bench --raster compute --strands "${CMP_STRANDS%%,*}" --resolution "$CMP_RES" \
    --frames "$CMP_FRAMES"
  for round in $(seq 1 "${HP_COMPARE_ROUNDS:-2}"); do
    for who in base new; do
      exe=$H; extra=(${HP_COMPARE_NEW_ARGS:-}); [ $who = base ] && exe=$W/bin/hairpipe_base && extra=()
      step compare/ab_${who}_${round} 90 "$DEADLINE" - "$exe" bench --raster compute --strands "$CMP_STRANDS" \
        --resolution "$CMP_RES" --frames "$CMP_FRAMES" "${extra[@]}" --json "$OUT/bench/ab_${who}_${round}.json"
    done
  done
  # The new build's two fine walks against each other (the staged one is what a GPU gets by default).
  step compare/fine_walks 60 "$DEADLINE" - "$H" bench --raster compute --strands "${CMP_STRANDS%%,*}" --resolution "$CMP_RES" \
    --frames "$CMP_FRAMES" --fine-walk direct,staged --json "$OUT/bench/fine_walks.json"
  step compare/lights 60 "$DEADLINE" - "$H" bench --raster compute --strands "${CMP_STRANDS%%,*}" --resolution "$CMP_RES" \
    --frames "$CMP_FRAMES" --lights 1,3 --json "$OUT/bench/lights.json"
  step compare/groom 60 "$DEADLINE" - "$H" bench --raster compute --strands "${CMP_STRANDS%%,*}" --resolution "$CMP_RES" \
    --frames "$CMP_FRAMES" --groom scene,none --json "$OUT/bench/groom.json"
  for who in base new; do
    exe=$H; extra=(${HP_COMPARE_NEW_ARGS:-}); [ $who = base ] && exe=$W/bin/hairpipe_base && extra=()
    step compare/ab720_${who} 60 "$DEADLINE" - "$exe" bench --raster compute --strands "${CMP_STRANDS%%,*}" --resolution "$CMP_SMALL" \
      --frames "$CMP_FRAMES" "${extra[@]}" --json "$OUT/bench/ab720_${who}.json"
  done
fi
