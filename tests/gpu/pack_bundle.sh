#!/usr/bin/env bash
# pack_bundle.sh BUILD_DIR OUT_DIR: packs a folder that runs hairpipe's GPU checks on a machine with an
# NVIDIA driver (its Vulkan ICD) but no Vulkan packages: no loader, no glvnd, no validation layer
# (tests/gpu/README.md). OUT_DIR is emptied and refilled:
#   bin/     hairpipe and the device test suites of BUILD_DIR (a Release build), spirv-val (a test runs it),
#            plus HP_PACK_EXTRA_BINS:
#            space-separated NAME=PATH pairs (e.g. a baseline build's hairpipe, to bench both in one run)
#   lib/     every shared library they and the libraries below need, glibc's own excepted; the Vulkan
#            loader (libvulkan.so.1: volk opens it at run time, so ldd does not list it) and glvnd
#            (libGLdispatch, libGLX, libEGL, libOpenGL, libGL: the NVIDIA ICD needs them, and without
#            libGLdispatch vkCreateInstance fails with VK_ERROR_INCOMPATIBLE_DRIVER)
#   lib/fallback/  libstdc++ and libgcc_s: used there only when the machine's own are older
#   layer/   the Khronos validation layer and its JSON, library_path rewritten to ./ (VK_LAYER_PATH)
#   data/    tests/data (the tests read it at the source path compiled in; run_on_gpu.sh links it there)
#   run_on_gpu.sh, compare_binaries.sh and frame_checks.sh (HP_GPU_EXTRA scripts), vkhr_setting.sh
#            (samples/peer/: the peer setting's bench), bundle.env (the compiled-in paths, versions), MANIFEST (files, sizes, sources)
# Files over 256 KiB are stored gzipped (the device tool carries at most 64 MiB; the bundle is ~35 MiB
# packed, ~95 MiB unpacked); run_on_gpu.sh unpacks a copy before it runs anything.
# Needs at pack time (Debian 12): libvulkan1, vulkan-validationlayers, libglvnd0, libgl1, libegl1,
# libglx0, libopengl0 (all already pulled in by the Makefile's PACKAGES today), gzip, binutils' readelf.
set -euo pipefail

usage() { echo "usage: $0 BUILD_DIR OUT_DIR" >&2; exit 2; }
[ $# -eq 2 ] || usage
BUILD=$(cd "$1" && pwd) || usage
OUT=$2
HERE=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
SRC=$(cd "$HERE/../.." && pwd)
MULTIARCH=/usr/lib/x86_64-linux-gnu
LAYER_JSON=${HP_LAYER_JSON:-/usr/share/vulkan/explicit_layer.d/VkLayer_khronos_validation.json}
# Suites that touch the device (hair_tests and shading_tests are host only; soak_tests runs 100,000
# frames: neither belongs in an 8-minute device run).
SUITES=${HP_PACK_SUITES:-"vk_tests compute_tests render_tests cli_tests api_tests"}
GLVND="libGLdispatch.so.0 libGLX.so.0 libEGL.so.1 libOpenGL.so.0 libGL.so.1"
GZIP_OVER=$((256 * 1024))

die() { echo "pack_bundle: $*" >&2; exit 1; }
note() { echo "pack_bundle: $*"; }

# --- what to pack -----------------------------------------------------------------------------------
[ -f "$BUILD/CMakeCache.txt" ] || die "$BUILD is not a CMake build folder (no CMakeCache.txt)"
build_type=$(sed -n 's/^CMAKE_BUILD_TYPE:[A-Z]*=//p' "$BUILD/CMakeCache.txt")
[ "$build_type" = Release ] || note "warning: $BUILD is a '$build_type' build, not Release: timings will not be representative"
grep -q '^HAIRPIPE_SANITIZE:BOOL=ON' "$BUILD/CMakeCache.txt" && die "$BUILD is a sanitizer build; pack a Release build"

bins=("$BUILD/samples/hairpipe")
for s in $SUITES; do bins+=("$BUILD/tests/$s"); done
for b in "${bins[@]}"; do [ -x "$b" ] || die "missing $b (build it first: make build)"; done
# spirv-val: EmbeddedShaders.EveryShaderIsValidSpirv... runs it from PATH (run_on_gpu.sh puts bin/ first).
spirv_val=$(command -v spirv-val) || die "spirv-val is missing: apt-get install spirv-tools"
bins+=("$spirv_val")
extra_bins=()
for pair in ${HP_PACK_EXTRA_BINS:-}; do
  name=${pair%%=*}
  [ -x "${pair#*=}" ] && [ "$name" != "$pair" ] && [[ "$name" =~ ^[A-Za-z0-9._-]+$ ]] ||
    die "HP_PACK_EXTRA_BINS: '$pair' is not NAME=EXECUTABLE (NAME without '/')"
  for b in "${bins[@]}"; do [ "$(basename "$b")" != "$name" ] || die "HP_PACK_EXTRA_BINS: $name would replace the packed $b"; done
  extra_bins+=("$pair")
done
# The applications built against the installed package by the Package.* tests (ctest -R Package first):
# they call Vulkan through the loader themselves, as an engine does. Packed when present.
for app in "$BUILD/tests/package_embed/embed/hairpipe_embed" "$BUILD/tests/package_hello/hello/hello_hair"; do
  [ -x "$app" ] && bins+=("$app")
done

# The tests find their data and the tool at absolute paths compiled in (tests/CMakeLists.txt).
flags="$BUILD/tests/CMakeFiles/cli_tests.dir/flags.make"
data_dir=$(sed -n 's/.*-DHAIRPIPE_TEST_DATA_DIR=\\"\([^"\\]*\)\\".*/\1/p' "$flags" 2>/dev/null | head -1)
cli_path=$(sed -n 's/.*-DHAIRPIPE_CLI_PATH=\\"\([^"\\]*\)\\".*/\1/p' "$flags" 2>/dev/null | head -1)
: "${data_dir:=$SRC/tests/data}"
: "${cli_path:=$BUILD/samples/hairpipe}"

find_lib() {  # the real file of a library by soname, from the multiarch folders
  local name=$1 d
  for d in "$MULTIARCH" /lib/x86_64-linux-gnu; do
    [ -e "$d/$name" ] && { readlink -f "$d/$name"; return 0; }
  done
  return 1
}

loader=$(find_lib libvulkan.so.1) || die "libvulkan.so.1 not found: apt-get install libvulkan1"
glvnd_files=()
for l in $GLVND; do
  f=$(find_lib "$l") || die "$l not found: apt-get install libglvnd0 libgl1 libegl1 libglx0 libopengl0"
  glvnd_files+=("$l=$f")
done
[ -f "$LAYER_JSON" ] || die "$LAYER_JSON not found: apt-get install vulkan-validationlayers"
layer_lib_name=$(sed -n 's/.*"library_path"[[:space:]]*:[[:space:]]*"\([^"]*\)".*/\1/p' "$LAYER_JSON" | head -1)
case "$layer_lib_name" in
  /*) layer_lib=$layer_lib_name ;;
  */*) layer_lib=$(cd "$(dirname "$LAYER_JSON")" && readlink -f "$layer_lib_name") ;;
  *) layer_lib=$(find_lib "$layer_lib_name") || die "the layer's $layer_lib_name not found" ;;
