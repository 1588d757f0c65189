#!/usr/bin/env bash
# Fails if a layer includes a layer above it. Bottom to top: engine/{hair,shading,sim} (no Vulkan),
# engine/vk, compute/, engine/render/, the facade (engine/*.h: Renderer, HairInstance, HairSystem),
# samples/tools/, samples/cli/, samples/viewer/ and the embedding sample; Embree only in
# samples/tools/reference/. Usage: check_layers.sh SOURCE_DIR
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
check engine/hair engine/shading engine/sim -- 'engine/vk/|engine/render/|compute/|samples/|engine/(hair_system|hair_instance|renderer|renderer_settings|frame_recorder)\.h'
check engine/vk -- 'engine/render/|compute/|samples/|engine/(hair_system|hair_instance|renderer|renderer_settings|frame_recorder)\.h'
check compute -- 'engine/render/|samples/|engine/(hair_system|hair_instance|renderer|renderer_settings|frame_recorder)\.h'
check engine/render -- 'samples/|engine/(hair_system|hair_instance|renderer|renderer_settings|frame_recorder)\.h'
check engine/*.h engine/*.cpp -- 'samples/'
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
