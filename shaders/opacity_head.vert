#version 460
// Opacity maps, head occluder: the head mesh (pulled by index) seen from the light, drawn with a large
// per-fragment opacity so everything behind its surface is in shadow. Same output as opacity.vert.
#include "shared/opacity.h"

layout(std430, binding = OPACITY_BINDING_POSITIONS) readonly buffer Positions { vec4 positions[]; };
layout(std430, binding = OPACITY_BINDING_INDICES) readonly buffer Indices { uint indices[]; };
layout(std430, binding = OPACITY_BINDING_LIGHT) readonly buffer Light { LightSpace lights[]; };
layout(push_constant) uniform Push { OpacityPush push; };

layout(location = 0) out float outSlice;
layout(location = 1) out float outOpacity;

void main() {
  vec4 world = push.headToWorld * vec4(positions[indices[gl_VertexIndex]].xyz, 1.0);
  LightSpace light = lights[push.slot];
  vec4 clip = light.viewProj * world;
  outSlice = clip.z * float(OPACITY_SLICES);
  outOpacity = push.opacity;
  gl_Position = vec4(clip.xy, 0.5 * clip.w, clip.w);  // w = 1 (directional) or spot depth
}
