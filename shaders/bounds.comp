#version 460
#extension GL_KHR_shader_subgroup_basic : require
#extension GL_KHR_shader_subgroup_arithmetic : require
// Light-space bounds of the render strands (shared/opacity.h), two modes:
//  REDUCE:   each invocation folds BOUNDS_VERTICES_PER_THREAD vertices of one chunk into a min/max of
//            light (x, y, d) (spot: (x/d, y/d, d)); the subgroup reduces them (subgroupMin/Max) and one of its
//            invocations merges the result into LightSpace.minBits/maxBits with atomicMin/atomicMax on
//            order-preserving uint encodings (one atomic per component per subgroup, not per vertex; no
//            shared memory or barrier: lavapipe ran the pass in half the time, 5 against 10 ms).
//  FINALIZE: one invocation reads the accumulators, pads the x/y box, builds the orthographic
//            (directional) or perspective (spot) viewProj and the slice depths, and re-arms the
//            accumulators for the next frame.
#include "shared/opacity.h"
#include "common.glsl"

layout(local_size_x = BOUNDS_WORKGROUP_SIZE) in;
layout(std430, binding = BOUNDS_BINDING_POSITIONS) readonly buffer Positions { vec4 positions[]; };
layout(std430, binding = BOUNDS_BINDING_LIGHT) buffer Light { LightSpace lights[]; };
layout(push_constant) uniform Push { BoundsPush push; };

const float BIG = 3.0e38;

vec3 lightCoords(vec3 p) {
  return vec3(dot(push.row0.xyz, p), dot(push.row1.xyz, p), -dot(push.row2.xyz, p));
}

// What is reduced for vertex p: (x, y, d) for a directional light, (x/d, y/d, d) for a spot; false
// for a vertex at or behind the spot (it can shadow nothing inside the cone) or not finite.
bool reducedCoords(vec3 p, out vec3 c) {
  if (!allFinite(p)) return false;  // a NaN guide's strands: min/max of a NaN is undefined
  if (push.perspective == 0u) {
    c = lightCoords(p);
    return true;
  }
  c = lightCoords(p - push.origin.xyz);
  if (!(c.z > push.nearLimit)) return false;
  c.xy /= c.z;
  return true;
}

void reduce() {
  uint local = gl_LocalInvocationID.x;
  uint group = hpThreadId(BOUNDS_WORKGROUP_SIZE) / BOUNDS_WORKGROUP_SIZE;
  // Consecutive invocations read consecutive vertices in every step of the loop.
  uint base = group * BOUNDS_WORKGROUP_SIZE * BOUNDS_VERTICES_PER_THREAD + local;
  vec3 lo = vec3(BIG), hi = vec3(-BIG);
  for (uint k = 0u; k < BOUNDS_VERTICES_PER_THREAD; ++k) {
    uint v = base + k * BOUNDS_WORKGROUP_SIZE;
    vec3 c;
    if (v < push.vertexCount && reducedCoords(positions[v].xyz, c)) {
      lo = min(lo, c);
      hi = max(hi, c);
    }
  }
  lo = subgroupMin(lo);
  hi = subgroupMax(hi);
  if (!subgroupElect() || lo.x > hi.x) return;  // an empty subgroup changes nothing
  for (int c = 0; c < 3; ++c) {
    atomicMin(lights[push.slot].minBits[c], orderedFromFloat(lo[c]));
    atomicMax(lights[push.slot].maxBits[c], orderedFromFloat(hi[c]));
  }
}

// World -> clip rows for a directional light: orthographic over the x/y box [xyLo, xyHi].
mat4 orthographicViewProj(vec2 xyLo, vec2 xyHi, float zNear, float zFar) {
  vec2 scale = 2.0 / (xyHi - xyLo);
  float zScale = 1.0 / (zFar - zNear);
  // Rows of world -> clip: clip.x = scale.x (row0.p - xyLo.x) - 1, clip.y likewise,
  // clip.z = (-row2.p - zNear) / (zFar - zNear), clip.w = 1.
  vec4 r0 = vec4(push.row0.xyz * scale.x, -xyLo.x * scale.x - 1.0);
  vec4 r1 = vec4(push.row1.xyz * scale.y, -xyLo.y * scale.y - 1.0);
  vec4 r2 = vec4(-push.row2.xyz * zScale, -zNear * zScale);
  return transpose(mat4(r0, r1, r2, vec4(0.0, 0.0, 0.0, 1.0)));
}

