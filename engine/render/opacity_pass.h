#pragma once
// Contract: the opacity pass (REFERENCES.md §4, shaders/opacity*.vert/.frag, shaders/shared/opacity.h).
// Draws every render strand (lines, one draw per chunk) and the head mesh (an occluder with a large
// opacity) from the light into one 2D-array image of 4 RGBA layers = 16 slices, with additive
// blending, so slice i holds alpha(z_i) directly. The light framing comes from the bounds pass's
// LightSpace buffer on the device. Owns the image, its sampler, a copy of the head mesh, the
// pipelines and one descriptor set per chunk.
//
// record() begins and ends its own dynamic rendering, so it goes outside the application's rendering
// (HairSystem::recordPrepareDraw). It inserts no barriers; the frame recorder guarantees:
//   before record: image() in ImageUse::ColorAttachment (from FragmentSampled: the previous frame's
//                  lookups), strand positions and LightSpace visible to BufferUse::VertexRead;
//   after record:  image() is in ColorAttachment; transition it to FragmentSampled for the lookups.
// Construction clears the image to 0 (alpha = 0 everywhere, T = 1) and leaves it in FragmentSampled,
// so a frame with shadows off samples valid data without this pass.
#include <volk.h>

#include <glm/glm.hpp>

#include <vector>

#include "compute/strand_buffers.h"
#include "engine/hair/hair_asset.h"
#include "engine/render/opacity_settings.h"
#include "engine/render/shadow_inputs.h"
#include "engine/vk/buffer.h"
#include "engine/vk/descriptors.h"
#include "engine/vk/image.h"
#include "engine/vk/pipeline.h"

namespace hp::render {
class OpacityPass {
 public:
  OpacityPass(const vk::Context& ctx, const compute::StrandBuffers& strands, const HeadMesh& head,
              const vk::Buffer& lightSpace, const OpacitySettings& settings);
  OpacityPass(const OpacityPass&) = delete;
  OpacityPass& operator=(const OpacityPass&) = delete;

  void bind(const compute::StrandBuffers& strands);  // outside the frame loop, after StrandBuffers changed
  void record(VkCommandBuffer cmd, const glm::mat4& headToWorld) const;

  const vk::Image& image() const { return image_; }
  ShadowInputs shadowInputs() const { return {image_.view(), sampler_.handle(), lightSpace_->handle()}; }
  const OpacitySettings& settings() const { return settings_; }

 private:
  void uploadHead(const HeadMesh& head);
  void clearImage();

  const vk::Context& ctx_;
  OpacitySettings settings_;
  const vk::Buffer* lightSpace_;
  const compute::StrandBuffers* strands_ = nullptr;
  vk::Image image_;
  vk::Sampler sampler_;
  vk::Buffer headPositions_, headIndices_;
  std::uint32_t headIndexCount_ = 0;
  vk::DescriptorSet headSet_;
  std::vector<vk::DescriptorSet> strandSets_;  // one per chunk
  vk::GraphicsPipeline strandPipeline_;
  vk::GraphicsPipeline headPipeline_;
};
}  // namespace hp::render
