// The opacity one fragment of a strand adds to the opacity maps (docs/THEORY.md §5.1; shared/opacity.h),
// GLSL only: the graphics pass (opacity.vert, per vertex) and the compute pass (opacity_splat.comp, per
// segment end) both call it, so the two paths cannot drift apart.
// Footprint mode (footprint.w = 1): the strand's width over the texel's size at this depth (the box is
// in light x/y units, per unit depth for a spot, so the texel grows with clip.w), i.e. the fraction of
// the texel the strand covers per texel of its length. The per-strand width variation (widthScale,
// mean 1) is left out: its mean is what the map's density needs. Otherwise a constant per fragment.
#ifndef HP_OPACITY_FOOTPRINT_GLSL
#define HP_OPACITY_FOOTPRINT_GLSL
#include "shared/opacity.h"

// along: 0 at the root, 1 at the tip; clipW: the vertex's light clip w (1 for a directional light).
float strandFragmentOpacity(LightSpace light, vec4 footprint, float opacity, float along, float clipW) {
  if (footprint.w <= 0.5) return opacity;
  float width = footprint.x * mix(1.0, footprint.y, along);
  vec2 texel = (light.extent.zw - light.extent.xy) * (footprint.z * clipW);
  return opacity * width / sqrt(max(texel.x * texel.y, 1e-20));
}
#endif
