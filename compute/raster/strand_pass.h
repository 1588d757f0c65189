#pragma once
// Contract: draws the render strands as camera-facing ribbons (or lines) shaded with Marschner S, into
// the caller's dynamic rendering: depth test and write on; with MSAA a sub-pixel strand writes its
// coverage as a dithered sample mask (strands.frag), without MSAA it blends with alpha = coverage.
// Vertex pulling from the interpolate pass's chunk buffers (one descriptor set per chunk). Reads the
// frame block (gpu::RenderFrame, a dynamic read-only storage buffer: draw() names the slot's offset), the Marschner
// resources and the shadows (ShadowInputs: opacity maps and head depth map sampled in the
// fragment shader, read in the vertex shader); the caller keeps them current and orders the strand
// buffers' ComputeWrite before this pass's VertexRead. draw() goes inside vkCmdBeginRendering with
// attachments matching `formats`. Descriptors are written once: anything they name changes by building a
// new StrandPass (cheap with a PipelineLibrary) and retiring the old one after its last frame.
#include <vector>

#include "compute/strands/strand_buffers.h"
#include "hairpipe/settings.h"
#include "compute/raster/marschner_textures.h"
#include "compute/shadows/shadow_inputs.h"
#include "engine/vk/descriptors.h"
#include "engine/vk/pipeline_library.h"

namespace hp::render {
class StrandPass {
 public:
  StrandPass(const vk::Context& ctx, const compute::StrandBuffers& strands, const MarschnerTextures& marschner,
             const vk::Buffer& frameBlock, const ShadowInputs& shadows, const hairpipe::AttachmentFormats& formats,
             vk::PipelineLibrary* library = nullptr);
  // frameOffset: byte offset of this draw's gpu::RenderFrame in frameBlock. strandLimit: the level of
  // detail's prefix of the strands drawn (compute::strandsWithin).
  void draw(VkCommandBuffer cmd, VkExtent2D extent, bool lines, std::uint32_t frameOffset,
            std::uint32_t strandLimit = compute::kAllStrands) const;

 private:
  const compute::StrandBuffers* strands_ = nullptr;
  std::vector<vk::DescriptorSet> sets_;  // one per chunk
  std::shared_ptr<const vk::GraphicsPipeline> ribbons_;
  std::shared_ptr<const vk::GraphicsPipeline> lines_;
  VkSampleCountFlagBits samples_;  // the flag's value is the count
};
}  // namespace hp::render
