#include "compute/shadows/opacity_splat_pass.h"

#include <string>

#include "engine/core/error.h"
#include "engine/vk/barriers.h"
#include "engine/vk/context.h"
#include "shaders/shared/opacity.h"

namespace hp::compute {
namespace {
const vk::Binding kOpacitySplatBindings[] = {
    {gpu::OPACITY_SPLAT_BINDING_POSITIONS, vk::kStorage, vk::kCompute},
    {gpu::OPACITY_SPLAT_BINDING_LIGHT, vk::kStorage, vk::kCompute},
    {gpu::OPACITY_SPLAT_BINDING_BINS, vk::kStorage, vk::kCompute},
    {gpu::OPACITY_SPLAT_BINDING_FIRST, vk::kStorage, vk::kCompute},
};

std::string modeName(std::uint32_t mode) {
  switch (mode) {
    case gpu::OPACITY_SPLAT_MODE_PLAIN: return "global slices";
    case gpu::OPACITY_SPLAT_MODE_FIRST: return "first hair";
    case gpu::OPACITY_SPLAT_MODE_DEEP: return "deep slices";
    default: return "deep fine bins";
  }
}
}  // namespace

OpacitySplatPass::OpacitySplatPass(const vk::Context& ctx, const StrandBuffers& strands, const vk::Buffer& lightSpace,
                                   const vk::Buffer& bins, const vk::Buffer& first, std::uint32_t resolution,
                                   OpacityBins layout, vk::PipelineLibrary* library)
    : ctx_(&ctx), resolution_(resolution), verticesPerStrand_(strands.layout().verticesPerStrand) {
  for (const StrandChunk& c : strands.chunks()) {
    Chunk chunk{vk::DescriptorSet(ctx, kOpacitySplatBindings, "opacity splat [chunk " + std::to_string(chunks_.size()) + "]"),
                c.range};
    chunk.set.writeStorageBuffer(gpu::OPACITY_SPLAT_BINDING_POSITIONS, c.positions.handle());
    chunk.set.writeStorageBuffer(gpu::OPACITY_SPLAT_BINDING_LIGHT, lightSpace.handle());
    chunk.set.writeStorageBuffer(gpu::OPACITY_SPLAT_BINDING_BINS, bins.handle());
    chunk.set.writeStorageBuffer(gpu::OPACITY_SPLAT_BINDING_FIRST, first.handle());
    chunks_.push_back(std::move(chunk));
  }
  // GPUs read a texel's nearest depth before the atomic minimum (17% off the opacity pass on an H100);
  // lavapipe runs the branch on all 8 lanes anyway, and the read made its pass 10-40% slower.
  const std::uint32_t readBeforeMin = ctx.properties().deviceType != VK_PHYSICAL_DEVICE_TYPE_CPU ? 1u : 0u;
  // constant_id 1: the mode, one pipeline for each of the layout's (lavapipe would run every mode's code).
  for (const std::uint32_t mode : splatModes(layout))
    pipelines_.emplace_back(mode, vk::makeComputePipeline(ctx, library, "opacity_splat.comp",
                                                          gpu::OPACITY_SPLAT_WORKGROUP_SIZE, {chunks_.front().set.layout()},
                                                          sizeof(gpu::OpacitySplatPush),
                                                          "opacity splat (" + modeName(mode) + ")",
                                                          {readBeforeMin, mode}));
}

const vk::ComputePipeline& OpacitySplatPass::pipeline(std::uint32_t mode) const {
  for (const auto& [built, pipeline] : pipelines_)
    if (built == mode) return *pipeline;
  throw Error("opacity splat: mode " + std::to_string(mode) + " is not one of its bins' layout");
}

void OpacitySplatPass::record(VkCommandBuffer cmd, const SplatFootprint& f, std::uint32_t mode,
                              std::uint32_t strandLimit) const {
  gpu::OpacitySplatPush push{};
  push.footprint = glm::vec4(f.strandWidth, 1.0f / float(resolution_), f.footprint ? 1.0f : 0.0f);
  push.opacity = f.footprint ? 1.0f : f.opacity;
  push.verticesPerStrand = verticesPerStrand_;
  push.resolution = resolution_;
  push.slot = f.slot;
  const vk::ComputePipeline& pipeline = this->pipeline(mode);
  for (std::size_t i = 0; i < chunks_.size(); ++i) {
    const std::uint32_t strands = strandsWithin(chunks_[i].range, strandLimit);
    if (strands == 0) break;  // the chunks are in strand order: the prefix ends here
    if (i > 0) vk::memoryBarrier(*ctx_, cmd, vk::BufferUse::ComputeWrite, vk::BufferUse::ComputeWrite);
    push.segmentCount = strands * (verticesPerStrand_ - 1);
    pipeline.bind(cmd, chunks_[i].set.set());
    pipeline.push(cmd, push);
    pipeline.dispatch(cmd, push.segmentCount);
  }
}
}  // namespace hp::compute
