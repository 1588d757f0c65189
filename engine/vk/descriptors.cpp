#include "engine/vk/descriptors.h"

#include <map>
#include <utility>
#include <vector>

#include "engine/vk/check.h"
#include "engine/vk/context.h"

namespace hp::vk {
DescriptorSet::DescriptorSet(const Context& ctx, std::span<const Binding> bindings, const std::string& name)
    : device_(ctx.device()), fn_(&ctx.fn()) {
  std::vector<VkDescriptorSetLayoutBinding> layoutBindings;
  std::map<VkDescriptorType, std::uint32_t> typeCounts;
  for (const Binding& b : bindings) {
    layoutBindings.push_back({b.binding, b.type, 1, b.stages, nullptr});
    ++typeCounts[b.type];
  }
  VkDescriptorSetLayoutCreateInfo layoutInfo{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO};
  layoutInfo.bindingCount = static_cast<std::uint32_t>(layoutBindings.size());
  layoutInfo.pBindings = layoutBindings.data();
  HP_VK_CHECK(fn_->vkCreateDescriptorSetLayout(device_, &layoutInfo, nullptr, &layout_));

  try {
    ctx.setName(VK_OBJECT_TYPE_DESCRIPTOR_SET_LAYOUT, reinterpret_cast<std::uint64_t>(layout_), name + " layout");
    set_ = ctx.descriptorPools().allocate(layout_, typeCounts, pool_);
    pools_ = &ctx.descriptorPools();
    counts_ = std::move(typeCounts);
    ctx.setName(VK_OBJECT_TYPE_DESCRIPTOR_SET, reinterpret_cast<std::uint64_t>(set_), name);
  } catch (...) {
    release();
    throw;
  }
}

DescriptorSet::~DescriptorSet() { release(); }

DescriptorSet::DescriptorSet(DescriptorSet&& other) noexcept { *this = std::move(other); }

DescriptorSet& DescriptorSet::operator=(DescriptorSet&& other) noexcept {
  if (this != &other) {
    release();
    device_ = std::exchange(other.device_, VK_NULL_HANDLE);
    fn_ = std::exchange(other.fn_, nullptr);
    layout_ = std::exchange(other.layout_, VK_NULL_HANDLE);
    pools_ = std::exchange(other.pools_, nullptr);
    pool_ = std::exchange(other.pool_, VK_NULL_HANDLE);
    set_ = std::exchange(other.set_, VK_NULL_HANDLE);
    counts_ = std::move(other.counts_);
  }
  return *this;
}

void DescriptorSet::release() {
  if (pools_ && set_) pools_->free(pool_, set_, counts_);
  if (layout_) fn_->vkDestroyDescriptorSetLayout(device_, layout_, nullptr);
  pools_ = nullptr;
  pool_ = VK_NULL_HANDLE;
  layout_ = VK_NULL_HANDLE;
  set_ = VK_NULL_HANDLE;
}

void DescriptorSet::writeBuffer(std::uint32_t binding, VkDescriptorType type, VkBuffer buffer, VkDeviceSize offset,
                                VkDeviceSize range) const {
  VkDescriptorBufferInfo info{buffer, offset, range};
  VkWriteDescriptorSet write{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
  write.pBufferInfo = &info;
  update(binding, type, write);
}

void DescriptorSet::writeImage(std::uint32_t binding, VkDescriptorType type, const VkDescriptorImageInfo& info) const {
  VkWriteDescriptorSet write{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
  write.pImageInfo = &info;
  update(binding, type, write);
}

void DescriptorSet::update(std::uint32_t binding, VkDescriptorType type, VkWriteDescriptorSet write) const {
  write.dstSet = set_;
  write.dstBinding = binding;
  write.descriptorCount = 1;
  write.descriptorType = type;
  fn_->vkUpdateDescriptorSets(device_, 1, &write, 0, nullptr);
}

void DescriptorSet::writeSampledImage(std::uint32_t binding, VkImageView view, VkSampler sampler,
                                      VkImageLayout layout) const {
  writeImage(binding, VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, {sampler, view, layout});
}

void DescriptorSet::writeTexelBuffer(std::uint32_t binding, VkBufferView view) const {
  VkWriteDescriptorSet write{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET};
  write.pTexelBufferView = &view;
  update(binding, VK_DESCRIPTOR_TYPE_UNIFORM_TEXEL_BUFFER, write);
}

void DescriptorSet::writeStorageImage(std::uint32_t binding, VkImageView view) const {
  writeImage(binding, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, {VK_NULL_HANDLE, view, VK_IMAGE_LAYOUT_GENERAL});
}
}  // namespace hp::vk
