#pragma once
// Contract: the head bounce map of one light, shared by every instance of a Renderer like the heads' depth
// shadow map (ShadowMaps owns both; shaders/head_bounce.frag writes it, head_bounce.glsl gathers from it):
// the skin nearest the light, RENDER_BOUNCE_RESOLUTION^2 texels framed like that depth map, as flux
// (RGBA32F: rgb, a = 1 + the hair's opacity there; a = 0: no skin) and position (RGBA32F: xyz world, w =
// the encoded normal), with a depth buffer for the draw. begin() opens the rendering into them (cleared)
// and end() closes it, with the barriers from and back to FragmentSampled, the state construction leaves
// them in (cleared: no skin), so a frame without the bounce samples valid data. One blocking submission.
#include <glm/glm.hpp>

#include "compute/shadows/head_shadow_view.h"
#include "engine/vk/barriers.h"
#include "engine/vk/image.h"
#include "shaders/shared/render.h"

namespace hp::render {
class HeadBounceMap {
 public:
  static constexpr VkFormat kFormat = VK_FORMAT_R32G32B32A32_SFLOAT;
  static constexpr VkFormat kDepthFormat = VK_FORMAT_D32_SFLOAT;

  explicit HeadBounceMap(const vk::Context& ctx);
  HeadBounceMap(const HeadBounceMap&) = delete;
  HeadBounceMap& operator=(const HeadBounceMap&) = delete;

  void begin(VkCommandBuffer cmd) const;
  void end(VkCommandBuffer cmd) const;
  // Both colour images from one use to another (e.g. a compute reader between frames' draws).
  void transition(VkCommandBuffer cmd, vk::ImageUse from, vk::ImageUse to) const;
  VkImageView fluxView() const { return flux_.view(); }
  VkImageView positionView() const { return position_.view(); }
  VkSampler sampler() const { return sampler_.handle(); }

 private:
  const vk::Context* ctx_;
  vk::Image flux_, position_, depth_;
  vk::Sampler sampler_;  // nearest: the gather fetches texels (texelFetch)
};
}  // namespace hp::render
