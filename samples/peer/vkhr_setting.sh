#!/usr/bin/env bash
# vkhr_setting.sh HAIRPIPE OUT_DIR [STRANDS] [FRAMES] [RESOLUTION]: the frame at the peer renderer vkhr's
# published setting (EGSR 2019: straight hair, 1280x720), on a model of hairpipe's own, timed by `hairpipe bench`.
#   1. `hairpipe strands --density N --no-groom` writes the default head's hair, straight (no clumps, wave or
#      frizz), as N strands of 36 points: OUT_DIR/straight_N.hair (for each N of STRANDS, default 10000,136320).
#   2. A scene per model, OUT_DIR/vkhr_view_N.json: the file's strands in metres, seen from behind through the
#      camera of vkhr's own ponytail scene (25 degrees vertical field of view, its distance of 226 units at 270
#      units a metre: 0.837 m from the head's centre), so that vkhr, given the same file scaled by 270 and its
#      ponytail camera, draws the same picture (docs/PERFORMANCE.md "Against vkhr").
#   3. `hairpipe bench --raster compute --scene ... --own-strands --groom none`: one render strand per file
#      strand, FRAMES timed frames (default 10) at RESOLUTION (default 1280x720); OUT_DIR/bench_N.json and .log.
# Exits non-zero when a step fails; what it wrote so far stays.
set -euo pipefail
HAIRPIPE=${1:?usage: vkhr_setting.sh HAIRPIPE OUT_DIR [STRANDS] [FRAMES] [RESOLUTION]}
OUT=${2:?usage: vkhr_setting.sh HAIRPIPE OUT_DIR [STRANDS] [FRAMES] [RESOLUTION]}
STRANDS=${3:-10000,136320}
FRAMES=${4:-10}
RESOLUTION=${5:-1280x720}
mkdir -p "$OUT"
IFS=, read -r -a counts <<<"$STRANDS"
for n in "${counts[@]}"; do
  [[ "$n" =~ ^[1-9][0-9]*$ ]] || { echo "vkhr_setting.sh: strand count '$n' is not a positive integer" >&2; exit 2; }
  model="$OUT/straight_$n.hair"
  [ -s "$model" ] || "$HAIRPIPE" strands --density "$n" --no-groom --out "$model"
  cat >"$OUT/vkhr_view_$n.json" <<JSON
{
  "model": {"source": "straight_$n.hair", "scale": 1.0, "up": "y"},
  "camera": {"orbitDeg": 180, "elevationDeg": 0, "distance": 0.837, "fovDeg": 25, "target": [0, 0, 0]}
}
JSON
  "$HAIRPIPE" bench --raster compute --scene "$OUT/vkhr_view_$n.json" --own-strands --groom none \
    --resolution "$RESOLUTION" --frames "$FRAMES" --json "$OUT/bench_$n.json" 2>&1 | tee "$OUT/bench_$n.log"
done
