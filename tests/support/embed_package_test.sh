#!/usr/bin/env bash
# Installs a hairpipe build into a temporary prefix, configures and builds the standalone samples/embed
# against that package (find_package(hairpipe CONFIG)) and runs it under the validation layer with
# synchronization validation on; the sample fails on any validation message and must write its PNG.
# Usage: embed_package_test.sh SOURCE_DIR BUILD_DIR WORK_DIR CXX_COMPILER [LAUNCHER] [EXTRA_FLAGS]
set -euo pipefail
src=$1 build=$2 work=$3 cxx=$4 launcher=${5:-} flags=${6:-}
rm -rf "$work"
mkdir -p "$work"
start=$(date +%s.%N)
cmake --install "$build" --prefix "$work/prefix" > "$work/install.log"
installed=$(date +%s.%N)
cmake -S "$src/samples/embed" -B "$work/build" -DCMAKE_BUILD_TYPE=Release -DCMAKE_PREFIX_PATH="$work/prefix" \
  -DCMAKE_CXX_COMPILER="$cxx" ${launcher:+-DCMAKE_CXX_COMPILER_LAUNCHER="$launcher"} \
  ${flags:+-DCMAKE_CXX_FLAGS="$flags" -DCMAKE_EXE_LINKER_FLAGS="$flags"} > "$work/configure.log"
configured=$(date +%s.%N)
cmake --build "$work/build" -j2 > "$work/build.log"
built=$(date +%s.%N)
"$work/build/hairpipe_embed" --validation --frames 4 --out "$work/embed.png"
ran=$(date +%s.%N)
[ -s "$work/embed.png" ] || { echo "no PNG written" >&2; exit 1; }
# The application's code must not reach into the source tree: only the prefix's headers were used.
if grep -q "$src/engine\|$src/compute" "$work/build/CMakeFiles/hairpipe_embed.dir/flags.make"; then
  echo "the sample was compiled with the source tree on its include path" >&2
  exit 1
fi
awk -v a="$start" -v b="$installed" -v c="$configured" -v d="$built" -v e="$ran" 'BEGIN {
  printf "install %.1f s, configure %.1f s, build %.1f s, run %.1f s\n", b - a, c - b, d - c, e - d }'