esac
[ -f "$layer_lib" ] || die "the validation layer library $layer_lib is missing"

# --- lay it out --------------------------------------------------------------------------------------
case "$OUT" in /|"$SRC"|"$BUILD"|"") die "refusing to empty '$OUT'" ;; esac
rm -rf "$OUT"
mkdir -p "$OUT/bin" "$OUT/lib/fallback" "$OUT/layer" "$OUT/data"
OUT=$(cd "$OUT" && pwd)
manifest=$OUT/MANIFEST
: >"$manifest"
record() { printf '%s\t%s\n' "$1" "$2" >>"$manifest"; }

for b in "${bins[@]}"; do cp -p "$b" "$OUT/bin/"; record "bin/$(basename "$b")" "$b"; done
for pair in "${extra_bins[@]}"; do cp -p "${pair#*=}" "$OUT/bin/${pair%%=*}"; record "bin/${pair%%=*}" "${pair#*=}"; done
cp -L "$loader" "$OUT/lib/libvulkan.so.1"; record lib/libvulkan.so.1 "$loader"
for pair in "${glvnd_files[@]}"; do
  cp -L "${pair#*=}" "$OUT/lib/${pair%%=*}"; record "lib/${pair%%=*}" "${pair#*=}"
done
cp -L "$layer_lib" "$OUT/layer/libVkLayer_khronos_validation.so"
record layer/libVkLayer_khronos_validation.so "$layer_lib"
sed 's|"library_path"[[:space:]]*:[[:space:]]*"[^"]*"|"library_path": "./libVkLayer_khronos_validation.so"|' \
  "$LAYER_JSON" >"$OUT/layer/VkLayer_khronos_validation.json"
grep -q '"library_path": "./libVkLayer_khronos_validation.so"' "$OUT/layer/VkLayer_khronos_validation.json" ||
  die "could not rewrite library_path in the layer JSON"
record layer/VkLayer_khronos_validation.json "$LAYER_JSON (library_path rewritten)"
cp -R "$data_dir/." "$OUT/data/"; record data/ "$data_dir"

