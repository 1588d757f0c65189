// Shared by GLSL and C++: the benchmarks' compute copy (samples/tools/copy_reference.h), the yardstick
// beside vkCmdCopyBuffer: some GPUs' transfer copies reach a fraction of what a shader's loads and stores do.
#ifndef HP_SHARED_COPY_REFERENCE_H
#define HP_SHARED_COPY_REFERENCE_H
#include "common.h"  // relative to this header: works for glslc and C++ alike

HP_BEGIN
HP_CONST(uint, COPY_WORKGROUP_SIZE, 64)
HP_CONST(uint, COPY_BINDING_SOURCE, 0)       // uvec4[]
HP_CONST(uint, COPY_BINDING_DESTINATION, 1)  // uvec4[]

struct CopyPush {
  uint count;  // uvec4 elements to copy
};
HP_END

#ifdef __cplusplus
static_assert(sizeof(hp::gpu::CopyPush) == 4);
#endif
#endif
