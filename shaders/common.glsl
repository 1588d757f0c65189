// GLSL-only helpers shared by the compute shaders.
#ifndef HP_COMMON_GLSL
#define HP_COMMON_GLSL

// Flat invocation index for a grid that ComputePipeline::dispatch may have folded into 2D
// (when the group count exceeds maxComputeWorkGroupCount[0]). Callers bounds-check it.
// The workgroup size is passed in (the shared-header constant) rather than read from
// gl_WorkGroupSize: that built-in becomes a WorkgroupSize-decorated constant which lavapipe in
// Mesa 22.3 honours wrongly (every workgroup then runs a single invocation).
uint hpThreadId(uint workgroupSize) {
  return gl_GlobalInvocationID.x + gl_WorkGroupID.y * gl_NumWorkGroups.x * workgroupSize;
}

// Whether every component is finite (neither NaN nor infinite), read from the exponent bits: without a
// float-controls declaration a driver may assume float values are never NaN or infinite and fold isnan,
// isinf and NaN-aware comparisons away; an integer test it must keep.
bool allFinite(vec3 v) { return all(notEqual(floatBitsToUint(v) & 0x7F800000u, uvec3(0x7F800000u))); }
bool allFinite(vec4 v) { return all(notEqual(floatBitsToUint(v) & 0x7F800000u, uvec4(0x7F800000u))); }

#endif
