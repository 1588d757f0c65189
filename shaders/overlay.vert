#version 460
// The overlay's vertices pulled from a storage buffer (layout in shared/overlay.h).
#include "shared/overlay.h"

layout(std430, binding = OVERLAY_BINDING_VERTICES) readonly buffer Vertices { uint words[]; };
layout(push_constant) uniform Push { OverlayPush pc; };
layout(location = 0) out vec2 outUv;
layout(location = 1) out vec4 outColor;

void main() {
  const uint base = uint(gl_VertexIndex) * OVERLAY_VERTEX_WORDS;
  const vec2 pos = vec2(uintBitsToFloat(words[base]), uintBitsToFloat(words[base + 1]));
  outUv = vec2(uintBitsToFloat(words[base + 2]), uintBitsToFloat(words[base + 3]));
  outColor = unpackUnorm4x8(words[base + 4]);
  gl_Position = vec4(pos * pc.scale + pc.translate, 0.0, 1.0);
}
