#version 460
// Opacity maps, strands (docs/THEORY.md §5): every segment of every render strand as a line seen from
// the light, pulled from the chunk's position buffer (line list, 2 vertices per segment). The light
// depth travels as the slice coordinate s = 16 clip.z (linear in light depth, so perspective-correct
// interpolation keeps it exact for a spot); clip z is half of w so no hair or head part in front of
// the light is ever depth-clipped (there is no depth test: opacity is additive, order-independent).
// For a spot, parts behind it (w <= 0) are clipped: they cannot shadow anything in the cone.
#include "shared/opacity.h"
#include "opacity_footprint.glsl"

layout(std430, binding = OPACITY_BINDING_POSITIONS) readonly buffer Positions { vec4 positions[]; };
layout(std430, binding = OPACITY_BINDING_LIGHT) readonly buffer Light { LightSpace lights[]; };
layout(push_constant) uniform Push { OpacityPush push; };

layout(location = 0) out float outSlice;
layout(location = 1) out float outOpacity;

void main() {
  uint q = push.verticesPerStrand;
  uint segment = gl_VertexIndex / 2u;
  uint strand = segment / (q - 1u);
  uint k = segment % (q - 1u);
  uint v = strand * q + k + (gl_VertexIndex & 1u);
  LightSpace light = lights[push.slot];
  vec4 clip = light.viewProj * vec4(positions[v].xyz, 1.0);
  outSlice = clip.z * float(OPACITY_SLICES);
  float along = float(k + (uint(gl_VertexIndex) & 1u)) / float(q - 1u);
  outOpacity = strandFragmentOpacity(light, push.footprint, push.opacity, along, clip.w);
  gl_Position = vec4(clip.xy, 0.5 * clip.w, clip.w);  // w = 1 (directional) or spot depth
}
