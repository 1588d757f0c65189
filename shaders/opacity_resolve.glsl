// The compute opacity pass's resolve (shared/opacity.h), GLSL only; included by one shader per map
// format (opacity_resolve_rgba32f.comp / _rgba16f.comp define OPACITY_MAPS_FORMAT first, since a storage
// image's format is part of its declaration). One invocation per texel: the prefix sum of its 16 bins,
// from fixed point, is alpha(z_i) for i = 1..16 (deep maps from fine bins: resolveFine), written to the 4
// RGBA layers as the graphics pass blends them. A saturated bin makes its slice and every one behind it
// OPACITY_SATURATED_ALPHA. The last layer gets each texel's first hair (deep maps) or OPACITY_NO_HAIR.
#include "shared/opacity.h"
#include "common.glsl"

layout(local_size_x = OPACITY_RESOLVE_WORKGROUP_SIZE) in;
layout(std430, binding = OPACITY_RESOLVE_BINDING_BINS) readonly buffer Bins { uint bins[]; };
layout(binding = OPACITY_RESOLVE_BINDING_MAPS, OPACITY_MAPS_FORMAT) uniform writeonly image2DArray maps;
layout(std430, binding = OPACITY_RESOLVE_BINDING_FIRST) readonly buffer First { uint first[]; };
layout(push_constant) uniform Push { OpacityResolvePush push; };
// OPACITY_RESOLVE_*: which bins the splats filled; one pipeline per layout (lavapipe would run both resolves).
layout(constant_id = 0) const uint BIN_LAYOUT = OPACITY_RESOLVE_GLOBAL;

float alphaOf(uint bin) { return float(bin & ~OPACITY_BIN_SATURATED) / OPACITY_FIXED_ONE; }
bool saturatedBin(uint bin) { return (bin & OPACITY_BIN_SATURATED) != 0u; }

void store(ivec2 xy, float slices[OPACITY_SLICES], float s0) {
  for (uint layer = 0u; layer < OPACITY_TARGETS; ++layer)
    imageStore(maps, ivec3(xy, int(layer)),
               vec4(slices[4u * layer], slices[4u * layer + 1u], slices[4u * layer + 2u], slices[4u * layer + 3u]));
  imageStore(maps, ivec3(xy, int(OPACITY_TARGETS)), vec4(s0, 0.0, 0.0, 0.0));
}

// 16 bins, global slices or deep ones from the first-hair buffer (two splats): their prefix sums.
void resolveSlices(uint texel, ivec2 xy) {
  float slices[OPACITY_SLICES];
  float alpha = 0.0;
  bool saturated = false;
  for (uint i = 0u; i < OPACITY_SLICES; ++i) {
    uint bin = bins[texel * OPACITY_SLICES + i];
    saturated = saturated || saturatedBin(bin);
    alpha += alphaOf(bin);
    slices[i] = saturated ? OPACITY_SATURATED_ALPHA : alpha;
  }
  // Deep maps: the first hair's s (the buffer starts at the largest uint: none there).
  uint firstBits = BIN_LAYOUT == OPACITY_RESOLVE_DEEP ? first[texel] : 0xFFFFFFFFu;
  store(xy, slices, firstBits != 0xFFFFFFFFu ? floatFromOrdered(firstBits) : OPACITY_NO_HAIR);
}

// Deep maps from one splat's fine bins (shared/opacity.h): deep slice i (1..16) ends at the fine coordinate
// f0 + i, f0 = OPACITY_DEEP_FACTOR x the first hair's s, which lies in fine bin b0 = floor(f0). Nothing lies
// in front of f0, so the slice holds bins b0 .. b0 + i - 1 whole and, taking a bin's hair as spread evenly
// over it, the share f0 - b0 of bin b0 + i; the last slice holds every bin (it reaches to infinity).
void resolveFine(uint texel, ivec2 xy) {
  float slices[OPACITY_SLICES];
  uint firstBits = first[texel];
  if (firstBits == 0xFFFFFFFFu) {  // no hair: no bin was added to
    for (uint i = 0u; i < OPACITY_SLICES; ++i) slices[i] = 0.0;
    store(xy, slices, OPACITY_NO_HAIR);
    return;
  }
  float s0 = floatFromOrdered(firstBits);
  float f0 = s0 * OPACITY_DEEP_FACTOR;
  uint b0 = min(uint(max(f0, 0.0)), OPACITY_DEEP_BINS - 1u);
  float share = clamp(f0 - float(b0), 0.0, 1.0);
  float alpha = 0.0;  // bins b0 .. b0 + i - 1
  bool saturated = false;
  uint next = bins[opacityFineBin(texel, b0)];
  for (uint i = 1u; i < OPACITY_SLICES; ++i) {
    saturated = saturated || saturatedBin(next);
    alpha += alphaOf(next);
    next = b0 + i < OPACITY_DEEP_BINS ? bins[opacityFineBin(texel, b0 + i)] : 0u;
    bool full = saturated || (share > 0.0 && saturatedBin(next));
    slices[i - 1u] = full ? OPACITY_SATURATED_ALPHA : alpha + share * alphaOf(next);
  }
  for (uint j = b0 + OPACITY_SLICES; ; ++j) {  // the last slice: bin b0 + 15 (in `next`) and every farther one
    saturated = saturated || saturatedBin(next);
    alpha += alphaOf(next);
    if (j >= OPACITY_DEEP_BINS) break;
    next = bins[opacityFineBin(texel, j)];
  }
  slices[OPACITY_SLICES - 1u] = saturated ? OPACITY_SATURATED_ALPHA : alpha;
  store(xy, slices, s0);
}

void main() {
  uint texel = hpThreadId(OPACITY_RESOLVE_WORKGROUP_SIZE);
  uint n = push.resolution;
  if (texel >= n * n) return;
  ivec2 xy = ivec2(texel % n, texel / n);
  if (BIN_LAYOUT == OPACITY_RESOLVE_DEEP_FINE)
    resolveFine(texel, xy);
  else
    resolveSlices(texel, xy);
}
