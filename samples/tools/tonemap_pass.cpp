#include "samples/tools/tonemap_pass.h"

#include "engine/vk/context.h"
#include "engine/vk/image.h"
#include "shaders/shared/render.h"

namespace hp::render {
namespace {
const vk::Binding kBindings[] = {
    {gpu::TONEMAP_BINDING_HDR, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, VK_SHADER_STAGE_FRAGMENT_BIT}};
}

TonemapPass::TonemapPass(const vk::Context& ctx, VkFormat displayFormat)
    : sampler_(ctx, "tonemap sampler") {
  set_ = vk::DescriptorSet(ctx, kBindings, "tonemap");
  vk::GraphicsPipelineDesc desc;
  desc.vertexShader = "tonemap.vert";
  desc.fragmentShader = "tonemap.frag";
  desc.colorFormats = {displayFormat};
  desc.sets = {set_.layout()};
  desc.pushSize = sizeof(gpu::TonemapPush);
  desc.name = "tonemap";
  pipeline_ = vk::GraphicsPipeline(ctx, desc);
}

void TonemapPass::setInput(VkImageView hdr) { set_.writeSampledImage(gpu::TONEMAP_BINDING_HDR, hdr, sampler_.handle()); }

void TonemapPass::draw(VkCommandBuffer cmd, VkExtent2D extent, float exposure) const {
  pipeline_.bind(cmd, set_.set(), extent);
  pipeline_.push(cmd, gpu::TonemapPush{exposure, 0, 0, 0});
  pipeline_.draw(cmd, 3);
}
}  // namespace hp::render
