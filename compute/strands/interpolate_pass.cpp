#include "compute/strands/interpolate_pass.h"

#include <string>

namespace hp::compute {
namespace {
constexpr VkShaderStageFlags kCompute = VK_SHADER_STAGE_COMPUTE_BIT;
constexpr VkDescriptorType kStorage = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
const vk::Binding kBindings[] = {
    {gpu::INTERPOLATE_BINDING_GUIDE_POSITIONS, kStorage, kCompute},
    {gpu::INTERPOLATE_BINDING_GUIDE_TANGENTS, kStorage, kCompute},
    {gpu::INTERPOLATE_BINDING_TRIANGLES, kStorage, kCompute},
    {gpu::INTERPOLATE_BINDING_BINDINGS, kStorage, kCompute},
    {gpu::INTERPOLATE_BINDING_POSITIONS, kStorage, kCompute},
    {gpu::INTERPOLATE_BINDING_TANGENTS, kStorage, kCompute},
    {gpu::INTERPOLATE_BINDING_ATTRIBUTES, kStorage, kCompute},
};
}  // namespace

InterpolatePass::InterpolatePass(const vk::Context& ctx, const StrandBuffers& buffers, vk::PipelineLibrary* library,
                                 const GroomSettings& groom)
    : ctx_(&ctx),
      layoutSet_(ctx, kBindings, "interpolate layout"),
      pipeline_(vk::makeComputePipeline(ctx, library, "interpolate.comp", gpu::INTERPOLATE_WORKGROUP_SIZE, {layoutSet_.layout()},
                sizeof(gpu::InterpolatePush), "interpolate")) {
  setGroom(groom);
  bind(buffers);
}

void InterpolatePass::setGroom(const GroomSettings& groom) {
  groom.validate();
  groom_ = groomParams(groom);
  for (Chunk& c : chunks_) c.push.groom = groom_;
}

void InterpolatePass::bind(const StrandBuffers& buffers) {
  const StrandLayout& l = buffers.layout();
  const std::uint32_t mode = l.guidesOnly ? gpu::INTERPOLATE_MODE_GUIDES : gpu::INTERPOLATE_MODE_STRANDS;
  std::vector<Chunk> chunks;
  for (const StrandChunk& c : buffers.chunks()) {
    Chunk chunk{vk::DescriptorSet(*ctx_, kBindings, "interpolate [chunk " + std::to_string(chunks.size()) + "]"),
                {c.range.firstStrand, c.range.strandCount, l.verticesPerStrand, mode, groom_}};
    const vk::DescriptorSet& s = chunk.set;
    s.writeStorageBuffer(gpu::INTERPOLATE_BINDING_GUIDE_POSITIONS, buffers.guidePositions().handle());
    s.writeStorageBuffer(gpu::INTERPOLATE_BINDING_GUIDE_TANGENTS, buffers.guideTangents().handle());
    s.writeStorageBuffer(gpu::INTERPOLATE_BINDING_TRIANGLES, buffers.triangles().handle());
    s.writeStorageBuffer(gpu::INTERPOLATE_BINDING_BINDINGS, c.bindings.handle());
    s.writeStorageBuffer(gpu::INTERPOLATE_BINDING_POSITIONS, c.positions.handle());
    s.writeStorageBuffer(gpu::INTERPOLATE_BINDING_TANGENTS, c.tangents.handle());
    s.writeStorageBuffer(gpu::INTERPOLATE_BINDING_ATTRIBUTES, c.attributes.handle());
    chunks.push_back(std::move(chunk));
  }
  chunks_ = std::move(chunks);
}

void InterpolatePass::record(VkCommandBuffer cmd, vk::GpuProfiler* profiler) const {
  if (profiler) profiler->begin(cmd, "interpolate");
  for (const Chunk& c : chunks_) {
    pipeline_->bind(cmd, c.set.set());
    pipeline_->push(cmd, c.push);
    pipeline_->dispatch(cmd, c.push.strandCount);
  }
  if (profiler) profiler->end(cmd);
}
}  // namespace hp::compute
