#pragma once
// Contract: draws the opaque head mesh (HairAsset::head) with the paper's wrap lighting and its indirect light
// (the mesh's skin transfer, a SkinTransferBuffer the caller computes once per mesh), the hair colour where
// HeadMesh::scalp marks hair roots (so the scalp does not show bare between strands), depth test and write
// on, into the caller's dynamic rendering. Owns the mesh buffers (uploaded once), pipeline and descriptor set; reads the frame block the caller keeps up to date (RenderFrame, shaders/shared/render.h;
// a dynamic read-only storage buffer, draw() names the slot's offset) and the shadows (ShadowInputs): hair shadows
// from the opacity maps, the head's own from its depth map.
// draw() must be called inside vkCmdBeginRendering with attachments matching `formats`.
#include <glm/glm.hpp>

#include "engine/core/hair/hair_asset.h"
#include "hairpipe/settings.h"
#include "compute/head/skin_transfer_buffer.h"
#include "compute/shadows/shadow_inputs.h"
#include "engine/vk/buffer.h"
#include "engine/vk/descriptors.h"
#include "engine/vk/pipeline_library.h"

#include <memory>

namespace hp::render {
class HeadPass {
 public:
  // transfer: the mesh's (SkinTransferBuffer), required unless the mesh is empty.
  HeadPass(const vk::Context& ctx, const HeadMesh& mesh, std::shared_ptr<const SkinTransferBuffer> transfer,
           const vk::Buffer& frameBlock, const ShadowInputs& shadows, const hairpipe::AttachmentFormats& formats,
           vk::PipelineLibrary* library = nullptr);
  // oneLight: the frame block holds at most one light (the head.frag variant without the light loop).
  void draw(VkCommandBuffer cmd, VkExtent2D extent, const glm::mat4& headToWorld, std::uint32_t frameOffset,
            bool oneLight = false) const;
  bool empty() const { return indexCount_ == 0; }
  // The mesh as uploaded (positions; normals with the scalp weight in w; indices), for other head draws.
  const vk::Buffer& positions() const { return positions_; }
  const vk::Buffer& normals() const { return normals_; }
  const vk::Buffer& indices() const { return indices_; }
  std::uint32_t indexCount() const { return indexCount_; }

 private:
  std::uint32_t indexCount_ = 0;
  vk::Buffer positions_, normals_, indices_;
  std::shared_ptr<const SkinTransferBuffer> transfer_;  // the mesh's skin transfer, shared with other instances
  vk::DescriptorSet set_;
  std::shared_ptr<const vk::GraphicsPipeline> pipeline_, oneLightPipeline_;
};
}  // namespace hp::render
