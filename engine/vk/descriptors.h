#pragma once
// Contract: one descriptor set together with its layout, move-only; the set comes from the Context's shared
// descriptor pools (descriptor_pools.h) and goes back to them.
// Passes declare their bindings once (numbers from the shared GLSL/C++ header) and write resources
// whenever the buffers behind them change; writes happen outside command recording.
#include "hairpipe_volk.h"

#include <cstdint>

#include <map>
#include <span>
#include <string>

#include "engine/vk/descriptor_pools.h"

namespace hp::vk {
class Context;

struct Binding {
  std::uint32_t binding;
  VkDescriptorType type;
  VkShaderStageFlags stages;
};

// The shorthands the passes' binding tables are written in (one definition: the library is built in unity
// batches, where a file-local copy in each pass would collide).
inline constexpr VkShaderStageFlags kCompute = VK_SHADER_STAGE_COMPUTE_BIT;
inline constexpr VkShaderStageFlags kVertex = VK_SHADER_STAGE_VERTEX_BIT;
inline constexpr VkShaderStageFlags kFragment = VK_SHADER_STAGE_FRAGMENT_BIT;
inline constexpr VkDescriptorType kStorage = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
inline constexpr VkDescriptorType kSampled = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
inline constexpr VkDescriptorType kTexels = VK_DESCRIPTOR_TYPE_UNIFORM_TEXEL_BUFFER;

class DescriptorSet {
 public:
  DescriptorSet() = default;
  DescriptorSet(const Context& ctx, std::span<const Binding> bindings, const std::string& name);
  ~DescriptorSet();
  DescriptorSet(DescriptorSet&& other) noexcept;
  DescriptorSet& operator=(DescriptorSet&& other) noexcept;
  DescriptorSet(const DescriptorSet&) = delete;
  DescriptorSet& operator=(const DescriptorSet&) = delete;

  VkDescriptorSetLayout layout() const { return layout_; }
  VkDescriptorSet set() const { return set_; }

  void writeBuffer(std::uint32_t binding, VkDescriptorType type, VkBuffer buffer, VkDeviceSize offset = 0,
                   VkDeviceSize range = VK_WHOLE_SIZE) const;
  void writeStorageBuffer(std::uint32_t binding, VkBuffer buffer) const {
    writeBuffer(binding, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, buffer);
  }
  void writeSampledImage(std::uint32_t binding, VkImageView view, VkSampler sampler,
                         VkImageLayout layout = VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL) const;
  // A uniform texel buffer (engine/vk/buffer_view.h).
  void writeTexelBuffer(std::uint32_t binding, VkBufferView view) const;
  // A storage image, used in VK_IMAGE_LAYOUT_GENERAL (ImageUse::ComputeStorageWrite).
  void writeStorageImage(std::uint32_t binding, VkImageView view) const;

 private:
  void writeImage(std::uint32_t binding, VkDescriptorType type, const VkDescriptorImageInfo& info) const;
  // Writes one descriptor of `type` at `binding`; `write` carries its buffer, image or texel view.
  void update(std::uint32_t binding, VkDescriptorType type, VkWriteDescriptorSet write) const;
  void release();
  VkDevice device_ = VK_NULL_HANDLE;
  const VolkDeviceTable* fn_ = nullptr;  // the Context's device functions
  VkDescriptorSetLayout layout_ = VK_NULL_HANDLE;
  DescriptorPools* pools_ = nullptr;
  VkDescriptorPool pool_ = VK_NULL_HANDLE;  // the shared pool the set came from
  VkDescriptorSet set_ = VK_NULL_HANDLE;
  std::map<VkDescriptorType, std::uint32_t> counts_;  // its descriptors per type, given back with it
};
}  // namespace hp::vk
