#version 460
// Linear HDR -> display: exposure, then a filmic curve (Narkowicz's fit of ACES). The target is an
// sRGB format, so the hardware applies the sRGB transfer function on store.
#include "shared/render.h"

layout(binding = TONEMAP_BINDING_HDR) uniform sampler2D hdr;
layout(push_constant) uniform Push { TonemapPush push; };
layout(location = 0) in vec2 inUv;
layout(location = 0) out vec4 outColor;

vec3 filmic(vec3 x) {
  return clamp((x * (2.51 * x + 0.03)) / (x * (2.43 * x + 0.59) + 0.14), 0.0, 1.0);
}

void main() {
  // The viewport is Y-flipped (clip +Y is up), so uv.y = 0 is the bottom row: row 0 of hdr is the top.
  vec3 c = texture(hdr, vec2(inUv.x, 1.0 - inUv.y)).rgb * push.exposure;
  outColor = vec4(filmic(c), 1.0);
}
