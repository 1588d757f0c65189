#version 460
// Interpolation (REFERENCES.md §1): render strand s of a scalp triangle with guides A, B, C and
// barycentrics X is K_j = X1 A_j + X2 B_j + X3 C_j for every vertex j of the smoothed guides.
// Tangents: the guides' unit tangents blended with the same weights and renormalised (A's tangent if
// the blend vanishes). One invocation per output vertex of one chunk; vertex 0 also writes the
// strand's attributes (makeStrandAttributes in shared/strands.h).
// Debug mode INTERPOLATE_MODE_GUIDES: strand s is smoothed guide firstStrand + s, copied as is.
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

void copyGuide(uint id, uint s, uint j) {
  uint guide = push.firstStrand + s;
  uint src = guide * push.vertices + j;
  positions[id] = guidePositions[src];
  tangents[id] = guideTangents[src];
  if (j == 0u) attributes[s] = makeStrandAttributes(strandHash01(guide, 0u), guide);
}

void interpolate(uint id, uint s, uint j) {
  StrandBindingGpu b = bindings[s];
  uvec3 tri = triangles[b.triangle].xyz * push.vertices + j;
  vec3 w = vec3(b.x1, b.x2, max(0.0, 1.0 - b.x1 - b.x2));
  vec4 pa = guidePositions[tri.x];
  vec3 pos = w.x * pa.xyz + w.y * guidePositions[tri.y].xyz + w.z * guidePositions[tri.z].xyz;
  vec3 ta = guideTangents[tri.x].xyz;
  vec3 tan = w.x * ta + w.y * guideTangents[tri.y].xyz + w.z * guideTangents[tri.z].xyz;
  float len2 = dot(tan, tan);
  tan = len2 > 1e-30 ? tan * inversesqrt(len2) : ta;
  positions[id] = vec4(pos, pa.w);  // w = v, the same for all guides
  tangents[id] = vec4(tan, 0.0);
  if (j == 0u) attributes[s] = makeStrandAttributes(b.random, b.triangle);
}

void main() {
  uint id = hpThreadId(INTERPOLATE_WORKGROUP_SIZE);
  if (id >= push.strandCount * push.vertices) return;
  uint s = id / push.vertices;
  uint j = id - s * push.vertices;
  if (push.mode == INTERPOLATE_MODE_GUIDES)
    copyGuide(id, s, j);
  else
    interpolate(id, s, j);
}
