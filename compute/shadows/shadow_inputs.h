#pragma once
// Contract: what a shading pass binds to look the shadows up (frame_shadows.glsl), for every shadow slot:
// the opacity image (OPACITY_LAYERS layers per slot) with its sampler, the LightSpace buffer (one per slot)
// and the heads' depth map (a layer per slot) with its compare sampler, and the head bounce map's two images
// (head_bounce.glsl, slot 0). Handles owned by ShadowMaps (opacity image, LightSpace, head depth map,
// bounce map); valid while the Renderer lives.
#include "hairpipe_volk.h"

namespace hp::render {
struct ShadowInputs {
  VkImageView opacityView = VK_NULL_HANDLE;  // 2D array, OPACITY_LAYERS per slot, FragmentSampled
  VkSampler sampler = VK_NULL_HANDLE;
  VkBuffer lightSpace = VK_NULL_HANDLE;      // gpu::LightSpace[slots], GraphicsRead
  VkImageView headShadowView = VK_NULL_HANDLE;  // D32 depth, 2D array of a layer per slot, FragmentSampled
  VkSampler headShadowSampler = VK_NULL_HANDLE;  // depth-compare
  VkImageView bounceFluxView = VK_NULL_HANDLE;      // the head bounce map (head_bounce_map.h), FragmentSampled
  VkImageView bouncePositionView = VK_NULL_HANDLE;
  VkSampler bounceSampler = VK_NULL_HANDLE;         // nearest
};
}  // namespace hp::render
