#version 460
// Opacity maps: a fragment at slice coordinate s adds its opacity to every slice at or behind it
// (slice i at s = i, i = 1..16), so with additive blending target t channel c holds alpha(z_{4t+c+1})
// directly (docs/THEORY.md §5); no prefix sum afterwards.
#include "shared/opacity.h"

layout(location = 0) in float inSlice;
layout(location = 1) in float inOpacity;  // per fragment (strands: from the footprint, opacity.vert)
layout(location = 0) out vec4 outSlices0;  // slices 1-4
layout(location = 1) out vec4 outSlices1;  // slices 5-8
layout(location = 2) out vec4 outSlices2;  // slices 9-12
layout(location = 3) out vec4 outSlices3;  // slices 13-16

void main() {
  float s = inSlice - OPACITY_SLICE_EPSILON;
  const vec4 first = vec4(1.0, 2.0, 3.0, 4.0);
  // step(edge, x) = x >= edge: slice i >= s.
  outSlices0 = inOpacity * step(vec4(s), first);
  outSlices1 = inOpacity * step(vec4(s), first + 4.0);
  outSlices2 = inOpacity * step(vec4(s), first + 8.0);
  outSlices3 = inOpacity * step(vec4(s), first + 12.0);
}
