#version 460
// Light-space bounds of the render strands (shared/opacity.h), two modes:
//  REDUCE:   each invocation folds BOUNDS_VERTICES_PER_THREAD vertices of one chunk into a min/max of
//            light (x, y, d); a shared-memory tree reduces the workgroup; invocation 0 merges the
//            group's result into LightSpace.minBits/maxBits with atomicMin/atomicMax on
//            order-preserving uint encodings (one atomic per component per group, not per vertex).
//  FINALIZE: one invocation reads the accumulators, pads the x/y box, builds the orthographic
//            viewProj and the slice depths, and re-arms the accumulators for the next frame.
#include "shared/opacity.h"
#include "common.glsl"

layout(local_size_x = BOUNDS_WORKGROUP_SIZE) in;
layout(std430, binding = BOUNDS_BINDING_POSITIONS) readonly buffer Positions { vec4 positions[]; };
layout(std430, binding = BOUNDS_BINDING_LIGHT) buffer Light { LightSpace light; };
layout(push_constant) uniform Push { BoundsPush push; };

const float BIG = 3.0e38;
shared vec3 sMin[BOUNDS_WORKGROUP_SIZE];
shared vec3 sMax[BOUNDS_WORKGROUP_SIZE];

vec3 lightCoords(vec3 p) {
  return vec3(dot(push.row0.xyz, p), dot(push.row1.xyz, p), -dot(push.row2.xyz, p));
}

void reduce() {
  uint local = gl_LocalInvocationID.x;
  uint group = hpThreadId(BOUNDS_WORKGROUP_SIZE) / BOUNDS_WORKGROUP_SIZE;
  // Consecutive invocations read consecutive vertices in every step of the loop.
  uint base = group * BOUNDS_WORKGROUP_SIZE * BOUNDS_VERTICES_PER_THREAD + local;
  vec3 lo = vec3(BIG), hi = vec3(-BIG);
  for (uint k = 0u; k < BOUNDS_VERTICES_PER_THREAD; ++k) {
    uint v = base + k * BOUNDS_WORKGROUP_SIZE;
    if (v < push.vertexCount) {
      vec3 c = lightCoords(positions[v].xyz);
      lo = min(lo, c);
      hi = max(hi, c);
    }
  }
  sMin[local] = lo;
  sMax[local] = hi;
  barrier();
  for (uint stride = BOUNDS_WORKGROUP_SIZE / 2u; stride > 0u; stride >>= 1u) {
    if (local < stride) {
      sMin[local] = min(sMin[local], sMin[local + stride]);
      sMax[local] = max(sMax[local], sMax[local + stride]);
    }
    barrier();
  }
  if (local != 0u || sMin[0].x > sMax[0].x) return;  // an empty group changes nothing
  for (int c = 0; c < 3; ++c) {
    atomicMin(light.minBits[c], orderedFromFloat(sMin[0][c]));
    atomicMax(light.maxBits[c], orderedFromFloat(sMax[0][c]));
  }
}

void finalize() {
  if (hpThreadId(BOUNDS_WORKGROUP_SIZE) != 0u) return;
  vec3 lo = vec3(floatFromOrdered(light.minBits.x), floatFromOrdered(light.minBits.y), floatFromOrdered(light.minBits.z));
  vec3 hi = vec3(floatFromOrdered(light.maxBits.x), floatFromOrdered(light.maxBits.y), floatFromOrdered(light.maxBits.z));
  if (!(lo.x <= hi.x)) {  // no vertices: a unit box, nothing will be drawn into it
    lo = vec3(-1.0);
    hi = vec3(1.0);
  }
  // x/y: pad by the strand half-width plus a few texels, so ribbons and linear filtering stay inside.
  vec2 size = max(hi.xy - lo.xy, vec2(1e-6));
  vec2 pad = vec2(push.marginWorld) + size * (push.marginTexels / float(push.resolution));
  vec2 xyLo = lo.xy - pad, xyHi = hi.xy + pad;
  // Depth: exactly [z_near, z_far] of the vertices (REFERENCES §4), never a zero-thick range.
  float zNear = lo.z;
  float zFar = max(hi.z, zNear + max(1e-6, abs(zNear) * 1e-6));
  float dz = (zFar - zNear) / float(OPACITY_SLICES);

  vec2 scale = 2.0 / (xyHi - xyLo);
  float zScale = 1.0 / (zFar - zNear);
  // Rows of world -> clip: clip.x = scale.x (row0.p - xyLo.x) - 1, clip.y likewise,
  // clip.z = (-row2.p - zNear) / (zFar - zNear), clip.w = 1.
  vec4 r0 = vec4(push.row0.xyz * scale.x, -xyLo.x * scale.x - 1.0);
  vec4 r1 = vec4(push.row1.xyz * scale.y, -xyLo.y * scale.y - 1.0);
  vec4 r2 = vec4(-push.row2.xyz * zScale, -zNear * zScale);
  light.viewProj = transpose(mat4(r0, r1, r2, vec4(0.0, 0.0, 0.0, 1.0)));
  light.depthRange = vec4(zNear, zFar, dz, 1.0 / dz);
  light.extent = vec4(xyLo, xyHi);
  light.minBits = uvec4(orderedFromFloat(BIG));
  light.maxBits = uvec4(orderedFromFloat(-BIG));
}

void main() {
  if (push.mode == BOUNDS_MODE_FINALIZE)
    finalize();
  else
    reduce();
}
