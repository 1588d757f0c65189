#pragma once
// Contract: the guide simulation on the device (docs/THEORY.md §2). Owns the guide particle buffers
// (positions, previous, rest; layout in shaders/shared/simulate.h), its frame uniform block, pipeline
// and descriptor set. record() writes this frame's constants into the command buffer and dispatches
// one invocation per guide; nothing is read back. positions() is what tessellation reads. The asset's
// distance grid (if any) is a separate read-only binding (SdfBuffer), uploaded once, and rebuilt on the device
// before the simulation on the frames a skinned character collider is given a pose (CharacterPass). The hair grid
// (HairGridPass, docs/THEORY.md §2.7) is built at construction with params.gridResolution, which cannot change
// later; record() rebuilds it from the particles before the simulation whenever the params make it act
// (volume or friction above 0), except on a teleport frame.
// Barriers: record() guards its own uniform block; the caller orders positions()/previous() between
// passes and frames (before: any earlier ComputeWrite/reads finished; after: BufferUse::ComputeWrite).
#include <glm/glm.hpp>

#include <optional>
#include <span>

#include "compute/strands/character_pass.h"
#include "compute/strands/hair_grid_pass.h"
#include "compute/strands/sdf_buffer.h"
#include "engine/core/hair/hair_asset.h"
#include "compute/strands/scalp_input.h"
#include "engine/core/hair/sim_params.h"
#include "engine/vk/buffer.h"
#include "engine/vk/descriptors.h"
#include "engine/vk/pipeline_library.h"
#include "engine/vk/profiler.h"
#include "shaders/shared/simulate.h"

namespace hp {
// Where the head is during one frame, and the clock.
struct HeadMotion {
  glm::mat4 from{1.0f};  // head-to-world at the start of the frame
  glm::mat4 to{1.0f};    // at its end
  double time = 0.0;     // seconds at the start of the frame
  bool teleport = false; // carry the hair rigidly instead of simulating the jump
};

class SimulatePass {
 public:
  // Guides start in their rest pose placed by `initialHead`. Throws hp::Error on invalid params or
  // an asset the pass cannot hold (too many colliders, buffers past maxStorageBufferRange).
  SimulatePass(const vk::Context& ctx, const HairAsset& asset, const SimulationParams& params,
               const glm::mat4& initialHead = glm::mat4(1.0f), vk::PipelineLibrary* library = nullptr,
               const ScalpInput& scalp = {});

  // Throws hp::Error on invalid params or a gridResolution other than the one the pass was built with.
  void setParams(const SimulationParams& params);
  // The colliders of the next frames, in head space (they move with HeadMotion): any time between frames.
  // Throws hp::Error on too many, negative or non-finite ones.
  void setColliders(std::span<const SphereCollider> spheres, std::span<const CapsuleCollider> capsules = {});
  // Scalp input Bones: the bone matrices at the end of the next recorded frame (ScalpState::setBones).
  void setBones(std::span<const glm::mat4> bones) { scalp_.setBones(bones); }
  // Scalp input RootFrames: the application's buffer (offset, bytes from it) that the next recorded frames
  // read, in a new descriptor set; the one frames already recorded bind is returned for the caller to keep
  // until they are done. Throws hp::Error as ScalpState::setRootFrames.
  std::shared_ptr<vk::DescriptorSet> setRootFrames(VkBuffer buffer, VkDeviceSize offset, VkDeviceSize bytes);
  // A skinned character the hair collides with (HairAsset::characterCollides): its pose for the next recorded
  // frame (one head-space matrix per joint), which record() skins and rebuilds the distance grid from on the
  // device (CharacterPass). Throws hp::Error when the asset has none or the pose does not fit it.
  void setCharacterPose(std::span<const glm::mat4> bones);
  // The character pass, or null; characterPosed(): whether the last record() posed it.
  const CharacterPass* character() const { return character_.get(); }
  bool characterPosed() const { return characterPosed_; }
  const SimulationParams& params() const { return params_; }
  // Puts every guide back in its rest pose at `head` (one-shot upload, outside the frame loop).
  void reset(const glm::mat4& head);
  void record(VkCommandBuffer cmd, const HeadMotion& motion, vk::GpuProfiler* profiler = nullptr);

  const vk::Buffer& positions() const { return positions_; }
  const vk::Buffer& previous() const { return previous_; }
  std::uint32_t guideCount() const { return guideCount_; }
  std::uint32_t particlesPerGuide() const { return particlesPerGuide_; }
  // Rest pose in head space (xyz) and the rest length of the segment ending at each particle (w).
  const std::vector<glm::vec4>& rest() const { return rest_; }
  const std::vector<SphereCollider>& colliders() const { return colliders_; }
  const std::vector<CapsuleCollider>& capsules() const { return capsules_; }
  const std::shared_ptr<const SdfGrid>& sdf() const { return sdf_.grid(); }
  const HairGridPass& grid() const { return *grid_; }
  HairGridPass& grid() { return *grid_; }

 private:
  gpu::SimFrame frameConstants(const HeadMotion& motion, bool gridActs) const;
  vk::DescriptorSet makeSet() const;  // every binding of the simulate shader, as the pass holds them now

  const vk::Context& ctx_;
  SimulationParams params_;
  std::uint32_t guideCount_;
  std::uint32_t particlesPerGuide_;
  std::vector<glm::vec4> rest_;
  std::vector<SphereCollider> colliders_;
  std::vector<CapsuleCollider> capsules_;
  ScalpState scalp_;
  vk::Buffer positions_;
  vk::Buffer previous_;
  vk::Buffer restBuffer_;
  vk::Buffer frame_;
  SdfBuffer sdf_;
  std::unique_ptr<CharacterPass> character_;
  bool characterPosed_ = false;
  std::optional<HairGridPass> grid_;
  vk::DescriptorSet set_;
  std::shared_ptr<const vk::ComputePipeline> pipeline_;
  bool frameWritten_ = false;
};

// Rest pose of an asset's guides as the simulation stores it (see SimulatePass::rest()).
std::vector<glm::vec4> guideRestPose(const GuideSet& guides);
}  // namespace hp
