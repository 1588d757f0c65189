#pragma once
// Contract: full-screen pass from the resolved linear HDR image to the display image (exposure and a
// filmic curve; the sRGB target format applies the transfer function). Draws inside the caller's
// dynamic rendering of a single-sample `displayFormat` attachment; the HDR input must be in
// ImageUse::FragmentSampled.
#include "engine/vk/descriptors.h"
#include "engine/vk/image.h"
#include "engine/vk/pipeline.h"

namespace hp::render {
class TonemapPass {
 public:
  TonemapPass(const vk::Context& ctx, VkFormat displayFormat);
  void setInput(VkImageView hdr);
  void draw(VkCommandBuffer cmd, VkExtent2D extent, float exposure) const;

 private:
  vk::Sampler sampler_;
  vk::DescriptorSet set_;
  vk::GraphicsPipeline pipeline_;
};
}  // namespace hp::render
