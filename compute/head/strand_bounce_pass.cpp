#include "compute/head/strand_bounce_pass.h"

#include <string>

namespace hp::render {
namespace {
constexpr VkShaderStageFlags kCompute = VK_SHADER_STAGE_COMPUTE_BIT;
constexpr VkDescriptorType kStorage = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
constexpr VkDescriptorType kSampled = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
const vk::Binding kBindings[] = {
    {gpu::RENDER_BINDING_FRAME, kStorage, kCompute},
    {gpu::RENDER_BINDING_OPACITY, kSampled, kCompute},
    {gpu::RENDER_BINDING_HEAD_SHADOW, kSampled, kCompute},
    {gpu::RENDER_BINDING_BOUNCE_FLUX, kSampled, kCompute},
    {gpu::RENDER_BINDING_BOUNCE_POSITION, kSampled, kCompute},
    {gpu::RENDER_BINDING_LIGHT, kStorage, kCompute},
    {gpu::RENDER_BINDING_POSITIONS, kStorage, kCompute},
    {gpu::RENDER_BINDING_BOUNCE_SAMPLES, kStorage, kCompute},
};
}  // namespace

StrandBouncePass::StrandBouncePass(const vk::Context& ctx, const compute::StrandBuffers& strands, VkBuffer frameBlock,
                                   const ShadowInputs& shadows, vk::PipelineLibrary* library)
    : strands_(&strands) {
  for (const compute::StrandChunk& c : strands.chunks()) {
    Chunk chunk{vk::DescriptorSet(ctx, kBindings, "strand bounce [chunk " + std::to_string(chunks_.size()) + "]"),
                c.range.strandCount};
    const vk::DescriptorSet& s = chunk.set;
    s.writeStorageBuffer(gpu::RENDER_BINDING_FRAME, frameBlock);
    s.writeSampledImage(gpu::RENDER_BINDING_OPACITY, shadows.opacityView, shadows.sampler);
    s.writeSampledImage(gpu::RENDER_BINDING_HEAD_SHADOW, shadows.headShadowView, shadows.headShadowSampler);
    s.writeSampledImage(gpu::RENDER_BINDING_BOUNCE_FLUX, shadows.bounceFluxView, shadows.bounceSampler);
    s.writeSampledImage(gpu::RENDER_BINDING_BOUNCE_POSITION, shadows.bouncePositionView, shadows.bounceSampler);
    s.writeStorageBuffer(gpu::RENDER_BINDING_LIGHT, shadows.lightSpace);
    s.writeStorageBuffer(gpu::RENDER_BINDING_POSITIONS, c.positions.handle());
    s.writeStorageBuffer(gpu::RENDER_BINDING_BOUNCE_SAMPLES, c.bounce.handle());
    chunks_.push_back(std::move(chunk));
  }
  pipeline_ = vk::makeComputePipeline(ctx, library, "strand_bounce.comp", gpu::RENDER_BOUNCE_WORKGROUP_SIZE,
                                      {chunks_.front().set.layout()}, sizeof(gpu::StrandBouncePush), "strand bounce");
}

void StrandBouncePass::record(VkCommandBuffer cmd) const {
  const compute::StrandLayout& layout = strands_->layout();
  for (const Chunk& c : chunks_) {
    const gpu::StrandBouncePush push{c.strandCount, layout.verticesPerStrand, layout.bounceSamples, 0u};
    pipeline_->bind(cmd, c.set.set());
    pipeline_->push(cmd, push);
    pipeline_->dispatch(cmd, c.strandCount * layout.bounceSamples);
  }
}
}  // namespace hp::render
