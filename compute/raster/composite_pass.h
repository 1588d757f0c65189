#pragma once
// Contract: composites the compute rasterizer's hair image (compute/raster/strand_raster_pass.h: premultiplied
// radiance, alpha = 1 - T) over the caller's colour attachment with one full-screen triangle, blending
// ONE / ONE_MINUS_SRC_ALPHA, no depth test. draw() goes inside vkCmdBeginRendering with attachments
// matching `formats`; the hair images must be in ImageUse::FragmentSampled and the hair image as large as
// the extent. Over a multisampled attachment it draws the raster's two layers (shaders/shared/raster.h):
// the far one into the samples outside each pixel's near mask, the near one into those inside it.
// With a VelocityOutput (attachment >= 0) a further full-screen triangle writes the hair's motion (the motion
// image, also FragmentSampled) into that one of formats.otherColors where the hair's coverage exceeds its
// minCoverage (shaders/composite_velocity.glsl), leaving every other attachment and pixel as they are.
#include <optional>

#include "hairpipe/settings.h"
#include "engine/vk/descriptors.h"
#include "engine/vk/image.h"
#include "engine/vk/pipeline.h"
#include "shaders/shared/raster.h"

namespace hp::render {
class CompositePass {
 public:
  CompositePass(const vk::Context& ctx, const hairpipe::AttachmentFormats& formats,
                const hairpipe::VelocityOutput& velocity = {}, VkPipelineCache cache = VK_NULL_HANDLE);
  // near, nearMask: the raster's near layer and sample mask (read only over a multisampled attachment);
  // motion: the raster's motion image (read only with a velocity output).
  void setInput(VkImageView hair, VkImageView near, VkImageView nearMask, VkImageView motion = VK_NULL_HANDLE);
  void draw(VkCommandBuffer cmd, VkExtent2D extent) const;

 private:
  struct VelocityWrite {
    vk::DescriptorSet set;
    vk::GraphicsPipeline pipeline;
    gpu::CompositeVelocityPush push;
  };
  static std::optional<VelocityWrite> velocityWrite(const vk::Context& ctx, const hairpipe::AttachmentFormats& formats,
                                                    const hairpipe::VelocityOutput& velocity, VkPipelineCache cache);

  vk::Sampler sampler_;
  vk::DescriptorSet set_;
  vk::GraphicsPipeline pipeline_;
  bool multisampled_;
  std::optional<VelocityWrite> velocity_;
};
}  // namespace hp::render