// World -> clip rows for a spot at o over the box [xyLo, xyHi] of (x/d, y/d): clip.w = d,
// clip.x = scale.x (x - xyLo.x d) - d (so clip.x / d spans [-1, 1]), clip.y likewise, and
// clip.z = (d - zNear) / (zFar - zNear), linear in d (see shared/opacity.h).
mat4 perspectiveViewProj(vec2 xyLo, vec2 xyHi, float zNear, float zFar) {
  vec2 scale = 2.0 / (xyHi - xyLo);
  float zScale = 1.0 / (zFar - zNear);
  vec3 o = push.origin.xyz;
  // x = r0.(p - o) and d = -r2.(p - o): a row R applied to (p - o) is vec4(R, -R.o).
  vec3 a0 = push.row0.xyz * scale.x + push.row2.xyz * (xyLo.x * scale.x + 1.0);
  vec3 a1 = push.row1.xyz * scale.y + push.row2.xyz * (xyLo.y * scale.y + 1.0);
  vec3 a2 = -push.row2.xyz * zScale;
  vec3 a3 = -push.row2.xyz;
  vec4 r0 = vec4(a0, -dot(a0, o));
  vec4 r1 = vec4(a1, -dot(a1, o));
  vec4 r2 = vec4(a2, -dot(a2, o) - zNear * zScale);
  vec4 r3 = vec4(a3, -dot(a3, o));
  return transpose(mat4(r0, r1, r2, r3));
}

void finalize() {
  if (hpThreadId(BOUNDS_WORKGROUP_SIZE) != 0u) return;
  vec3 lo = vec3(floatFromOrdered(lights[push.slot].minBits.x), floatFromOrdered(lights[push.slot].minBits.y), floatFromOrdered(lights[push.slot].minBits.z));
  vec3 hi = vec3(floatFromOrdered(lights[push.slot].maxBits.x), floatFromOrdered(lights[push.slot].maxBits.y), floatFromOrdered(lights[push.slot].maxBits.z));
  bool spot = push.perspective != 0u;
  if (!(lo.x <= hi.x)) {  // no vertices: a unit box (spot: the cone, depths [1, 2]), nothing will be drawn into it
    lo = spot ? vec3(-push.tanCone, -push.tanCone, 1.0) : vec3(-1.0);
    hi = spot ? vec3(push.tanCone, push.tanCone, 2.0) : vec3(1.0);
  }
  if (spot) {  // nothing outside the cone is lit, so the map never covers more than the cone
    lo.xy = clamp(lo.xy, vec2(-push.tanCone), vec2(push.tanCone));
    hi.xy = clamp(hi.xy, lo.xy, vec2(push.tanCone));
  }
  // x/y: pad by the strand half-width plus a few texels, so ribbons and linear filtering stay inside.
  // For a spot the box is in x/d: half a strand at the nearest depth is marginWorld / z_near.
  vec2 size = max(hi.xy - lo.xy, vec2(1e-6));
  float margin = spot ? push.marginWorld / lo.z : push.marginWorld;
  vec2 pad = vec2(margin) + size * (push.marginTexels / float(push.resolution));
  vec2 xyLo = lo.xy - pad, xyHi = hi.xy + pad;
  // Depth: exactly [z_near, z_far] of the vertices (docs/THEORY.md §5.2), never a zero-thick range.
  float zNear = lo.z;
  float zFar = max(hi.z, zNear + max(1e-6, abs(zNear) * 1e-6));
  float dz = (zFar - zNear) / float(OPACITY_SLICES);

  lights[push.slot].viewProj = spot ? perspectiveViewProj(xyLo, xyHi, zNear, zFar) : orthographicViewProj(xyLo, xyHi, zNear, zFar);
  lights[push.slot].depthRange = vec4(zNear, zFar, dz, 1.0 / dz);
  lights[push.slot].extent = vec4(xyLo, xyHi);
  lights[push.slot].minBits = uvec4(orderedFromFloat(BIG));
  lights[push.slot].maxBits = uvec4(orderedFromFloat(-BIG));
}

void main() {
  if (push.mode == BOUNDS_MODE_FINALIZE)
    finalize();
  else
    reduce();
}
