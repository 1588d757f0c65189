#version 460
// The benchmarks' compute copy (shared/copy_reference.h): one 16-byte element per invocation, so a warp's
// loads and stores are contiguous. Its bandwidth is a yardstick of what the device's memory delivers to
// shaders; it copies, it computes nothing.
#include "shared/copy_reference.h"
#include "common.glsl"

layout(local_size_x = COPY_WORKGROUP_SIZE) in;
layout(std430, binding = COPY_BINDING_SOURCE) readonly buffer Source { uvec4 source[]; };
layout(std430, binding = COPY_BINDING_DESTINATION) writeonly buffer Destination { uvec4 destination[]; };
layout(push_constant) uniform Push { CopyPush push; };

void main() {
  uint i = hpThreadId(COPY_WORKGROUP_SIZE);
  if (i < push.count) destination[i] = source[i];
}
