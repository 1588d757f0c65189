#version 460
// Linear HDR -> display: exposure, then the filmic curve of shared/tonemap.h. The target is an
// sRGB format, so the hardware applies the sRGB transfer function on store.
#include "shared/render.h"
#include "shared/tonemap.h"

layout(binding = TONEMAP_BINDING_HDR) uniform sampler2D hdr;
layout(push_constant) uniform Push { TonemapPush push; };
layout(location = 0) in vec2 inUv;
layout(location = 0) out vec4 outColor;

void main() {
  // The viewport is Y-flipped (clip +Y is up), so uv.y = 0 is the bottom row: row 0 of hdr is the top.
  vec3 c = texture(hdr, vec2(inUv.x, 1.0 - inUv.y)).rgb * push.exposure;
  outColor = vec4(tonemapFilmic(c.r), tonemapFilmic(c.g), tonemapFilmic(c.b), 1.0);
}
