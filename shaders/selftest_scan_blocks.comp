#version 460
// Inclusive prefix sum of each block of SCAN_WORKGROUP_SIZE values, in place; writes each block's total.
#include "shared/selftest.h"
#include "common.glsl"

layout(local_size_x = SCAN_WORKGROUP_SIZE) in;
layout(std430, binding = SCAN_BINDING_DATA) buffer Data { uint data[]; };
layout(std430, binding = SCAN_BINDING_SUMS) buffer Sums { uint sums[]; };
layout(push_constant) uniform Push { ScanPush push; };

// Hillis-Steele with two ping-pong rows: each round reads one row and writes the other, so one
// barrier per round separates all reads of a row from the next writes to it.
shared uint rows[2][SCAN_WORKGROUP_SIZE];

void main() {
  uint i = hpThreadId(SCAN_WORKGROUP_SIZE);
  uint lane = gl_LocalInvocationID.x;
  rows[0][lane] = i < push.count ? data[i] : 0u;
  barrier();
  uint src = 0u;
  for (uint offset = 1u; offset < SCAN_WORKGROUP_SIZE; offset <<= 1u) {
    uint value = rows[src][lane];
    if (lane >= offset) value += rows[src][lane - offset];
    rows[1u - src][lane] = value;
    src = 1u - src;
    barrier();
  }
  if (i < push.count) data[i] = rows[src][lane];
  if (lane == SCAN_WORKGROUP_SIZE - 1u) sums[i / SCAN_WORKGROUP_SIZE] = rows[src][lane];
}
