#include "compute/strands/scalp_input.h"

#include <cmath>
#include <string>

#include <glm/gtc/quaternion.hpp>

#include "engine/core/error.h"
#include "engine/core/hair/finite.h"
#include "engine/vk/barriers.h"
#include "engine/vk/context.h"
#include "engine/vk/transfer.h"

namespace hp {
namespace {
constexpr VkBufferUsageFlags kScalpUsage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT;

void requireAlignedRootFrames(const vk::Context& ctx, VkDeviceSize offset) {
  const VkDeviceSize alignment = ctx.properties().limits.minStorageBufferOffsetAlignment;
  if (offset % alignment != 0)
    throw Error("scalp input: the root frames' offset " + std::to_string(offset) +
                " is not a multiple of the device's minStorageBufferOffsetAlignment (" + std::to_string(alignment) + ")");
}
}  // namespace

void ScalpInput::validate(std::uint32_t guideCount) const {
  if (kind == Kind::RootFrames) {
    if (rootFrames == VK_NULL_HANDLE) throw Error("scalp input: root frames mode needs the application's buffer");
    if (rootFramesBytes < VkDeviceSize(guideCount) * 2 * sizeof(glm::vec4))
      throw Error("scalp input: the root frame buffer holds " + std::to_string(rootFramesBytes) + " bytes, " +
                  std::to_string(guideCount) + " guides need " + std::to_string(guideCount * 32ull));
  }
  if (kind != Kind::Bones) return;
  if (boneCount == 0 || boneCount > gpu::SIM_MAX_BONES)
    throw Error("scalp input: bone count must be in [1, " + std::to_string(gpu::SIM_MAX_BONES) + "]");
  if (skin.size() != guideCount)
    throw Error("scalp input: " + std::to_string(skin.size()) + " skin weights for " + std::to_string(guideCount) +
                " guides");
  for (const gpu::SkinWeights& s : skin) {
    float sum = 0.0f;
    for (int k = 0; k < 4; ++k) {
      if (s.bones[k] >= boneCount) throw Error("scalp input: a skin weight names a bone past the bone count");
      if (!(s.weights[k] >= 0.0f)) throw Error("scalp input: skin weights must be non-negative numbers");
      sum += s.weights[k];
    }
    if (std::abs(sum - 1.0f) > 1e-4f) throw Error("scalp input: the skin weights of a guide must sum to 1");
  }
}

ScalpState::ScalpState(const vk::Context& ctx, const ScalpInput& input, std::span<const glm::vec4> rest,
                       std::uint32_t particlesPerGuide, const glm::mat4& initialHead)
    : ctx_(&ctx), input_(input) {
  const std::uint32_t guides = static_cast<std::uint32_t>(rest.size() / particlesPerGuide);
  input_.validate(guides);
  if (input_.kind == ScalpInput::Kind::RootFrames) requireAlignedRootFrames(ctx, input_.rootFramesOffset);
  rootFramesRange_ = VkDeviceSize(guides) * 2 * sizeof(glm::vec4);
  dummy_ = vk::Buffer(ctx, 64, kScalpUsage, vk::MemoryKind::DeviceLocal, "scalp unused");
  if (input_.kind == ScalpInput::Kind::RootFrames) {
    // The frame before the first: the rest roots placed by the initial head.
    const glm::quat q = glm::quat_cast(glm::mat3(initialHead));
    std::vector<glm::vec4> frames;
    for (std::uint32_t g = 0; g < guides; ++g) {
      frames.push_back(initialHead * glm::vec4(glm::vec3(rest[std::size_t(g) * particlesPerGuide]), 1.0f));
      frames.emplace_back(q.x, q.y, q.z, q.w);
    }
    rootsPrev_ = vk::Buffer(ctx, frames.size() * sizeof(glm::vec4), kScalpUsage, vk::MemoryKind::DeviceLocal,
                            "previous root frames");
    vk::upload<glm::vec4>(ctx, rootsPrev_, frames, vk::BufferUse::ComputeWrite);
  }
  if (input_.kind == ScalpInput::Kind::Bones) {
    previous_.assign(input_.boneCount, initialHead);
    current_ = previous_;
    bones_ = vk::Buffer(ctx, 2 * input_.boneCount * sizeof(glm::mat4), kScalpUsage, vk::MemoryKind::DeviceLocal, "bones");
    skin_ = vk::Buffer(ctx, input_.skin.size() * sizeof(gpu::SkinWeights), kScalpUsage, vk::MemoryKind::DeviceLocal,
                       "skin weights");
    vk::upload<gpu::SkinWeights>(ctx, skin_, input_.skin, vk::BufferUse::ComputeRead);
  }
}

std::uint32_t ScalpState::mode() const {
  switch (input_.kind) {
    case ScalpInput::Kind::RootFrames: return gpu::SIM_SCALP_ROOT_FRAMES;
    case ScalpInput::Kind::Bones: return gpu::SIM_SCALP_BONES;
    case ScalpInput::Kind::Rigid: break;
  }
  return gpu::SIM_SCALP_RIGID;
}

void ScalpState::writeDescriptors(const vk::DescriptorSet& set) const {
  const bool frames = input_.kind == ScalpInput::Kind::RootFrames;
  const bool bones = input_.kind == ScalpInput::Kind::Bones;
  if (frames)
    set.writeBuffer(gpu::SIM_BINDING_ROOTS, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, input_.rootFrames, input_.rootFramesOffset,
                    rootFramesRange_);
  else
    set.writeStorageBuffer(gpu::SIM_BINDING_ROOTS, dummy_.handle());
  set.writeStorageBuffer(gpu::SIM_BINDING_ROOTS_PREV, frames ? rootsPrev_.handle() : dummy_.handle());
  set.writeStorageBuffer(gpu::SIM_BINDING_BONES, bones ? bones_.handle() : dummy_.handle());
  set.writeStorageBuffer(gpu::SIM_BINDING_SKIN, bones ? skin_.handle() : dummy_.handle());
}

void ScalpState::setRootFrames(VkBuffer buffer, VkDeviceSize offset, VkDeviceSize bytes) {
  if (input_.kind != ScalpInput::Kind::RootFrames) throw Error("setRootFrames: the scalp input is not RootFrames");
  ScalpInput next = input_;
  next.rootFrames = buffer;
  next.rootFramesOffset = offset;
  next.rootFramesBytes = bytes;
  next.validate(std::uint32_t(rootFramesRange_ / (2 * sizeof(glm::vec4))));
  requireAlignedRootFrames(*ctx_, offset);
  input_ = std::move(next);
}

void ScalpState::setBones(std::span<const glm::mat4> bones) {
  if (input_.kind != ScalpInput::Kind::Bones) throw Error("setBones: the scalp input is not Bones");
  if (bones.size() != input_.boneCount)
    throw Error("setBones: " + std::to_string(bones.size()) + " matrices for " + std::to_string(input_.boneCount) +
                " bones");
  for (const glm::mat4& m : bones)
    if (!allFinite(m)) throw Error("setBones: bone matrices must be finite");
  current_.assign(bones.begin(), bones.end());
}

void ScalpState::record(VkCommandBuffer cmd) {
  if (input_.kind != ScalpInput::Kind::Bones) return;
  // start = last frame's end (a frame without setBones holds the bones still).
  std::vector<glm::mat4> both = previous_;
  both.insert(both.end(), current_.begin(), current_.end());
  vk::bufferBarrier(*ctx_, cmd, bones_.handle(), everRecorded_ ? vk::BufferUse::ComputeRead : vk::BufferUse::None,
                    vk::BufferUse::TransferDst);
  ctx_->fn().vkCmdUpdateBuffer(cmd, bones_.handle(), 0, both.size() * sizeof(glm::mat4), both.data());
  vk::bufferBarrier(*ctx_, cmd, bones_.handle(), vk::BufferUse::TransferDst, vk::BufferUse::ComputeRead);
  previous_ = current_;
  everRecorded_ = true;
}
}  // namespace hp
