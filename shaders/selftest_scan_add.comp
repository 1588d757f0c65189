#version 460
// Adds the (already scanned) totals of all previous blocks to every value of a block.
#include "shared/selftest.h"
#include "common.glsl"

layout(local_size_x = SCAN_WORKGROUP_SIZE) in;
layout(std430, binding = SCAN_BINDING_DATA) buffer Data { uint data[]; };
layout(std430, binding = SCAN_BINDING_SUMS) readonly buffer Sums { uint sums[]; };
layout(push_constant) uniform Push { ScanPush push; };

void main() {
  uint i = hpThreadId(SCAN_WORKGROUP_SIZE);
  uint block = i / SCAN_WORKGROUP_SIZE;
  if (i < push.count && block > 0u) data[i] += sums[block - 1u];
}
