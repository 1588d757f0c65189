#version 460
// Interpolation (docs/THEORY.md §1.4): render strand s of a scalp triangle with guides A, B, C and
// barycentrics X is K_j = X1 A_j + X2 B_j + X3 C_j for every vertex j of the smoothed guides.
// Tangents: the guides' unit tangents blended with the same weights and renormalised (A's tangent if
// the blend vanishes). Also writes the strand's attributes (makeStrandAttributes, shared/strands.h).
// Debug mode INTERPOLATE_MODE_GUIDES: strand s is smoothed guide firstStrand + s, copied as is.
// One invocation per strand of one chunk, looping over its Q vertices: the binding and triangle are
// read once per strand instead of once per vertex (1.65x faster on lavapipe than one invocation per
// vertex, docs/PERFORMANCE.md); lanes write Q*16 bytes apart, which caches merge on GPUs.
#include "shared/strands.h"
#include "common.glsl"

layout(local_size_x = INTERPOLATE_WORKGROUP_SIZE) in;
layout(std430, binding = INTERPOLATE_BINDING_GUIDE_POSITIONS) readonly buffer GuidePositions { vec4 guidePositions[]; };
layout(std430, binding = INTERPOLATE_BINDING_GUIDE_TANGENTS) readonly buffer GuideTangents { vec4 guideTangents[]; };
layout(std430, binding = INTERPOLATE_BINDING_TRIANGLES) readonly buffer Triangles { uvec4 triangles[]; };
layout(std430, binding = INTERPOLATE_BINDING_BINDINGS) readonly buffer Bindings { StrandBindingGpu bindings[]; };
layout(std430, binding = INTERPOLATE_BINDING_POSITIONS) writeonly buffer Positions { vec4 positions[]; };
layout(std430, binding = INTERPOLATE_BINDING_TANGENTS) writeonly buffer Tangents { vec4 tangents[]; };
layout(std430, binding = INTERPOLATE_BINDING_ATTRIBUTES) writeonly buffer Attributes { StrandAttributes attributes[]; };
layout(push_constant) uniform Push { InterpolatePush push; };

void copyGuide(uint s) {
  uint guide = push.firstStrand + s;
  uint src = guide * push.vertices, dst = s * push.vertices;
  for (uint j = 0u; j < push.vertices; ++j) {
    positions[dst + j] = guidePositions[src + j];
    tangents[dst + j] = guideTangents[src + j];
  }
  attributes[s] = makeStrandAttributes(strandHash01(guide, 0u), guide);
}

void interpolate(uint s) {
  StrandBindingGpu b = bindings[s];
  uvec3 src = triangles[b.triangle].xyz * push.vertices;
  vec3 w = vec3(b.x1, b.x2, max(0.0, 1.0 - b.x1 - b.x2));
  uint dst = s * push.vertices;
  for (uint j = 0u; j < push.vertices; ++j) {
    vec4 pa = guidePositions[src.x + j];
    vec3 pos = w.x * pa.xyz + w.y * guidePositions[src.y + j].xyz + w.z * guidePositions[src.z + j].xyz;
    vec3 ta = guideTangents[src.x + j].xyz;
    vec3 tan = w.x * ta + w.y * guideTangents[src.y + j].xyz + w.z * guideTangents[src.z + j].xyz;
    float len2 = dot(tan, tan);
    tan = len2 > 1e-30 ? tan * inversesqrt(len2) : ta;
    positions[dst + j] = vec4(pos, pa.w);  // w = v, the same for all guides
    tangents[dst + j] = vec4(tan, 0.0);
  }
  attributes[s] = makeStrandAttributes(b.random, b.triangle);
}

void main() {
  uint s = hpThreadId(INTERPOLATE_WORKGROUP_SIZE);
  if (s >= push.strandCount) return;
  if (push.mode == INTERPOLATE_MODE_GUIDES)
    copyGuide(s);
  else
    interpolate(s);
}
