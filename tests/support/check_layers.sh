#!/usr/bin/env bash
# Fails if a layer includes a layer above it. Bottom to top: engine/{hair,shading} (no Vulkan),
# engine/vk, compute/, engine/render/, the facade (engine/*.h: Renderer, HairInstance), the public API's
# implementation (engine/api/), samples/tools/, samples/cli/, samples/viewer/. The public headers
# (engine/include/hairpipe/) include only each other (and Vulkan's core header): the value types they
# define once are used by the Vulkan layers too, never by the Vulkan-free core. Embree only in
# samples/tools/reference/.
# Usage: check_layers.sh SOURCE_DIR
set -euo pipefail
cd "$1"
status=0
check() {  # check DIRS... -- PATTERN: no file under DIRS includes a header matching PATTERN
  local pattern=${*: -1}
  local dirs=("${@:1:$#-2}")
  local found
  found=$(grep -rEn "#include \"($pattern)" "${dirs[@]}" --include='*.h' --include='*.cpp' || true)
  if [ -n "$found" ]; then
    echo "$found" >&2
    status=1
  fi
}
facade='engine/(hair_instance|renderer|renderer_settings|frame_recorder|compute_raster)\.h'
check engine/hair engine/shading -- "engine/vk/|engine/render/|compute/|samples/|engine/api/|hairpipe/|$facade"
check engine/vk -- "engine/render/|compute/|samples/|engine/api/|$facade"
check compute -- "engine/render/|samples/|engine/api/|$facade"
check engine/render -- "samples/|engine/api/|$facade"
check engine/*.h engine/*.cpp -- 'samples/|engine/api/'
check engine/api -- 'samples/'
check engine/include -- 'engine/|compute/|shaders/|samples/|hairpipe_volk'
check samples/tools -- 'samples/(cli|embed|viewer)'
check samples/cli -- 'samples/viewer'
# Embree is the path-traced reference's alone (samples/tools/reference/, inside the tools target).
embree=$(grep -rEln '#include <embree3/' engine compute shaders samples tests --include='*.h' --include='*.cpp' \
  | grep -v '^samples/tools/reference/' || true)
if [ -n "$embree" ]; then
  echo "Embree is included outside samples/tools/reference/:" >&2
  echo "$embree" >&2
  status=1
fi
[ $status -eq 0 ] && echo "no layer includes a layer above it"
exit $status
