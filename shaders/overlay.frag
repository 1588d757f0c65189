#version 460
// Texture x vertex colour. The colours are authored in sRGB and the target is an sRGB format, which
// encodes on write: decode them first so they land unchanged.
#include "shared/overlay.h"

layout(binding = OVERLAY_BINDING_TEXTURE) uniform sampler2D atlas;
layout(location = 0) in vec2 uv;
layout(location = 1) in vec4 color;
layout(location = 0) out vec4 outColor;

vec3 srgbToLinear(vec3 c) {
  return mix(c / 12.92, pow((c + 0.055) / 1.055, vec3(2.4)), greaterThan(c, vec3(0.04045)));
}

void main() {
  const vec4 c = color * texture(atlas, uv);
  outColor = vec4(srgbToLinear(c.rgb), c.a);
}
