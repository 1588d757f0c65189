#pragma once
// Contract: one hair instance's part of the opacity pass (docs/THEORY.md §5, shaders/opacity*.vert/.frag,
// shaders/shared/opacity.h): draws its render strands (lines, one draw per chunk) and its head mesh (an
// occluder with a large opacity) from the light into the shared ShadowMaps with additive blending, so
// slice i holds alpha(z_i) of every instance together. The light framing comes from the maps' LightSpace
// buffer on the device. Owns a copy of the head mesh and one descriptor set per chunk; the pipelines come
// from the PipelineLibrary (shared by every instance) when one is given.
//
// On the maps' compute path (ShadowMaps::raster()) the strands go through a compute::OpacitySplatPass
// into the maps' bins instead (recordSplats), and only the head, if it has an opacity, is drawn.
//
// recordDraws() / recordHeadDraw() go between ShadowMaps::beginRendering and endRendering
// (hp::recordShadowPasses). They insert no barriers; the frame recorder guarantees strand positions and
// LightSpace visible to BufferUse::VertexRead before them (ComputeRead before recordSplats).
#include "hairpipe_volk.h"

#include <glm/glm.hpp>

#include <memory>
#include <vector>

#include "compute/shadows/opacity_splat_pass.h"
#include "compute/strands/strand_buffers.h"
#include "engine/core/hair/hair_asset.h"
#include "compute/shadows/head_shadow_view.h"
#include "compute/shadows/shadow_maps.h"
#include "engine/vk/buffer.h"
#include "engine/vk/descriptors.h"
#include "engine/vk/pipeline_library.h"

namespace hp::render {
class OpacityPass {
 public:
  OpacityPass(const vk::Context& ctx, const compute::StrandBuffers& strands, const HeadMesh& head,
              const ShadowMaps& maps, vk::PipelineLibrary* library = nullptr);
  OpacityPass(const OpacityPass&) = delete;
  OpacityPass& operator=(const OpacityPass&) = delete;

  // strandWidth: x = width at the root (scene units), y = tip / root (the instance's LookSettings), for
  // the footprint opacity (OpacitySettings::footprint). strandLimit: the level of detail's prefix of the
  // strands drawn (compute::strandsWithin); the constant per-strand opacity (no footprint) grows by
  // strands / limit so the thinned hair casts the same shadow (the caller widens the strands for the
  // footprint).
  // slot: the light's shadow slot (its LightSpace; shared/opacity.h), for every record call here.
  void recordDraws(VkCommandBuffer cmd, std::uint32_t slot, const glm::mat4& headToWorld, const glm::vec2& strandWidth,
                   std::uint32_t strandLimit = compute::kAllStrands) const;
  // Compute path: the strands into the bins (ShadowMaps::resolvePass), then the head if drawsHead().
  void recordSplats(VkCommandBuffer cmd, std::uint32_t slot, const glm::vec2& strandWidth, std::uint32_t mode,
                    std::uint32_t strandLimit = compute::kAllStrands) const;
  bool drawsHead() const;  // the head goes into the slices (OpacitySettings::headOpacity > 0)
  void recordHeadDraw(VkCommandBuffer cmd, std::uint32_t slot, const glm::mat4& headToWorld) const;
  // The head's back faces into ShadowMaps' head depth map (between beginHeadRendering and endRendering).
  void recordHeadDepth(VkCommandBuffer cmd, const glm::mat4& headToLightClip) const;
  HeadSphere headSphere(const glm::mat4& headToWorld) const;  // bounding sphere in world space
  // Grows the head's bounding sphere (head space) to hold `extra` too: a posed character's reach.
  void encloseHead(const HeadSphere& extra) { sphere_ = enclose(sphere_, extra); }
  // The head's positions as the head draws here read them (vec4 per vertex; a posed character copies into it).
  const vk::Buffer& headPositions() const { return headPositions_; }

 private:
  void uploadHead(const HeadMesh& head);
  void bind(const compute::StrandBuffers& strands);

  const vk::Context& ctx_;
  const ShadowMaps& maps_;
  const compute::StrandBuffers* strands_ = nullptr;
  vk::Buffer headPositions_, headIndices_;
  std::uint32_t headIndexCount_ = 0;
  vk::DescriptorSet headSet_;
  std::vector<vk::DescriptorSet> strandSets_;  // one per chunk
  std::shared_ptr<const vk::GraphicsPipeline> strandPipeline_;
  std::shared_ptr<const vk::GraphicsPipeline> headPipeline_;
  std::shared_ptr<const vk::GraphicsPipeline> headDepthPipeline_;
  std::unique_ptr<compute::OpacitySplatPass> splat_;  // the maps' compute path only
  HeadSphere sphere_;  // head space
};
}  // namespace hp::render
