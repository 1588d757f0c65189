#pragma once
// Contract: the descriptor pools every hairpipe descriptor set comes from, shared per Context instead of a
// pool per set: pools of kSetsPerPool sets with room for kDescriptorsPerType descriptors of each type,
// created as needed (FREE_DESCRIPTOR_SET), each set taken from the first pool with room for its
// descriptors (counted here, so the driver's out-of-pool results are never relied on) and given back on
// release; a pool whose last set goes is destroyed. Thread-safe. Owned by the Context, which destroys what
// is left before the device; every descriptor set goes first.
#include "hairpipe_volk.h"

#include <cstdint>
#include <map>
#include <mutex>
#include <vector>

namespace hp::vk {
class Context;

class DescriptorPools {
 public:
  static constexpr std::uint32_t kSetsPerPool = 256;
  static constexpr std::uint32_t kDescriptorsPerType = 2048;

  explicit DescriptorPools(const Context& ctx);
  ~DescriptorPools();
  DescriptorPools(const DescriptorPools&) = delete;
  DescriptorPools& operator=(const DescriptorPools&) = delete;

  // A set of `layout` holding `counts` descriptors per type; the pool it came from is returned for free().
  VkDescriptorSet allocate(VkDescriptorSetLayout layout, const std::map<VkDescriptorType, std::uint32_t>& counts,
                           VkDescriptorPool& pool);
  void free(VkDescriptorPool pool, VkDescriptorSet set, const std::map<VkDescriptorType, std::uint32_t>& counts) noexcept;
  std::size_t poolsHeld() const;
  std::uint64_t poolsCreated() const;

 private:
  struct Pool {
    VkDescriptorPool pool = VK_NULL_HANDLE;
    std::uint32_t setsLeft = kSetsPerPool;
    std::map<VkDescriptorType, std::uint32_t> left;  // descriptors left per type (absent: kDescriptorsPerType)
    bool fits(const std::map<VkDescriptorType, std::uint32_t>& counts) const;
  };
  Pool makePool();

  VkDevice device_;
  const VolkDeviceTable* fn_;
  const Context* ctx_;
  mutable std::mutex mutex_;
  std::vector<Pool> pools_;
  std::uint64_t created_ = 0;
};
}  // namespace hp::vk
