#pragma once
// Contract: the opacity shadow maps of one light, shared by every hair instance a Renderer draws, so
// heads shadow each other (REFERENCES.md §4; engine/render/README.md "Opacity shadow maps"). Owns the
// LightSpace buffer the bounds pass of every instance reduces into (one framing over all of them), the
// 2D-array image of 4 RGBA layers = 16 slices every instance's OpacityPass draws into, and its sampler.
// beginRendering()/endRendering() open and close the additive rendering into the 4 layers (cleared to 0);
// the instances' OpacityPass::recordDraws go between them. Inserts no barriers: the frame recorder
// (hp::recordShadowPasses) owns them.
// Construction clears the image (alpha = 0, T = 1) and leaves it in ImageUse::FragmentSampled, and
// uploads an armed LightSpace (compute::initialLightSpace) left in BufferUse::VertexRead, so a frame with
// shadows off samples valid data. One blocking submission. Throws hp::Error on invalid settings.
#include "engine/render/opacity_settings.h"
#include "engine/render/shadow_inputs.h"
#include "engine/vk/buffer.h"
#include "engine/vk/image.h"

namespace hp::render {
class ShadowMaps {
 public:
  ShadowMaps(const vk::Context& ctx, const OpacitySettings& settings);
  ShadowMaps(const ShadowMaps&) = delete;
  ShadowMaps& operator=(const ShadowMaps&) = delete;

  // New opacities, k, bias or on/off with the same resolution and format (read at record time).
  void setTuning(const OpacitySettings& settings) { settings_ = settings; }

  void beginRendering(VkCommandBuffer cmd) const;
  void endRendering(VkCommandBuffer cmd) const;

  const vk::Image& image() const { return image_; }
  const vk::Buffer& lightSpace() const { return lightSpace_; }
  ShadowInputs inputs() const { return {image_.view(), sampler_.handle(), lightSpace_.handle()}; }
  const OpacitySettings& settings() const { return settings_; }

 private:
  const vk::Context* ctx_;
  OpacitySettings settings_;
  vk::Buffer lightSpace_;
  vk::Image image_;
  vk::Sampler sampler_;
};
}  // namespace hp::render
