#include "compute/head/head_bounce_pass.h"

#include "compute/shadows/head_bounce_map.h"
#include "engine/vk/pipeline_library.h"
#include "shaders/shared/render.h"

namespace hp::render {
namespace {
const vk::Binding kHeadBounceBindings[] = {
    {gpu::RENDER_BINDING_FRAME, vk::kStorage, vk::kVertex | vk::kFragment},
    {gpu::RENDER_BINDING_POSITIONS, vk::kStorage, vk::kVertex},
    {gpu::RENDER_BINDING_TANGENTS, vk::kStorage, vk::kVertex},
    {gpu::RENDER_BINDING_ATTRIBUTES, vk::kStorage, vk::kVertex},
    {gpu::RENDER_BINDING_OPACITY, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, vk::kFragment},
    {gpu::RENDER_BINDING_HEAD_SHADOW, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, vk::kFragment},
    {gpu::RENDER_BINDING_LIGHT, vk::kStorage, vk::kFragment},
};
}  // namespace

HeadBouncePass::HeadBouncePass(const vk::Context& ctx, const HeadPass& head, VkBuffer frameBlock,
                               const ShadowInputs& shadows, vk::PipelineLibrary* library)
    : head_(&head), set_(ctx, kHeadBounceBindings, "head bounce") {
  set_.writeStorageBuffer(gpu::RENDER_BINDING_FRAME, frameBlock);
  set_.writeSampledImage(gpu::RENDER_BINDING_OPACITY, shadows.opacityView, shadows.sampler);
  set_.writeSampledImage(gpu::RENDER_BINDING_HEAD_SHADOW, shadows.headShadowView, shadows.headShadowSampler);
  set_.writeStorageBuffer(gpu::RENDER_BINDING_LIGHT, shadows.lightSpace);
  if (!head.empty()) {
    set_.writeStorageBuffer(gpu::RENDER_BINDING_POSITIONS, head.positions().handle());
    set_.writeStorageBuffer(gpu::RENDER_BINDING_TANGENTS, head.normals().handle());
    set_.writeStorageBuffer(gpu::RENDER_BINDING_ATTRIBUTES, head.indices().handle());
  }
  vk::GraphicsPipelineDesc desc;
  desc.vertexShader = "head_bounce.vert";
  desc.fragmentShader = "head_bounce.frag";
  desc.colorFormats = {HeadBounceMap::kFormat, HeadBounceMap::kFormat};
  desc.depthFormat = HeadBounceMap::kDepthFormat;
  desc.depthTest = desc.depthWrite = true;
  desc.cullMode = VK_CULL_MODE_BACK_BIT;
  desc.sets = {set_.layout()};
  desc.pushSize = sizeof(glm::mat4);
  desc.name = "head bounce";
  pipeline_ = vk::makeGraphicsPipeline(ctx, library, desc);
}

void HeadBouncePass::draw(VkCommandBuffer cmd, const glm::mat4& headToWorld) const {
  if (head_->empty()) return;
  pipeline_->bind(cmd, set_.set(), {gpu::RENDER_BOUNCE_RESOLUTION, gpu::RENDER_BOUNCE_RESOLUTION});
  pipeline_->push(cmd, headToWorld);
  pipeline_->draw(cmd, head_->indexCount());
}
}  // namespace hp::render
