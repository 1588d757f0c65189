#pragma once
// Contract: composites the compute rasterizer's hair image (compute/raster/strand_raster_pass.h: premultiplied
// radiance, alpha = 1 - T) over the caller's colour attachment with one full-screen triangle, blending
// ONE / ONE_MINUS_SRC_ALPHA, no depth test. draw() goes inside vkCmdBeginRendering with attachments
// matching `formats`; the hair images must be in ImageUse::FragmentSampled and the hair image as large as
// the extent. Over a multisampled attachment it draws the raster's two layers (shaders/shared/raster.h):
// the far one into the samples outside each pixel's near mask, the near one into those inside it.
#include "hairpipe/settings.h"
#include "engine/vk/descriptors.h"
#include "engine/vk/image.h"
#include "engine/vk/pipeline.h"

namespace hp::render {
class CompositePass {
 public:
  CompositePass(const vk::Context& ctx, const hairpipe::AttachmentFormats& formats,
                VkPipelineCache cache = VK_NULL_HANDLE);
  // near, nearMask: the raster's near layer and sample mask (read only over a multisampled attachment).
  void setInput(VkImageView hair, VkImageView near, VkImageView nearMask);
  void draw(VkCommandBuffer cmd, VkExtent2D extent) const;

 private:
  vk::Sampler sampler_;
  vk::DescriptorSet set_;
  vk::GraphicsPipeline pipeline_;
  bool multisampled_;
};
}  // namespace hp::render
