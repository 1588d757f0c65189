#version 460
// One invocation per triangle of a posed character: its distance to the grid nodes near it, as keys lowered
// by atomicMin (shared/character.h, step 2).
#include "shared/character.h"
#include "common.glsl"

layout(local_size_x = CHARACTER_WORKGROUP_SIZE) in;
layout(push_constant) uniform Push { CharacterParams params; };
layout(std430, binding = CHARACTER_BINDING_POSED) readonly buffer Posed { vec4 posed[]; };
layout(std430, binding = CHARACTER_BINDING_TRIANGLES) readonly buffer Triangles { uvec4 triangles[]; };
layout(std430, binding = CHARACTER_BINDING_KEYS) buffer Keys { uint keys[]; };

// The point of triangle abc nearest to p (by the region of the triangle's plane p projects into).
vec3 closestOnTriangle(vec3 p, vec3 a, vec3 b, vec3 c) {
  vec3 ab = b - a, ac = c - a, ap = p - a;
  float d1 = dot(ab, ap), d2 = dot(ac, ap);
  if (d1 <= 0.0 && d2 <= 0.0) return a;
  vec3 bp = p - b;
  float d3 = dot(ab, bp), d4 = dot(ac, bp);
  if (d3 >= 0.0 && d4 <= d3) return b;
  float vc = d1 * d4 - d3 * d2;
  if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) return a + ab * (d1 / (d1 - d3));
  vec3 cp = p - c;
  float d5 = dot(ab, cp), d6 = dot(ac, cp);
  if (d6 >= 0.0 && d5 <= d6) return c;
  float vb = d5 * d2 - d1 * d6;
  if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) return a + ac * (d2 / (d2 - d6));
  float va = d3 * d6 - d5 * d4;
  if (va <= 0.0 && (d4 - d3) >= 0.0 && (d5 - d6) >= 0.0) return b + (c - b) * ((d4 - d3) / ((d4 - d3) + (d5 - d6)));
  float denom = 1.0 / (va + vb + vc);
  return a + ab * (vb * denom) + ac * (vc * denom);
}

void main() {
  uint t = hpThreadId(CHARACTER_WORKGROUP_SIZE);
  if (t >= params.counts.y) return;
  uvec3 tri = triangles[t].xyz;
  vec3 a = posed[tri.x].xyz, b = posed[tri.y].xyz, c = posed[tri.z].xyz;
  vec3 normal = cross(b - a, c - a);
  if (dot(normal, normal) <= 0.0) return;  // degenerate in this pose
  float cell = params.originCell.w, band = float(params.counts.z) * cell;
  vec3 origin = params.originCell.xyz;
  ivec3 last = ivec3(params.dims.xyz) - 1;
  ivec3 lo = clamp(ivec3(floor((min(a, min(b, c)) - band - origin) / cell)), ivec3(0), last);
  ivec3 hi = clamp(ivec3(ceil((max(a, max(b, c)) + band - origin) / cell)), ivec3(0), last);
  for (int z = lo.z; z <= hi.z; ++z)
    for (int y = lo.y; y <= hi.y; ++y)
      for (int x = lo.x; x <= hi.x; ++x) {
        vec3 p = origin + cell * vec3(x, y, z);
        vec3 q = closestOnTriangle(p, a, b, c);
        float d = length(p - q);
        if (d > band) continue;
        uint outside = dot(p - q, normal) < 0.0 ? 0u : 1u;
        uint node = (uint(z) * params.dims.y + uint(y)) * params.dims.x + uint(x);
        atomicMin(keys[node], (floatBitsToUint(d) & ~1u) | outside);
      }
}