# Every library the binaries and the libraries above load, transitively (ldd resolves the whole tree),
# less glibc's own: the target's glibc (2.39) is newer than the build's (Debian 12: 2.36).
is_glibc() {
  case "$1" in
    linux-vdso.so.*|ld-linux*.so.*|libc.so.*|libm.so.*|libdl.so.*|libpthread.so.*|librt.so.*|libresolv.so.*|\
    libutil.so.*|libmvec.so.*|libanl.so.*|libBrokenLocale.so.*|libnss_*|libthread_db.so.*) return 0 ;;
  esac
  return 1
}
declare -A seen=()
scan() {
  local line name path
  while read -r line; do
    name=${line%% *}
    case "$line" in
      *"=> not found"*) die "$1 needs $name, which is not installed here" ;;
      *"=> /"*) path=${line#*=> }; path=${path%% (*} ;;
      *) continue ;;
    esac
    is_glibc "$name" && continue
    [ -n "${seen[$name]:-}" ] && continue
    seen[$name]=$path
  done < <(ldd "$1" 2>/dev/null)
}
for f in "$OUT"/bin/* "$OUT"/lib/*.so* "$OUT"/layer/*.so; do scan "$f"; done
for name in "${!seen[@]}"; do
  [ -e "$OUT/lib/$name" ] && continue
  case "$name" in
    libstdc++.so.6|libgcc_s.so.1) dest=lib/fallback/$name ;;
    *) dest=lib/$name ;;
  esac
  cp -L "${seen[$name]}" "$OUT/$dest"; record "$dest" "${seen[$name]}"
done
[ -f "$OUT/lib/fallback/libstdc++.so.6" ] || die "libstdc++.so.6 was not among the dependencies: unexpected"

# Versions the run script checks against the target: the newest GLIBCXX the bundled libstdc++ has (the
# system's is used when it has it too) and the newest GLIBC any packed file needs (the target must have it).
glibcxx=$(grep -a -o 'GLIBCXX_3\.4\.[0-9]*' "$OUT/lib/fallback/libstdc++.so.6" | sort -t. -k3,3n -u | tail -1)
glibc_needed=$(for f in "$OUT"/bin/* "$OUT"/lib/*.so* "$OUT"/lib/fallback/* "$OUT"/layer/*.so; do
  readelf -V --wide "$f" 2>/dev/null | grep -o 'Name: GLIBC_2\.[0-9]*' | sed 's/Name: //'
done | sort -t. -k2,2n -u | tail -1)

cp "$HERE/run_on_gpu.sh" "$OUT/run_on_gpu.sh"
cp "$HERE/compare_binaries.sh" "$OUT/compare_binaries.sh"
cp "$HERE/frame_checks.sh" "$OUT/frame_checks.sh"
cp "$SRC/samples/peer/vkhr_setting.sh" "$OUT/vkhr_setting.sh"
chmod +x "$OUT/run_on_gpu.sh" "$OUT/vkhr_setting.sh" "$OUT"/bin/*
{
  echo "# written by tests/gpu/pack_bundle.sh; read by run_on_gpu.sh"
  echo "HP_COMPILED_DATA_DIR='$data_dir'"
  echo "HP_COMPILED_CLI_PATH='$cli_path'"
  echo "HP_BUNDLE_SUITES='$SUITES'"
  echo "HP_BUNDLE_GLIBCXX='$glibcxx'"
  echo "HP_BUNDLE_GLIBC_NEEDED='$glibc_needed'"
  echo "HP_BUNDLE_BUILD_TYPE='$build_type'"
  echo "HP_BUNDLE_COMMIT='$(git -C "$SRC" rev-parse --short HEAD 2>/dev/null || echo unknown)$(git -C "$SRC" diff --quiet HEAD -- 2>/dev/null || echo +dirty)'"
  echo "HP_BUNDLE_PACKED='$(date -u +%Y-%m-%dT%H:%M:%SZ)'"
  echo "HP_BUNDLE_LOADER='$(basename "$loader")'"
  echo "HP_BUNDLE_LAYER_API='$(sed -n 's/.*"api_version"[[:space:]]*:[[:space:]]*"\([^"]*\)".*/\1/p' "$LAYER_JSON" | head -1)'"
} >"$OUT/bundle.env"

unpacked=$(du -sb "$OUT" | cut -f1)
# Store the big files gzipped (gzip is essential on Debian and Ubuntu; xz may be absent there).
find "$OUT/bin" "$OUT/lib" "$OUT/layer" -type f -size +"$((GZIP_OVER / 1024))"k -print0 | xargs -0 -r gzip -n -6
packed=$(du -sb "$OUT" | cut -f1)
echo "HP_BUNDLE_UNPACKED_BYTES=$unpacked" >>"$OUT/bundle.env"
note "packed $OUT: $(find "$OUT" -type f | wc -l) files, $((packed / 1048576)) MiB ($((unpacked / 1048576)) MiB unpacked)"
note "compiled-in paths: data $data_dir, tool $cli_path; needs GLIBC $glibc_needed; libstdc++ up to $glibcxx"
[ "$packed" -lt $((60 * 1048576)) ] || note "warning: over 60 MiB; the device tool carries at most 64 MiB"
