#include "compute/strands/tessellate_pass.h"

#include <string>

#include "engine/core/error.h"

namespace hp::compute {
namespace {
const vk::Binding kTessellateBindings[] = {
    {gpu::TESSELLATE_BINDING_PARTICLES, vk::kStorage, vk::kCompute},
    {gpu::TESSELLATE_BINDING_POSITIONS, vk::kStorage, vk::kCompute},
    {gpu::TESSELLATE_BINDING_TANGENTS, vk::kStorage, vk::kCompute},
};
}  // namespace

TessellatePass::TessellatePass(const vk::Context& ctx, const vk::Buffer& particles, const StrandBuffers& buffers,
                               vk::PipelineLibrary* library)
    : set_(ctx, kTessellateBindings, "tessellate"),
      pipeline_(vk::makeComputePipeline(ctx, library, "tessellate.comp", gpu::TESSELLATE_WORKGROUP_SIZE, {set_.layout()},
                sizeof(gpu::TessellatePush), "tessellate")) {
  bind(particles, buffers);
}

void TessellatePass::bind(const vk::Buffer& particles, const StrandBuffers& buffers) {
  const StrandLayout& l = buffers.layout();
  const VkDeviceSize needed = VkDeviceSize(l.guideCount) * l.particlesPerGuide * 16;
  if (particles.size() < needed)
    throw Error("tessellate: guide particle buffer '" + particles.name() + "' holds " +
                std::to_string(particles.size()) + " bytes, needs " + std::to_string(needed) + " (G x P vec4)");
  set_.writeStorageBuffer(gpu::TESSELLATE_BINDING_PARTICLES, particles.handle());
  set_.writeStorageBuffer(gpu::TESSELLATE_BINDING_POSITIONS, buffers.guidePositions().handle());
  set_.writeStorageBuffer(gpu::TESSELLATE_BINDING_TANGENTS, buffers.guideTangents().handle());
  push_ = {l.guideCount, l.particlesPerGuide, l.verticesPerStrand, 0};
}

void TessellatePass::record(VkCommandBuffer cmd, vk::GpuProfiler* profiler) const {
  if (profiler) profiler->begin(cmd, "tessellate");
  pipeline_->bind(cmd, set_.set());
  pipeline_->push(cmd, push_);
  pipeline_->dispatch(cmd, push_.guideCount * push_.vertices);
  if (profiler) profiler->end(cmd);
}
}  // namespace hp::compute
