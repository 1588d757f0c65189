#include "engine/vk/descriptor_pools.h"

#include <algorithm>
#include <string>

#include "engine/core/error.h"
#include "engine/vk/check.h"
#include "engine/vk/context.h"

namespace hp::vk {
namespace {
// Every descriptor type hairpipe's passes bind (no uniform buffer: docs/DESIGN.md, driver notes).
constexpr VkDescriptorType kTypes[] = {VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER_DYNAMIC,
                                       VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE,
                                       VK_DESCRIPTOR_TYPE_UNIFORM_TEXEL_BUFFER};
}  // namespace

DescriptorPools::DescriptorPools(const Context& ctx) : device_(ctx.device()), fn_(&ctx.fn()), ctx_(&ctx) {}

DescriptorPools::~DescriptorPools() {
  for (const Pool& p : pools_) fn_->vkDestroyDescriptorPool(device_, p.pool, nullptr);
}

bool DescriptorPools::Pool::fits(const std::map<VkDescriptorType, std::uint32_t>& counts) const {
  if (setsLeft == 0) return false;
  for (const auto& [type, n] : counts) {
    const auto it = left.find(type);
    if ((it == left.end() ? kDescriptorsPerType : it->second) < n) return false;
  }
  return true;
}

DescriptorPools::Pool DescriptorPools::makePool() {
  std::vector<VkDescriptorPoolSize> sizes;
  for (VkDescriptorType t : kTypes) sizes.push_back({t, kDescriptorsPerType});
  VkDescriptorPoolCreateInfo info{VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO};
  info.flags = VK_DESCRIPTOR_POOL_CREATE_FREE_DESCRIPTOR_SET_BIT;
  info.maxSets = kSetsPerPool;
  info.poolSizeCount = std::uint32_t(sizes.size());
  info.pPoolSizes = sizes.data();
  Pool p;
  HP_VK_CHECK(fn_->vkCreateDescriptorPool(device_, &info, nullptr, &p.pool));
  ++created_;
  ctx_->setName(VK_OBJECT_TYPE_DESCRIPTOR_POOL, reinterpret_cast<std::uint64_t>(p.pool),
                "hairpipe descriptor pool " + std::to_string(created_));
  return p;
}

VkDescriptorSet DescriptorPools::allocate(VkDescriptorSetLayout layout,
                                          const std::map<VkDescriptorType, std::uint32_t>& counts,
                                          VkDescriptorPool& poolOut) {
  for (const auto& [type, n] : counts) {
    if (std::find(std::begin(kTypes), std::end(kTypes), type) == std::end(kTypes))
      throw Error("descriptor pools: descriptor type " + std::to_string(type) + " is not one hairpipe's pools hold");
    if (n > kDescriptorsPerType) throw Error("descriptor pools: a set of " + std::to_string(n) + " descriptors of one type");
  }
  std::lock_guard lock(mutex_);
  auto it = std::find_if(pools_.begin(), pools_.end(), [&](const Pool& p) { return p.fits(counts); });
  if (it == pools_.end()) {
    pools_.push_back(makePool());
    it = std::prev(pools_.end());
  }
  VkDescriptorSetAllocateInfo alloc{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO};
  alloc.descriptorPool = it->pool;
  alloc.descriptorSetCount = 1;
  alloc.pSetLayouts = &layout;
  VkDescriptorSet set = VK_NULL_HANDLE;
  const VkResult first = fn_->vkAllocateDescriptorSets(device_, &alloc, &set);
  if (first == VK_ERROR_FRAGMENTED_POOL || first == VK_ERROR_OUT_OF_POOL_MEMORY) {
    // Counted room is not always the driver's (fragmentation): this pool takes no more, a fresh one does.
    it->setsLeft = 0;
    pools_.push_back(makePool());
    it = std::prev(pools_.end());
    alloc.descriptorPool = it->pool;
    HP_VK_CHECK(fn_->vkAllocateDescriptorSets(device_, &alloc, &set));
  } else {
    check(first, "vkAllocateDescriptorSets");
  }
  --it->setsLeft;
  for (const auto& [type, n] : counts) {
    auto [entry, fresh] = it->left.try_emplace(type, kDescriptorsPerType);
    entry->second -= n;
  }
  poolOut = it->pool;
  return set;
}

void DescriptorPools::free(VkDescriptorPool pool, VkDescriptorSet set,
                           const std::map<VkDescriptorType, std::uint32_t>& counts) noexcept {
  std::lock_guard lock(mutex_);
  const auto it = std::find_if(pools_.begin(), pools_.end(), [&](const Pool& p) { return p.pool == pool; });
  if (it == pools_.end()) return;
  fn_->vkFreeDescriptorSets(device_, pool, 1, &set);
  ++it->setsLeft;
  for (const auto& [type, n] : counts) it->left[type] += n;
  if (it->setsLeft == kSetsPerPool) {  // its last set went
    fn_->vkDestroyDescriptorPool(device_, it->pool, nullptr);
    pools_.erase(it);
  }
}

std::size_t DescriptorPools::poolsHeld() const {
  std::lock_guard lock(mutex_);
  return pools_.size();
}

std::uint64_t DescriptorPools::poolsCreated() const {
  std::lock_guard lock(mutex_);
  return created_;
}
}  // namespace hp::vk
