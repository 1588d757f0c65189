#include "compute/raster/composite_pass.h"

#include "engine/vk/application_attachments.h"
#include "engine/vk/context.h"
#include "shaders/shared/raster.h"

namespace hp::render {
namespace {
const vk::Binding kCompositeBindings[] = {{gpu::COMPOSITE_BINDING_HAIR, vk::kSampled, VK_SHADER_STAGE_FRAGMENT_BIT},
                                 {gpu::COMPOSITE_BINDING_NEAR, vk::kSampled, VK_SHADER_STAGE_FRAGMENT_BIT},
                                 {gpu::COMPOSITE_BINDING_NEAR_MASK, vk::kSampled, VK_SHADER_STAGE_FRAGMENT_BIT}};
}

CompositePass::CompositePass(const vk::Context& ctx, const hairpipe::AttachmentFormats& formats,
                             VkPipelineCache cache)
    : sampler_(ctx, "composite sampler", VK_FILTER_NEAREST),
      set_(ctx, kCompositeBindings, "composite"),
      multisampled_(formats.samples != VK_SAMPLE_COUNT_1_BIT) {
  vk::GraphicsPipelineDesc desc;
  desc.vertexShader = "composite.vert";
  desc.fragmentShader = "composite.frag";
  vk::setApplicationAttachments(desc, formats);
  desc.blend = vk::BlendMode::Premultiplied;
  desc.sets = {set_.layout()};
  desc.pushSize = sizeof(std::uint32_t);  // which samples (COMPOSITE_*)
  desc.name = "hair composite";
  pipeline_ = vk::GraphicsPipeline(ctx, desc, cache);
}

void CompositePass::setInput(VkImageView hair, VkImageView near, VkImageView nearMask) {
  set_.writeSampledImage(gpu::COMPOSITE_BINDING_HAIR, hair, sampler_.handle());
  set_.writeSampledImage(gpu::COMPOSITE_BINDING_NEAR, near, sampler_.handle());
  set_.writeSampledImage(gpu::COMPOSITE_BINDING_NEAR_MASK, nearMask, sampler_.handle());
}

void CompositePass::draw(VkCommandBuffer cmd, VkExtent2D extent) const {
  pipeline_.bind(cmd, set_.set(), extent);
  if (!multisampled_) {
    pipeline_.push(cmd, gpu::COMPOSITE_EVERY_SAMPLE);
    pipeline_.draw(cmd, 3);
    return;
  }
  for (std::uint32_t samples : {gpu::COMPOSITE_FAR_SAMPLES, gpu::COMPOSITE_NEAR_SAMPLES}) {
    pipeline_.push(cmd, samples);
    pipeline_.draw(cmd, 3);
  }
}
}  // namespace hp::render
