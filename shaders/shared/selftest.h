// Shared by GLSL and C++: the self-test kernels that prove the Vulkan layer (prefix sum, a flat draw) and
// evaluate GLSL-only functions against the CPU (the opacity lookup).
#ifndef HP_SHARED_SELFTEST_H
#define HP_SHARED_SELFTEST_H
#include "common.h"  // relative to this header: works for glslc and C++ alike

HP_BEGIN
HP_CONST(uint, SCAN_WORKGROUP_SIZE, 256)
HP_CONST(uint, SCAN_BINDING_DATA, 0)     // uint[]: scanned in place, block by block
HP_CONST(uint, SCAN_BINDING_SUMS, 1)     // uint[]: one total per block (output of scan, input of add)
HP_CONST(uint, DRAW_BINDING_VERTICES, 0) // vec4[]: xy in pixels
HP_CONST(uint, LOOKUP_WORKGROUP_SIZE, 64)
HP_CONST(uint, LOOKUP_BINDING_MAPS, 0)     // sampler2DArray: one shadow slot's OPACITY_LAYERS layers, 1 x 1
HP_CONST(uint, LOOKUP_BINDING_QUERIES, 1)  // vec4[]: x = slice coordinate s, y = bias, z = 1 for a deep map
HP_CONST(uint, LOOKUP_BINDING_RESULTS, 2)  // float[]: hairpipeShadowAlpha at each query
// selftest_hair_shadows.comp: an application's receivers, through the public hair_shadows.glsl alone.
HP_CONST(uint, HAIR_SHADOW_TEST_BINDING_MAPS, 0)     // sampler2DArray: Renderer::hairShadows().view
HP_CONST(uint, HAIR_SHADOW_TEST_BINDING_LIGHTS, 1)   // HairpipeLightSpace[]: .lightSpaces
HP_CONST(uint, HAIR_SHADOW_TEST_BINDING_POINTS, 2)   // vec4[]: world points (w unused)
HP_CONST(uint, HAIR_SHADOW_TEST_BINDING_RESULTS, 3)  // vec4[]: rgb = hairpipeHairShadow, a = the sharp alpha

struct ScanPush {
  uint count;
};

struct HairShadowTestPush {
  vec4 params;   // hairpipeHairShadow's: k, bias, deep
  vec4 forward;  // Instance::hairShadowForward()
  uint slot;
  uint count;
  uint pad0;
  uint pad1;
};

struct FlatDrawPush {
  vec4 color;
  vec2 viewportSize;
  vec2 pad;
};
HP_END

#ifdef __cplusplus
static_assert(sizeof(hp::gpu::ScanPush) == 4);
static_assert(sizeof(hp::gpu::FlatDrawPush) == 32);
static_assert(sizeof(hp::gpu::HairShadowTestPush) == 48);
#endif
#endif
