#!/usr/bin/env bash
# The installed package as an application meets it. Installs the build into WORK/install, MOVES that prefix
# to WORK/prefix (the package must be relocatable), then, by MODE:
#   embed      builds samples/embed against it and runs it under synchronization validation with the
#              graphics and the compute raster (it fails on any validation message and must write a PNG),
#              and once failing with frames in flight (--fail-at-frame: exit 1, its error, no PNG, no message)
#   hello      builds samples/hello_hair against it, runs it under validation, checks its PNG
#   consumers  builds tests/package/consumers (a -fno-exceptions consumer and one with glm's macros set
#              the other way from hairpipe's internals), with CMake's FindVulkan disabled (the package needs
#              Vulkan's headers, not the loader), and runs both
#   headers    the installed headers are exactly docs/API.md's public list, each compiles alone
#              (-fno-exceptions, -Wall -Wextra -Werror) and includes only public headers, Vulkan's core
#              header and the standard library; the GLSL file includes nothing and compiles (glslc) into an
#              application's compute shader that calls hairpipeHairShadow
#   symbols    no installed archive defines a global vk* or volk* symbol, nor any strong global symbol outside
#              hairpipe's namespaces (its copies of tinyobjloader and tinygltf renamed); the CMake package names no
#              absolute path, no compile definition and no link dependency but Vulkan's headers and libdl
# Usage: package_test.sh MODE SOURCE_DIR BUILD_DIR WORK_DIR CXX_COMPILER [LAUNCHER] [EXTRA_FLAGS]
set -euo pipefail
mode=$1 src=$2 build=$3 work=$4 cxx=$5 launcher=${6:-} flags=${7:-}
rm -rf "$work"
mkdir -p "$work"
cmake --install "$build" --prefix "$work/install" > "$work/install.log"
mv "$work/install" "$work/prefix"
prefix=$work/prefix

