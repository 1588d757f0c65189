#pragma once
// Contract: what a shading pass binds to look the opacity shadow maps up (opacity_lookup.glsl): the
// 4-layer opacity image with its sampler (fragment shader) and the LightSpace buffer (vertex shader).
// Handles owned by OpacityPass and BoundsPass; valid while the HairSystem lives.
#include <volk.h>

namespace hp::render {
struct ShadowInputs {
  VkImageView opacityView = VK_NULL_HANDLE;  // 2D array, 4 layers, FragmentSampled
  VkSampler sampler = VK_NULL_HANDLE;
  VkBuffer lightSpace = VK_NULL_HANDLE;      // gpu::LightSpace, VertexRead
};
}  // namespace hp::render
