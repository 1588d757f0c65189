// Keeps pearls outside a signed distance grid (shaders/shared/sdf.h) that moves with the head: the
// particle goes to head space, is pushed along the grid's gradient until the trilinear distance is at
// least the clearance (at most SDF_COLLISION_STEPS pushes), and comes back. The trilinear sample is
// engine/core/hair/sdf_grid.cpp's SdfGrid::sample, step for step. Include after declaring nothing else
// on SDF_BINDING; the includer picks the binding number.
#include "shared/sdf.h"

layout(std430, binding = SDF_BINDING) readonly buffer SdfField {
  SdfHeader sdfHeader;
  float sdfValues[];
};

float sdfNode(uvec3 i) {
  uvec3 d = sdfHeader.dims.xyz;
  return sdfValues[(i.z * d.y + i.y) * d.x + i.x];
}

float sdfSample(vec3 p) {
  vec3 lo = sdfHeader.originCell.xyz;
  float cell = sdfHeader.originCell.w;
  vec3 hi = lo + cell * vec3(sdfHeader.dims.xyz - 1u);
  vec3 clamped = clamp(p, lo, hi);
  float outside = length(p - clamped);
  vec3 g = (clamped - lo) / cell;
  uvec3 i0 = min(uvec3(g), sdfHeader.dims.xyz - 2u);
  vec3 t = g - vec3(i0);
  float x00 = mix(sdfNode(i0), sdfNode(i0 + uvec3(1, 0, 0)), t.x);
  float x10 = mix(sdfNode(i0 + uvec3(0, 1, 0)), sdfNode(i0 + uvec3(1, 1, 0)), t.x);
  float x01 = mix(sdfNode(i0 + uvec3(0, 0, 1)), sdfNode(i0 + uvec3(1, 0, 1)), t.x);
  float x11 = mix(sdfNode(i0 + uvec3(0, 1, 1)), sdfNode(i0 + uvec3(1, 1, 1)), t.x);
  return mix(mix(x00, x10, t.y), mix(x01, x11, t.y), t.z) + outside;
}

vec3 sdfGradient(vec3 p) {
  float h = 0.5 * sdfHeader.originCell.w;
  return vec3(sdfSample(p + vec3(h, 0, 0)) - sdfSample(p - vec3(h, 0, 0)),
              sdfSample(p + vec3(0, h, 0)) - sdfSample(p - vec3(0, h, 0)),
              sdfSample(p + vec3(0, 0, h)) - sdfSample(p - vec3(0, 0, h))) / (2.0 * h);
}

// p in world space; head / headInverse map head space to world and back.
vec3 sdfKeepOutside(vec3 p, mat4 head, mat4 headInverse, float clearance) {
  if (sdfHeader.dims.w == 0u) return p;
  vec3 q = (headInverse * vec4(p, 1.0)).xyz;
  bool moved = false;
  for (uint step = 0u; step < SDF_COLLISION_STEPS; ++step) {
    float depth = clearance - sdfSample(q);
    if (depth <= 0.0) break;
    vec3 g = sdfGradient(q);
    float len = length(g);
    if (len < 1e-6) break;
    q += g * (depth / len);
    moved = true;
  }
  return moved ? (head * vec4(q, 1.0)).xyz : p;
}