configure_and_build() {  # configure_and_build PROJECT_DIR BUILD_DIR [CMAKE_ARG...]
  local project=$1 out=$2
  shift 2
  cmake -S "$project" -B "$out" "$@" -DCMAKE_BUILD_TYPE=Release -DCMAKE_PREFIX_PATH="$prefix" -DCMAKE_CXX_COMPILER="$cxx" \
    ${launcher:+-DCMAKE_CXX_COMPILER_LAUNCHER="$launcher"} \
    ${flags:+-DCMAKE_CXX_FLAGS="$flags" -DCMAKE_EXE_LINKER_FLAGS="$flags"} > "$out.configure.log"
  cmake --build "$out" -j2 > "$out.build.log" || { cat "$out.build.log" >&2; exit 1; }
  # The application's code must not reach into the source tree: only the prefix's headers were used.
  if grep -rq "$src/engine\|$src/compute\|$src/third_party" "$out"/CMakeFiles/*.dir/flags.make; then
    echo "$project was compiled with the source tree on its include path" >&2
    exit 1
  fi
}

case $mode in
  embed)
    configure_and_build "$src/samples/embed" "$work/embed"
    for raster in graphics compute; do
      "$work/embed/hairpipe_embed" --validation --frames 4 --raster $raster --out "$work/embed_$raster.png"
      [ -s "$work/embed_$raster.png" ] || { echo "no PNG written ($raster)" >&2; exit 1; }
    done
    # An application failing with frames in flight: hairpipe's objects go while it unwinds, after its wait for
    # the device (a destroyed object still in use is a validation message); exit status 1, its error, no PNG.
    status=0
    "$work/embed/hairpipe_embed" --validation --frames 6 --raster compute --fail-at-frame 2 \
      --out "$work/embed_failed.png" > "$work/embed_failed.out" 2>&1 || status=$?
    [ "$status" -eq 1 ] || { cat "$work/embed_failed.out" >&2; echo "hairpipe_embed --fail-at-frame 2 exited with $status, not 1" >&2; exit 1; }
    grep -q "error: the application failed at frame 2" "$work/embed_failed.out" &&
      ! grep -q "validation" "$work/embed_failed.out" && [ ! -e "$work/embed_failed.png" ] ||
      { cat "$work/embed_failed.out" >&2; echo "hairpipe_embed did not fail cleanly at frame 2" >&2; exit 1; }
    ;;
  hello)
    configure_and_build "$src/samples/hello_hair" "$work/hello"
    # The sample has no validation code: the layer, synchronization validation and logging of every
    # warning and error come from the environment (the layer logs to stdout), and the loader's own log
    # proves the layer was loaded. A sample with a barrier left out fails here with its VUID and hazard.
    (cd "$work" && VK_INSTANCE_LAYERS=VK_LAYER_KHRONOS_validation \
      VK_LAYER_ENABLES=VK_VALIDATION_FEATURE_ENABLE_SYNCHRONIZATION_VALIDATION_EXT \
      VK_LAYER_REPORT_FLAGS=error,warn,perf VK_LAYER_DEBUG_ACTION=VK_DBG_LAYER_ACTION_LOG_MSG \
      VK_LOADER_DEBUG=layer "$work/hello/hello_hair" >"$work/hello.out" 2>&1) || { cat "$work/hello.out" >&2; exit 1; }
    grep -q 'Insert instance layer.*VK_LAYER_KHRONOS_validation' "$work/hello.out" ||
      { echo "the validation layer was not loaded for hello_hair" >&2; exit 1; }
    if grep -E 'Validation (Error|Warning|Performance Warning)' "$work/hello.out" >&2; then
      echo "hello_hair: validation messages (above)" >&2
      exit 1
    fi
    [ -s "$work/hello_hair.png" ] || { echo "hello_hair wrote no PNG" >&2; exit 1; }
    ;;
  consumers)
    # Without CMake's FindVulkan (which wants the loader library): the package finds Vulkan's headers alone.
    configure_and_build "$src/tests/package/consumers" "$work/consumers" -DCMAKE_DISABLE_FIND_PACKAGE_Vulkan=TRUE
    "$work/consumers/noexcept_consumer"
    "$work/consumers/glm_consumer"
    # Negative control: with a forced glm macro the consumer's check must fail, naming its own glm.
    if "$work/consumers/glm_consumer_forced" >"$work/forced.out" 2>&1; then
      echo "glm_consumer_forced passed: the glm consumer cannot see a forced macro" >&2
      exit 1
    fi
    grep -q "FAILED: the application's glm" "$work/forced.out" ||
      { cat "$work/forced.out" >&2; exit 1; }
    ;;
  headers)
    installed=$(cd "$prefix/include" && find . -type f | sed 's|^\./||' | sort)
    documented=$(sed -n '/^<!-- public-headers-begin -->$/,/^<!-- public-headers-end -->$/p' "$src/docs/API.md" \
      | grep -oE '^\| `hairpipe/[a-z_]*\.(h|glsl)`' | sed 's/^| `//; s/`$//' | sort)
    if [ "$installed" != "$documented" ]; then
      echo "installed headers differ from docs/API.md's public list:" >&2
      diff <(echo "$documented") <(echo "$installed") >&2 || true
      exit 1
    fi
    # The GLSL an application's shaders include: it compiles in a compute shader of the application's that
    # binds what Renderer::hairShadows() hands out and calls the one function it needs, with no other include.
    for h in $(echo "$installed" | grep '\.glsl$'); do
      cat > "$work/receiver.comp" <<GLSL
#version 460
#extension GL_GOOGLE_include_directive : require
#include <$h>
layout(local_size_x = 64) in;
layout(binding = 0) uniform sampler2DArray hairShadowMaps;
layout(std430, binding = 1) readonly buffer HairLights { HairpipeLightSpace hairLights[]; };
layout(std430, binding = 2) buffer Points { vec4 points[]; };
layout(push_constant) uniform Push { vec4 params; vec4 forward; };
void main() {
  uint i = gl_GlobalInvocationID.x;
  points[i].rgb = hairpipeHairShadow(hairShadowMaps, hairLights[0], 0u, points[i].xyz, params, forward);
}
GLSL
      "${GLSLC:-glslc}" --target-env=vulkan1.3 -Werror -I"$prefix/include" -o "$work/receiver.spv" "$work/receiver.comp" \
        || { echo "$h does not compile in an application's shader" >&2; exit 1; }
      if grep -q '^#include' "$prefix/include/$h"; then echo "$h includes another file" >&2; exit 1; fi
    done
    installed=$(echo "$installed" | grep -v '\.glsl$')
    for h in $installed; do
      bad=$(grep -E '^#include' "$prefix/include/$h" | grep -vE '^#include "hairpipe/[a-z_]+\.h"$|^#include <vulkan/vulkan_core\.h>$|^#include <[a-z_]+>$' || true)
      [ -z "$bad" ] || { echo "$h includes more than public headers, Vulkan's core header and the standard library: $bad" >&2; exit 1; }
      echo "#include <$h>" > "$work/alone.cpp"
      "$cxx" -std=c++20 -fno-exceptions -Wall -Wextra -Wpedantic -Werror -fsyntax-only -I"$prefix/include" "$work/alone.cpp" \
        || { echo "$h does not compile alone" >&2; exit 1; }
    done
    echo "$(echo "$installed" | wc -l) installed headers and the GLSL = docs/API.md's list; each compiles alone"
    ;;
  symbols)
    defined=$(nm -g --defined-only "$prefix"/lib/*.a | awk 'NF == 3 && $2 ~ /[A-TV-Z]/ {print $3}' | grep -E '^(vk|volk)' || true)
    if [ -n "$defined" ]; then
      echo "the installed archives define global Vulkan/volk symbols:" >&2
      echo "$defined" | head -20 >&2
      exit 1
    fi
    # Every other strong global symbol is hairpipe's own (namespaces hp, hairpipe and the renamed copies
    # hp_tinyobj, hp_tinygltf; volk's hpvk_*): an application's tinyobjloader or tinygltf cannot clash. (Weak
    # symbols, template instances of std, glm and nlohmann::json, merge with an application's like any
    # header-only library's.)
    symbols=$(nm -gC --defined-only "$prefix"/lib/*.a)
    grep -q ' hp::' <<< "$symbols" || { echo "nm listed no hp:: symbol: the check would see nothing" >&2; exit 1; }
    foreign=$(echo "$symbols" | awk 'NF >= 3 && $2 ~ /^[TDBRGS]$/ {$1 = ""; $2 = ""; print}' \
      | sed -E 's/^ +//; s/^(vtable|typeinfo|typeinfo name|VTT|guard variable|construction vtable) for //' \
      | grep -vE '^(hp::|hairpipe::|hp_[a-z]+::|hpvk)' | sort -u || true)
    if [ -n "$foreign" ]; then
      echo "the installed archives define global symbols outside hairpipe's namespaces:" >&2
      echo "$foreign" | head -20 >&2
      exit 1
    fi
    config=$(cat "$prefix"/lib/cmake/hairpipe/*.cmake)
    if echo "$config" | grep -n "$work\|$src\|/usr/include\|INTERFACE_COMPILE_DEFINITIONS" >&2; then
      echo "the CMake package names an absolute path or forces a compile definition (above)" >&2
      exit 1
    fi
    links=$(echo "$config" | grep -o 'INTERFACE_LINK_LIBRARIES "[^"]*"' | sed 's/INTERFACE_LINK_LIBRARIES //; s/"//g' | tr ';' '\n' \
      | grep -vE '^(Vulkan::Headers|dl|\\\$<LINK_ONLY:(hairpipe::(core|shaders|volk))?>)$' || true)
    [ -z "$links" ] || { echo "the package links more than Vulkan's headers, libdl and its own archives: $links" >&2; exit 1; }
    echo "no global vk*/volk* symbol in $(ls "$prefix"/lib/*.a | wc -l) archives; the package forces nothing"
    ;;
  *) echo "unknown mode $mode" >&2; exit 2 ;;
esac
