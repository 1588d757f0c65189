#pragma once
// Contract: composites the compute rasterizer's hair image (compute/strand_raster_pass.h: premultiplied
// radiance, alpha = 1 - T) over the caller's colour attachment with one full-screen triangle, blending
// ONE / ONE_MINUS_SRC_ALPHA, no depth test. draw() goes inside vkCmdBeginRendering with attachments
// matching `formats`; the hair image must be in ImageUse::FragmentSampled and as large as the extent.
#include "engine/render/attachment_formats.h"
#include "engine/vk/descriptors.h"
#include "engine/vk/image.h"
#include "engine/vk/pipeline.h"

namespace hp::render {
class CompositePass {
 public:
  CompositePass(const vk::Context& ctx, const AttachmentFormats& formats);
  void setInput(VkImageView hair);
  void draw(VkCommandBuffer cmd, VkExtent2D extent) const;

 private:
  vk::Sampler sampler_;
  vk::DescriptorSet set_;
  vk::GraphicsPipeline pipeline_;
};
}  // namespace hp::render
