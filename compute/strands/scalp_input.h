#pragma once
// Contract: where the guide roots of a simulation come from (shaders/shared/simulate.h "Scalp input"):
//   Rigid       the head's rigid transform pair of HeadMotion (default)
//   RootFrames  a device buffer the application's skinning writes every frame: per guide, 2 vec4 = world
//               position (xyz) and unit orientation quaternion (xyzw) of the root. The frame maps the
//               head-space rest pose around its root, so the rest pose follows the root's rotation.
//               Before recordUpdate the application makes its writes visible to COMPUTE_SHADER storage
//               reads; hairpipe only reads it, in COMPUTE_SHADER, during recordUpdate.
//   Bones       bone matrices (head-space rest -> world) given by the host every frame (setBones) and
//               per-guide weights of up to 4 bones (TressFX-style skinning data), linear blend skinning.
// The roots follow exactly (the root particle is pinned to the skinned root at every substep end).
// ScalpState owns the buffers behind the mode (the previous root frames, the bone matrices, the weights)
// and records the per-frame bone upload; the simulate pass binds them.
#include "hairpipe_volk.h"

#include <glm/glm.hpp>

#include <span>
#include <vector>

#include "engine/vk/buffer.h"
#include "engine/vk/descriptors.h"
#include "shaders/shared/simulate.h"

namespace hp {
struct ScalpInput {
  enum class Kind { Rigid, RootFrames, Bones };
  Kind kind = Kind::Rigid;
  VkBuffer rootFrames = VK_NULL_HANDLE;  // RootFrames: the application's buffer (storage usage) ...
  VkDeviceSize rootFramesBytes = 0;      // ... its size from rootFramesOffset, at least guides x 32 bytes
  VkDeviceSize rootFramesOffset = 0;     // ... where the frames start: a multiple of minStorageBufferOffsetAlignment
  std::vector<gpu::SkinWeights> skin;    // Bones: one per guide, weights >= 0 summing to 1
  std::uint32_t boneCount = 0;           // Bones: [1, SIM_MAX_BONES]
  void validate(std::uint32_t guideCount) const;  // throws hp::Error naming the problem
};

class ScalpState {
 public:
  // `rest`: the simulation's head-space rest pose (root of guide g at g x particlesPerGuide).
  ScalpState(const vk::Context& ctx, const ScalpInput& input, std::span<const glm::vec4> rest,
             std::uint32_t particlesPerGuide, const glm::mat4& initialHead);
  std::uint32_t mode() const;
  void writeDescriptors(const vk::DescriptorSet& set) const;
  // Bones: this frame's matrices (the previous call's are the frame's start). Throws hp::Error on a wrong
  // count or non-finite values.
  void setBones(std::span<const glm::mat4> bones);
  std::uint32_t boneCount() const { return input_.boneCount; }
  // RootFrames: the application's buffer from now on (descriptors written after this call read it). Throws
  // hp::Error in another mode, for a null buffer, too few bytes or a misaligned offset.
  void setRootFrames(VkBuffer buffer, VkDeviceSize offset, VkDeviceSize bytes);
  const ScalpInput& input() const { return input_; }
  // Records the bone upload (Bones mode, when setBones gave new ones); guards its buffer with barriers.
  void record(VkCommandBuffer cmd);

 private:
  const vk::Context* ctx_;
  ScalpInput input_;
  vk::Buffer rootsPrev_;  // RootFrames: last frame's root frames (written by the simulate shader)
  VkDeviceSize rootFramesRange_ = 0;  // RootFrames: the bytes of the application's buffer read, guides x 32
  vk::Buffer bones_;      // Bones: 2 x boneCount mat4 (start, end)
  vk::Buffer skin_;       // Bones: SkinWeights per guide
  vk::Buffer dummy_;      // bound where the mode reads nothing
  std::vector<glm::mat4> previous_, current_;
  bool everRecorded_ = false;
};
}  // namespace hp
