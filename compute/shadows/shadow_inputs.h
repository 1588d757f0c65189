#pragma once
// Contract: what a shading pass binds to look the shadows up: the 4-layer opacity image with its
// sampler (fragment shader, opacity_lookup.glsl), the LightSpace buffer (vertex shader) and the head's
// depth shadow map with its compare sampler (fragment shader, head_shadow.glsl), and the head bounce map's
// two images (head_bounce.glsl). Handles owned by ShadowMaps (opacity image, LightSpace, head depth map,
// bounce map); valid while the Renderer lives.
#include "hairpipe_volk.h"

namespace hp::render {
struct ShadowInputs {
  VkImageView opacityView = VK_NULL_HANDLE;  // 2D array, 4 layers, FragmentSampled
  VkSampler sampler = VK_NULL_HANDLE;
  VkBuffer lightSpace = VK_NULL_HANDLE;      // gpu::LightSpace, VertexRead
  VkImageView headShadowView = VK_NULL_HANDLE;  // D32 depth, FragmentSampled
  VkSampler headShadowSampler = VK_NULL_HANDLE;  // depth-compare
  VkImageView bounceFluxView = VK_NULL_HANDLE;      // the head bounce map (head_bounce_map.h), FragmentSampled
  VkImageView bouncePositionView = VK_NULL_HANDLE;
  VkSampler bounceSampler = VK_NULL_HANDLE;         // nearest
};
}  // namespace hp::render
