#version 460
// Pulls pixel-space vertices from a storage buffer and maps them to clip space (the viewport is Y-flipped).
#include "shared/selftest.h"

layout(std430, binding = DRAW_BINDING_VERTICES) readonly buffer Vertices { vec4 vertices[]; };
layout(push_constant) uniform Push { FlatDrawPush push; };

void main() {
  vec2 p = vertices[gl_VertexIndex].xy / push.viewportSize;
  gl_Position = vec4(p.x * 2.0 - 1.0, 1.0 - p.y * 2.0, 0.0, 1.0);
}
