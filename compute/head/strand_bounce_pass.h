#pragma once
// Contract: the skin's bounce at a few points along every strand of one instance (shaders/strand_bounce.comp:
// head_bounce.glsl's gather at StrandLayout::bounceSamples points per strand, written to each chunk's
// StrandChunk::bounce), once per frame after the head bounce map is drawn; the shading of every view reads
// them (shaders/bounce_samples.glsl). Reads the instance's bounce frame block (a storage buffer holding a
// RenderFrame: the slot-0 light, opacity settings, the map's framing, headBounce), the shadows' opacity maps,
// LightSpace and head bounce map, and the strand positions. Owns one descriptor set per chunk; inserts no
// barriers: the frame recorder (recordStrandBounce) expects the positions and frame block readable in
// compute, the maps in ImageUse::ComputeSampled, and leaves the samples in BufferUse::ComputeWrite.
#include <vector>

#include "compute/shadows/shadow_inputs.h"
#include "compute/strands/strand_buffers.h"
#include "engine/vk/descriptors.h"
#include "engine/vk/pipeline.h"
#include "engine/vk/pipeline_library.h"
#include "shaders/shared/render.h"

namespace hp::render {
class StrandBouncePass {
 public:
  StrandBouncePass(const vk::Context& ctx, const compute::StrandBuffers& strands, VkBuffer frameBlock,
                   const ShadowInputs& shadows, vk::PipelineLibrary* library = nullptr);
  // Every strand: a view may draw more of them than the last frame's level of detail did.
  void record(VkCommandBuffer cmd) const;

 private:
  struct Chunk {
    vk::DescriptorSet set;
    std::uint32_t strandCount;
  };
  const compute::StrandBuffers* strands_;
  std::vector<Chunk> chunks_;
  std::shared_ptr<const vk::ComputePipeline> pipeline_;
};
}  // namespace hp::render
