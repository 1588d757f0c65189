#pragma once
// Contract: the tessellation pass (docs/THEORY.md §1.3, shaders/tessellate.comp). Turns the simulated
// guides (P particles each) into smooth guides of Q vertices: cubic Beziers from central-difference
// tangents, every particle hit exactly (sample distribution in shaders/shared/strands.h), unit
// tangents. Owns its pipeline and descriptor set; record() adds one dispatch (G x Q invocations) to
// the caller's command buffer and inserts no barriers. The frame recorder guarantees:
//   before record: guide particles in BufferUse::ComputeRead (after the simulation's ComputeWrite);
//                  smoothed guides no longer read by the previous frame (their last use -> ComputeWrite).
//   after record:  smoothed guides (StrandBuffers::guidePositions/guideTangents) are in
//                  BufferUse::ComputeWrite; barrier them to ComputeRead before InterpolatePass.
#include "hairpipe_volk.h"

#include "compute/strands/strand_buffers.h"
#include "engine/vk/descriptors.h"
#include "engine/vk/pipeline_library.h"
#include "engine/vk/profiler.h"
#include "shaders/shared/strands.h"

namespace hp::compute {
class TessellatePass {
 public:
  // particles: vec4[G * P] (xyz position, w unused), at least layout().guideCount * P entries.
  // With a `library`, the pipeline is shared with every other pass built from it.
  TessellatePass(const vk::Context& ctx, const vk::Buffer& particles, const StrandBuffers& buffers,
                 vk::PipelineLibrary* library = nullptr);

  // After StrandBuffers or the particle buffer were re-allocated; outside the frame loop only.
  void bind(const vk::Buffer& particles, const StrandBuffers& buffers);
  void record(VkCommandBuffer cmd, vk::GpuProfiler* profiler = nullptr) const;

 private:
  vk::DescriptorSet set_;
  std::shared_ptr<const vk::ComputePipeline> pipeline_;
  gpu::TessellatePush push_{};
};
}  // namespace hp::compute
