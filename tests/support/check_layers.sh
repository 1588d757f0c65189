#!/usr/bin/env bash
# Fails if a layer includes a layer above it. The folders are the layers, bottom to top:
#   engine/include/hairpipe/  the public headers: include only each other (and Vulkan's core header)
#   engine/core/              the core without Vulkan (hair/: assets, formats, geometry; shading/: fibre math)
#   engine/vk/                the thin Vulkan layer
#   compute/strands/ < compute/shadows/ < compute/head/ < compute/raster/   the passes, in that order
#   compute/renderer/         the renderer facade (Renderer, HairInstance, the frame recorder)
#   compute/api/              the public API's implementation
#   samples/tools/ < samples/cli/ < samples/viewer/   the tools outside the library
# So no top-level folder includes one above it: shaders/shared < engine/ < compute/ < samples/.
# Embree only in samples/tools/reference/.
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
check engine/include -- 'engine/|compute/|shaders/|samples/|hairpipe_volk'
check engine/core -- 'engine/vk/|compute/|samples/|hairpipe/|hairpipe_volk'
check engine -- 'compute/|samples/'
check shaders -- 'engine/|compute/|samples/'
check compute/strands -- 'compute/(shadows|head|raster|renderer|api)/|samples/'
check compute/shadows -- 'compute/(head|raster|renderer|api)/|samples/'
check compute/head -- 'compute/(raster|renderer|api)/|samples/'
check compute/raster -- 'compute/(renderer|api)/|samples/'
check compute/renderer -- 'compute/api/|samples/'
check compute/api -- 'samples/'
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
