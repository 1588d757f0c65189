#version 460
// One invocation per triangle of a posed character: its distance to the grid nodes near it, as keys lowered
// by atomicMin (shared/character.h, step 2).
#include "shared/character.h"
#include "common.glsl"

layout(local_size_x = CHARACTER_WORKGROUP_SIZE) in;
layout(push_constant) uniform Push { CharacterParams params; };
layout(std430, binding = CHARACTER_BINDING_POSED) readonly buffer Posed { vec4 posed[]; };
layout(std430, binding = CHARACTER_BINDING_POSED_NORMALS) readonly buffer PosedNormals { vec4 posedNormals[]; };
layout(std430, binding = CHARACTER_BINDING_TRIANGLES) readonly buffer Triangles { uvec4 triangles[]; };
layout(std430, binding = CHARACTER_BINDING_KEYS) buffer Keys { uint keys[]; };

// The point of triangle abc nearest to p, and where it lies: 0 inside the face, 1-3 at vertex a, b or c, 4-6 on
// edge ab, ac or bc (by the region of the triangle's plane p projects into).
vec3 closestOnTriangle(vec3 p, vec3 a, vec3 b, vec3 c, out uint region) {
  vec3 ab = b - a, ac = c - a, ap = p - a;
  float d1 = dot(ab, ap), d2 = dot(ac, ap);
  region = 1u;
  if (d1 <= 0.0 && d2 <= 0.0) return a;
  vec3 bp = p - b;
  float d3 = dot(ab, bp), d4 = dot(ac, bp);
  region = 2u;
  if (d3 >= 0.0 && d4 <= d3) return b;
  float vc = d1 * d4 - d3 * d2;
  region = 4u;
  if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) return a + ab * (d1 / (d1 - d3));
  vec3 cp = p - c;
  float d5 = dot(ab, cp), d6 = dot(ac, cp);
  region = 3u;
  if (d6 >= 0.0 && d5 <= d6) return c;
  float vb = d5 * d2 - d1 * d6;
  region = 5u;
  if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) return a + ac * (d2 / (d2 - d6));
  float va = d3 * d6 - d5 * d4;
  region = 6u;
  if (va <= 0.0 && (d4 - d3) >= 0.0 && (d5 - d6) >= 0.0) return b + (c - b) * ((d4 - d3) / ((d4 - d3) + (d5 - d6)));
  region = 0u;
  float denom = 1.0 / (va + vb + vc);
  return a + ab * (vb * denom) + ac * (vc * denom);
}

// The normal that says the side at a nearest point: the face's inside the face; at a vertex its (posed,
// smooth) normal, on an edge the sum of its two vertices': a face normal alone misjudges points near sharp
// edges and corners.
vec3 sideNormal(uint region, uvec3 tri, vec3 face) {
  switch (region) {
    case 1u: return posedNormals[tri.x].xyz;
    case 2u: return posedNormals[tri.y].xyz;
    case 3u: return posedNormals[tri.z].xyz;
    case 4u: return posedNormals[tri.x].xyz + posedNormals[tri.y].xyz;
    case 5u: return posedNormals[tri.x].xyz + posedNormals[tri.z].xyz;
    case 6u: return posedNormals[tri.y].xyz + posedNormals[tri.z].xyz;
    default: return face;
  }
}

void main() {
  // One invocation per triangle and z slice of its box: a bounded loop each (lavapipe ends a shader's loops after
  // 65535 iterations in all).
  uint id = hpThreadId(CHARACTER_WORKGROUP_SIZE);
  uint t = id / params.counts.w, slice = id % params.counts.w;
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
  int z = lo.z + int(slice);
  if (z > hi.z) return;
  for (int y = lo.y; y <= hi.y; ++y)
    for (int x = lo.x; x <= hi.x; ++x) {
      vec3 p = origin + cell * vec3(x, y, z);
      uint region;
      vec3 q = closestOnTriangle(p, a, b, c, region);
      float d = length(p - q);
      if (d > band) continue;
      uint inside = dot(p - q, sideNormal(region, tri, normal)) < 0.0 ? 1u : 0u;  // a tie: outside wins
      uint node = (uint(z) * params.dims.y + uint(y)) * params.dims.x + uint(x);
      atomicMin(keys[node], (floatBitsToUint(d) & ~1u) | inside);
    }
}
