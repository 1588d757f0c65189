#include "compute/head/strand_bounce_pass.h"

#include <string>

#include "engine/vk/barriers.h"

namespace hp::render {
namespace {
const vk::Binding kStrandBounceBindings[] = {
    {gpu::RENDER_BINDING_FRAME, vk::kStorage, vk::kCompute},
    {gpu::RENDER_BINDING_OPACITY, vk::kSampled, vk::kCompute},
    {gpu::RENDER_BINDING_HEAD_SHADOW, vk::kSampled, vk::kCompute},
    {gpu::RENDER_BINDING_BOUNCE_FLUX, vk::kSampled, vk::kCompute},
    {gpu::RENDER_BINDING_BOUNCE_POSITION, vk::kSampled, vk::kCompute},
    {gpu::RENDER_BINDING_LIGHT, vk::kStorage, vk::kCompute},
    {gpu::RENDER_BINDING_POSITIONS, vk::kStorage, vk::kCompute},
    {gpu::RENDER_BINDING_BOUNCE_SAMPLES, vk::kStorage, vk::kCompute},
    {gpu::RENDER_BINDING_BOUNCE_GUIDE_SAMPLES, vk::kStorage, vk::kCompute},
    {gpu::RENDER_BINDING_STRAND_BINDINGS, vk::kStorage, vk::kCompute},
    {gpu::RENDER_BINDING_SCALP_TRIANGLES, vk::kStorage, vk::kCompute},
};

std::shared_ptr<const vk::ComputePipeline> makeStep(const vk::Context& ctx, vk::PipelineLibrary* library,
                                                    VkDescriptorSetLayout layout, std::uint32_t step) {
  return vk::makeComputePipeline(ctx, library, "strand_bounce.comp", gpu::RENDER_BOUNCE_WORKGROUP_SIZE, {layout},
                                 sizeof(gpu::StrandBouncePush),
                                 step == gpu::BOUNCE_STEP_BLEND ? "strand bounce blend" : "strand bounce gather", {step});
}
}  // namespace

vk::DescriptorSet StrandBouncePass::makeSet(const vk::Context& ctx, VkBuffer frameBlock, const ShadowInputs& shadows,
                                            VkBuffer positions, VkBuffer samples, VkBuffer guideSamples,
                                            VkBuffer bindings, const std::string& name) const {
  vk::DescriptorSet s(ctx, kStrandBounceBindings, name);
  s.writeStorageBuffer(gpu::RENDER_BINDING_FRAME, frameBlock);
  s.writeSampledImage(gpu::RENDER_BINDING_OPACITY, shadows.opacityView, shadows.sampler);
  s.writeSampledImage(gpu::RENDER_BINDING_HEAD_SHADOW, shadows.headShadowView, shadows.headShadowSampler);
  s.writeSampledImage(gpu::RENDER_BINDING_BOUNCE_FLUX, shadows.bounceFluxView, shadows.bounceSampler);
  s.writeSampledImage(gpu::RENDER_BINDING_BOUNCE_POSITION, shadows.bouncePositionView, shadows.bounceSampler);
  s.writeStorageBuffer(gpu::RENDER_BINDING_LIGHT, shadows.lightSpace);
  s.writeStorageBuffer(gpu::RENDER_BINDING_POSITIONS, positions);
  s.writeStorageBuffer(gpu::RENDER_BINDING_BOUNCE_SAMPLES, samples);
  s.writeStorageBuffer(gpu::RENDER_BINDING_BOUNCE_GUIDE_SAMPLES, guideSamples);
  s.writeStorageBuffer(gpu::RENDER_BINDING_STRAND_BINDINGS, bindings);
  s.writeStorageBuffer(gpu::RENDER_BINDING_SCALP_TRIANGLES, strands_->triangles().handle());
  return s;
}

StrandBouncePass::StrandBouncePass(const vk::Context& ctx, const compute::StrandBuffers& strands, VkBuffer frameBlock,
                                   const ShadowInputs& shadows, vk::PipelineLibrary* library)
    : ctx_(&ctx), strands_(&strands) {
  const compute::StrandLayout& layout = strands.layout();
  for (const compute::StrandChunk& c : strands.chunks())
    chunks_.push_back({makeSet(ctx, frameBlock, shadows, c.positions.handle(), c.bounce.handle(),
                               strands.guideBounce().handle(), c.bindings.handle(),
                               "strand bounce [chunk " + std::to_string(chunks_.size()) + "]"),
                       c.range.strandCount});
  // The gather never reads the guides' samples: its set gets the triangles there, so none of its bindings
  // aliases the buffer it writes.
  if (layout.bounceAtGuides)
    guides_ = Chunk{makeSet(ctx, frameBlock, shadows, strands.guidePositions().handle(), strands.guideBounce().handle(),
                            strands.triangles().handle(), strands.chunks().front().bindings.handle(),
                            "strand bounce [guides]"),
                    layout.guideCount};
  gather_ = makeStep(ctx, library, chunks_.front().set.layout(), gpu::BOUNCE_STEP_GATHER);
  if (guides_) blend_ = makeStep(ctx, library, chunks_.front().set.layout(), gpu::BOUNCE_STEP_BLEND);
}

void StrandBouncePass::record(VkCommandBuffer cmd) const {
  const compute::StrandLayout& layout = strands_->layout();
  auto dispatch = [&](const vk::ComputePipeline& step, const Chunk& c) {
    const gpu::StrandBouncePush push{c.strandCount, layout.verticesPerStrand, layout.bounceSamples, 0u};
    step.bind(cmd, c.set.set());
    step.push(cmd, push);
    step.dispatch(cmd, c.strandCount * layout.bounceSamples);
  };
  if (guides_) {
    dispatch(*gather_, *guides_);
    vk::bufferBarrier(*ctx_, cmd, strands_->guideBounce().handle(), vk::BufferUse::ComputeWrite, vk::BufferUse::ComputeRead);
  }
  for (const Chunk& c : chunks_) dispatch(guides_ ? *blend_ : *gather_, c);
}
}  // namespace hp::render
