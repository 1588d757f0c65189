#pragma once
// Contract: draws the render strands as camera-facing ribbons (or lines) shaded with Marschner S, into
// the caller's dynamic rendering: depth test and write on; with MSAA a sub-pixel strand writes its
// coverage as a dithered sample mask (strands.frag), without MSAA it blends with alpha = coverage.
// Vertex pulling from the interpolate pass's chunk buffers (one descriptor set per chunk). Reads the
// frame block, the Marschner resources and the opacity maps + LightSpace (ShadowInputs: sampled in the
// fragment shader, read in the vertex shader); the caller keeps them current and orders the strand
// buffers' ComputeWrite before this pass's VertexRead. draw() goes inside vkCmdBeginRendering with
// attachments matching `formats`.
#include <vector>

#include "compute/strand_buffers.h"
#include "engine/render/attachment_formats.h"
#include "engine/render/marschner_textures.h"
#include "engine/render/shadow_inputs.h"
#include "engine/vk/descriptors.h"
#include "engine/vk/pipeline.h"

namespace hp::render {
class StrandPass {
 public:
  StrandPass(const vk::Context& ctx, const compute::StrandBuffers& strands, const MarschnerTextures& marschner,
             const vk::Buffer& frameBlock, const ShadowInputs& shadows, const AttachmentFormats& formats);
  // Rewrites every descriptor (after the strand buffers or the Marschner textures changed).
  void bind(const compute::StrandBuffers& strands, const MarschnerTextures& marschner, const vk::Buffer& frameBlock,
            const ShadowInputs& shadows);
  void draw(VkCommandBuffer cmd, VkExtent2D extent, bool lines) const;

 private:
  const vk::Context& ctx_;
  const compute::StrandBuffers* strands_ = nullptr;
  std::vector<vk::DescriptorSet> sets_;  // one per chunk
  vk::GraphicsPipeline ribbons_;
  vk::GraphicsPipeline lines_;
  VkSampleCountFlagBits samples_;  // the flag's value is the count
};
}  // namespace hp::render
