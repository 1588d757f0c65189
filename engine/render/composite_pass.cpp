#include "engine/render/composite_pass.h"

#include "engine/vk/context.h"
#include "shaders/shared/raster.h"

namespace hp::render {
namespace {
const vk::Binding kBindings[] = {
    {gpu::COMPOSITE_BINDING_HAIR, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, VK_SHADER_STAGE_FRAGMENT_BIT}};
}

CompositePass::CompositePass(const vk::Context& ctx, const AttachmentFormats& formats)
    : sampler_(ctx, "composite sampler"), set_(ctx, kBindings, "composite") {
  vk::GraphicsPipelineDesc desc;
  desc.vertexShader = "composite.vert";
  desc.fragmentShader = "composite.frag";
  desc.colorFormats = {formats.color};
  desc.depthFormat = formats.depth;
  desc.samples = formats.samples;
  desc.blend = vk::BlendMode::Premultiplied;
  desc.sets = {set_.layout()};
  desc.name = "hair composite";
  pipeline_ = vk::GraphicsPipeline(ctx, desc);
}

void CompositePass::setInput(VkImageView hair) {
  set_.writeSampledImage(gpu::COMPOSITE_BINDING_HAIR, hair, sampler_.handle());
}

void CompositePass::draw(VkCommandBuffer cmd, VkExtent2D extent) const {
  pipeline_.bind(cmd, set_.set(), extent);
  pipeline_.draw(cmd, 3);
}
}  // namespace hp::render
