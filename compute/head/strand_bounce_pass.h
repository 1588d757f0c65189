#pragma once
// Contract: the skin's bounce at a few points along every strand of one instance (shaders/strand_bounce.comp),
// once per frame after the head bounce map is drawn; the shading of every view reads them
// (shaders/bounce_samples.glsl). With StrandLayout::bounceAtGuides head_bounce.glsl's gather runs at
// StrandLayout::bounceSamples points along each smoothed guide (StrandBuffers::guideBounce), and each render
// strand's samples (StrandChunk::bounce) are its three guides' blended with its barycentrics; otherwise the
// gather runs along every render strand and writes the chunks' samples directly. Reads the instance's bounce frame block (a storage buffer holding a RenderFrame: the
// slot-0 light, opacity settings, the map's framing, headBounce), the shadows' opacity maps, LightSpace and
// head bounce map, the smoothed guide positions and the interpolation topology. Owns its descriptor sets;
// the only barrier it inserts is between its two steps (the guides' samples, written then read). The frame
// recorder (recordStrandBounce) expects the positions and frame block readable in compute, the maps in
// ImageUse::ComputeSampled, and leaves the samples in BufferUse::ComputeWrite.
#include <optional>
#include <string>
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
  // A set with every binding of the shader written: `positions` gathered, or `guideSamples` blended, into
  // `samples`.
  vk::DescriptorSet makeSet(const vk::Context& ctx, VkBuffer frameBlock, const ShadowInputs& shadows,
                            VkBuffer positions, VkBuffer samples, VkBuffer guideSamples, VkBuffer bindings,
                            const std::string& name) const;
  const vk::Context* ctx_;
  const compute::StrandBuffers* strands_;
  std::vector<Chunk> chunks_;          // blended (or, guides only, gathered) render strand samples
  std::optional<Chunk> guides_;        // the gather along the smoothed guides (StrandLayout::bounceAtGuides)
  std::shared_ptr<const vk::ComputePipeline> gather_;
  std::shared_ptr<const vk::ComputePipeline> blend_;
};
}  // namespace hp::render
