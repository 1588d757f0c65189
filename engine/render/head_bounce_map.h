#pragma once
// Contract: the head bounce map of one light, shared by every instance of a Renderer like the heads' depth
// shadow map (ShadowMaps owns both; shaders/head_bounce.frag writes it, head_bounce.glsl gathers from it):
// the skin nearest the light, RENDER_BOUNCE_RESOLUTION^2 texels framed like that depth map, as flux
// (RGBA32F: rgb, a = 1 + the hair's opacity there; a = 0: no skin) and position (RGBA32F: xyz world, w =
// the encoded normal), with a depth buffer for the draw. begin() opens the rendering into them (cleared)
// and end() closes it, with the barriers from and back to FragmentSampled, the state construction leaves
// them in (cleared: no skin), so a frame without the bounce samples valid data. One blocking submission.
#include <glm/glm.hpp>

#include "engine/render/head_shadow_view.h"
#include "engine/vk/image.h"

namespace hp::render {
// RenderFrame::headBounce of a frame whose heads' depth map is framed by `view`: on only where the look
// asks for the bounce and there is a head map (the bounce map is framed by it and drawn with it).
glm::vec4 headBounceParams(const HeadShadowView& view, bool skinBounce);

class HeadBounceMap {
 public:
  static constexpr VkFormat kFormat = VK_FORMAT_R32G32B32A32_SFLOAT;
  static constexpr VkFormat kDepthFormat = VK_FORMAT_D32_SFLOAT;

  explicit HeadBounceMap(const vk::Context& ctx);
  HeadBounceMap(const HeadBounceMap&) = delete;
  HeadBounceMap& operator=(const HeadBounceMap&) = delete;

  void begin(VkCommandBuffer cmd) const;
  void end(VkCommandBuffer cmd) const;
  VkImage fluxImage() const { return flux_.handle(); }
  VkImage positionImage() const { return position_.handle(); }
  VkImageView fluxView() const { return flux_.view(); }
  VkImageView positionView() const { return position_.view(); }
  VkSampler sampler() const { return sampler_.handle(); }

 private:
  void transition(VkCommandBuffer cmd, bool toAttachments) const;
  const vk::Context* ctx_;
  vk::Image flux_, position_, depth_;
  vk::Sampler sampler_;  // nearest: the gather fetches texels (texelFetch)
};
}  // namespace hp::render
