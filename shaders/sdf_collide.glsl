// Keeps pearls outside a signed distance grid (shaders/shared/sdf.h) that moves with the head: the
// particle goes to head space, is pushed along the grid's gradient until the trilinear distance is at
// least the clearance (at most SDF_COLLISION_STEPS pushes), and comes back. The trilinear sample is
// engine/core/hair/sdf_grid.cpp's SdfGrid::sample, step for step; tests/compute/sim_reference.cpp does the same in
// double precision. Include after declaring nothing else on SDF_BINDING; the includer picks the binding number.
#include "shared/sdf.h"

layout(std430, binding = SDF_BINDING) readonly buffer SdfField {
  SdfHeader sdfHeader;
  float sdfValues[];
};

float sdfNode(uvec3 i) {
  uvec3 d = sdfHeader.dims.xyz;
  return sdfValues[(i.z * d.y + i.y) * d.x + i.x];
}

// The trilinear distance at p (plus the distance to the box outside it) in .w, and its gradient in .xyz: the
// interpolant's own derivative from the same 8 nodes (one read of each per push, where central differences
// took 48), zero along an axis on which p lies outside the box, plus the outside distance's.
vec4 sdfSampleGradient(vec3 p) {
  vec3 lo = sdfHeader.originCell.xyz;
  float cell = sdfHeader.originCell.w;
  vec3 hi = lo + cell * vec3(sdfHeader.dims.xyz - 1u);
  vec3 clamped = clamp(p, lo, hi);
  vec3 away = p - clamped;
  float outside = length(away);
  vec3 g = (clamped - lo) / cell;
  uvec3 i0 = min(uvec3(g), sdfHeader.dims.xyz - 2u);
  vec3 t = g - vec3(i0);
  float c000 = sdfNode(i0), c100 = sdfNode(i0 + uvec3(1, 0, 0));
  float c010 = sdfNode(i0 + uvec3(0, 1, 0)), c110 = sdfNode(i0 + uvec3(1, 1, 0));
  float c001 = sdfNode(i0 + uvec3(0, 0, 1)), c101 = sdfNode(i0 + uvec3(1, 0, 1));
  float c011 = sdfNode(i0 + uvec3(0, 1, 1)), c111 = sdfNode(i0 + uvec3(1, 1, 1));
  float x00 = mix(c000, c100, t.x), x10 = mix(c010, c110, t.x), x01 = mix(c001, c101, t.x), x11 = mix(c011, c111, t.x);
  float value = mix(mix(x00, x10, t.y), mix(x01, x11, t.y), t.z) + outside;
  vec3 d = vec3(mix(mix(c100 - c000, c110 - c010, t.y), mix(c101 - c001, c111 - c011, t.y), t.z),
                mix(mix(c010 - c000, c110 - c100, t.x), mix(c011 - c001, c111 - c101, t.x), t.z),
                mix(mix(c001 - c000, c101 - c100, t.x), mix(c011 - c010, c111 - c110, t.x), t.y)) / cell;
  d = vec3(away.x != 0.0 ? 0.0 : d.x, away.y != 0.0 ? 0.0 : d.y, away.z != 0.0 ? 0.0 : d.z);
  if (outside > 0.0) d += away / outside;
  return vec4(d, value);
}

// p in world space; head / headInverse map head space to world and back.
vec3 sdfKeepOutside(vec3 p, mat4 head, mat4 headInverse, float clearance) {
  if (sdfHeader.dims.w == 0u) return p;
  vec3 q = (headInverse * vec4(p, 1.0)).xyz;
  float halfCell = 0.5 * sdfHeader.originCell.w;
  bool moved = false;
  for (uint step = 0u; step < SDF_COLLISION_STEPS; ++step) {
    vec4 s = sdfSampleGradient(q);
    float depth = clearance - s.w;
    if (depth <= 0.0) break;
    vec3 g = s.xyz;
    // Central differences where the interpolant is flat, probe by probe in a loop with a per-lane count: llvmpipe
    // runs an if's body for every lane (this one cost 60% of the pass), but no iteration of a loop no lane enters.
    uint probes = dot(g, g) < SDF_FLAT_GRADIENT * SDF_FLAT_GRADIENT ? 6u : 0u;
    vec3 central = vec3(0.0);
    for (uint k = 0u; k < probes; ++k) {
      vec3 offset = vec3(0.0);
      offset[k >> 1u] = (k & 1u) == 0u ? halfCell : -halfCell;
      float v = sdfSampleGradient(q + offset).w;
      central[k >> 1u] += (k & 1u) == 0u ? v : -v;
    }
    if (probes > 0u) g = central / (2.0 * halfCell);
    float len = length(g);
    if (len < 1e-6) break;
    q += g * (depth / len);
    moved = true;
  }
  return moved ? (head * vec4(q, 1.0)).xyz : p;
}
