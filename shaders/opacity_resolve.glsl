// The compute opacity pass's resolve (shared/opacity.h), GLSL only; included by one shader per map
// format (opacity_resolve_rgba32f.comp / _rgba16f.comp define OPACITY_MAPS_FORMAT first, since a storage
// image's format is part of its declaration). One invocation per texel: the prefix sum of its 16 bins,
// from fixed point, is alpha(z_i) for i = 1..16, written to the 4 RGBA layers as the graphics pass
// blends them. A saturated bin makes its slice and every one behind it OPACITY_SATURATED_ALPHA. The last
// layer gets each texel's first hair (deep maps) or OPACITY_NO_HAIR.
#include "shared/opacity.h"
#include "common.glsl"

layout(local_size_x = OPACITY_RESOLVE_WORKGROUP_SIZE) in;
layout(std430, binding = OPACITY_RESOLVE_BINDING_BINS) readonly buffer Bins { uint bins[]; };
layout(binding = OPACITY_RESOLVE_BINDING_MAPS, OPACITY_MAPS_FORMAT) uniform writeonly image2DArray maps;
layout(std430, binding = OPACITY_RESOLVE_BINDING_FIRST) readonly buffer First { uint first[]; };
layout(push_constant) uniform Push { OpacityResolvePush push; };

void main() {
  uint texel = hpThreadId(OPACITY_RESOLVE_WORKGROUP_SIZE);
  uint n = push.resolution;
  if (texel >= n * n) return;
  ivec2 xy = ivec2(texel % n, texel / n);
  float alpha = 0.0;
  bool saturated = false;
  for (uint layer = 0u; layer < OPACITY_TARGETS; ++layer) {
    vec4 slices;
    for (uint c = 0u; c < 4u; ++c) {
      uint bin = bins[texel * OPACITY_SLICES + 4u * layer + c];
      saturated = saturated || (bin & OPACITY_BIN_SATURATED) != 0u;
      alpha += float(bin & ~OPACITY_BIN_SATURATED) / OPACITY_FIXED_ONE;
      slices[c] = saturated ? OPACITY_SATURATED_ALPHA : alpha;
    }
    imageStore(maps, ivec3(xy, int(layer)), slices);
  }
  // Deep maps: the first hair's s (the buffer starts at the largest uint: none there).
  float s0 = push.deep != 0u && first[texel] != 0xFFFFFFFFu ? floatFromOrdered(first[texel]) : OPACITY_NO_HAIR;
  imageStore(maps, ivec3(xy, int(OPACITY_TARGETS)), vec4(s0, 0.0, 0.0, 0.0));
}
