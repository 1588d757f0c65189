# frame_checks.sh: a profiling script for run_on_gpu.sh (HP_GPU_EXTRA=.../frame_checks.sh, sourced there).
# It runs compare_binaries.sh (beside it in the bundle), then:
# - the opacity maps' strand budget (`bench --shadow-strands`): 0, 131,072 and 262,144 at 1,000,000 strands and
#   0 and 65,536 at 136,320, at 1920x1080: bench/shadow_strands_1m.json, bench/shadow_strands_136k.json;
# - the tile lists reserved or grown (`bench --grow-lists off,on`) at 136,320 and 1,000,000 strands at 1920x1080:
#   the frame's passes and the raster target's device memory, bench/grow_lists.json;
# - two renders of one frame (136,320 strands at 1920x1080, the compute raster) compared with `hairpipe
#   compare`: a depth bin's entries composite in the atomics' order, so how far apart two runs land says how
#   much a still frame may shimmer on this device (lavapipe: 60 dB at 1280x720). Keeps render_1.png,
#   render_2.png and the comparison's JSON in the step's log, not the exports' strands or PFMs.
# With HP_GPU_QUICK=1, tiny sizes for a try on lavapipe.
. "$(dirname "${BASH_SOURCE[0]}")/compare_binaries.sh"
if [ "$QUICK" = 1 ]; then
  FC_SMALL=1000; FC_LARGE=2000; FC_W=64; FC_H=48; FC_FRAMES=2; FC_BUDGETS_L=0,1000; FC_BUDGETS_S=0,500
else
  FC_SMALL=136320; FC_LARGE=1000000; FC_W=1920; FC_H=1080; FC_FRAMES=20; FC_BUDGETS_L=0,131072,262144; FC_BUDGETS_S=0,65536
fi
step checks/shadow_strands_large 90 "$DEADLINE" - "$H" bench --raster compute --strands $FC_LARGE \
  --resolution ${FC_W}x$FC_H --frames $FC_FRAMES --shadow-strands $FC_BUDGETS_L --json "$OUT/bench/shadow_strands_1m.json"
step checks/shadow_strands_small 60 "$DEADLINE" - "$H" bench --raster compute --strands $FC_SMALL \
  --resolution ${FC_W}x$FC_H --frames $FC_FRAMES --shadow-strands $FC_BUDGETS_S --json "$OUT/bench/shadow_strands_136k.json"
step checks/grow_lists 90 "$DEADLINE" - "$H" bench --raster compute --strands $FC_SMALL,$FC_LARGE \
  --resolution ${FC_W}x$FC_H --frames $FC_FRAMES --grow-lists off,on --json "$OUT/bench/grow_lists.json"
for k in 1 2; do
  step checks/render_$k 60 "$DEADLINE" - "$H" render --density $FC_SMALL --width $FC_W --height $FC_H --raster compute \
    --export-frame "$OUT/render_$k" --out "$OUT/render_$k.png"
done
step checks/render_compare 30 "$DEADLINE" - "$H" compare --image "$OUT/render_1/realtime.pfm" \
  --reference "$OUT/render_2/realtime.pfm" --json
rm -rf "$OUT/render_1" "$OUT/render_2"
