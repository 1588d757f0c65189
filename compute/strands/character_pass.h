#pragma once
// Contract: a skinned character mesh on the device (docs/THEORY.md §8.7, shaders/shared/character.h): its rest
// vertices, skin weights and triangles uploaded once; setPose() takes the next frame's bone matrices (head
// space, bind pose to pose), and the record() after it skins the mesh into posedPositions()/posedNormals() and
// rebuilds the simulation's distance grid (the SdfBuffer given, in its grid's place and spacing) from the
// posed triangles within CHARACTER_SDF_BAND_CELLS cells of them (past that band: minus or plus the band, by the
// side of the body the node is on along its row). A record() without a new pose records
// nothing (the grid and the posed vertices keep the last pose; before any pose, the grid is the one the
// SdfBuffer was made with and the posed buffers hold the rest pose).
// Barriers: record() orders its own work after the previous frame's reads of what it writes (compute reads of
// the grid, transfer and compute reads of the posed buffers) and leaves the grid visible to compute reads and
// the posed buffers to compute and transfer reads.
#include <glm/glm.hpp>

#include <memory>
#include <span>
#include <vector>

#include "compute/strands/sdf_buffer.h"
#include "engine/core/hair/character_mesh.h"
#include "engine/vk/buffer.h"
#include "engine/vk/descriptors.h"
#include "engine/vk/pipeline_library.h"
#include "shaders/shared/character.h"

namespace hp {
class CharacterPass {
 public:
  // `scalp`: per vertex the head mesh's scalp weight (kept in the posed normals' w), or empty. Throws hp::Error
  // for a rigid mesh, one past CHARACTER_MAX_BONES bones, an SdfBuffer without a grid, or buffers past the
  // device's limits.
  CharacterPass(const vk::Context& ctx, const CharacterMesh& mesh, std::span<const float> scalp, const SdfBuffer& sdf,
                vk::PipelineLibrary* library);
  // One head-space matrix per joint; throws hp::Error on another count or a non-finite matrix.
  void setPose(std::span<const glm::mat4> bones);
  bool posePending() const { return pending_; }
  // Records the skinning and the grid when a pose is pending; returns whether it did.
  bool record(VkCommandBuffer cmd);

  const vk::Buffer& posedPositions() const { return posed_; }
  const vk::Buffer& posedNormals() const { return posedNormals_; }
  std::uint32_t vertexCount() const { return params_.counts.x; }

 private:
  const vk::Context& ctx_;
  gpu::CharacterParams params_{};
  std::vector<glm::mat4> bones_;
  bool pending_ = false;
  vk::Buffer rest_, skin_, triangles_, bonesBuffer_, posed_, posedNormals_, keys_;
  const vk::Buffer& sdf_;
  vk::DescriptorSet set_;
  std::shared_ptr<const vk::ComputePipeline> skinPipeline_, splat_, finish_;
};
}  // namespace hp
