#pragma once
// Contract: the device memory behind hairpipe's buffers and images, sub-allocated from blocks, so a hair
// instance costs a few vkAllocateMemory calls instead of one per buffer (drivers may allow as few as
// 4,096 allocations in all). Blocks are kBlockBytes per memory type, buffers and images in separate
// blocks (so bufferImageGranularity never matters); a request of more than half a block, or one the
// driver wants dedicated (VkMemoryDedicatedRequirements), gets memory of its own. Blocks of host-visible
// types are mapped once, whole. A block is freed when its last allocation is. Thread-safe. Owned by the
// Context, which frees what is left before destroying the device; every buffer and image goes first.
#include "hairpipe_volk.h"

#include <cstdint>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

namespace hp::vk {
class Context;

struct MemoryAllocation {
  VkDeviceMemory memory = VK_NULL_HANDLE;
  VkDeviceSize offset = 0;
  void* mapped = nullptr;      // host-visible types: the allocation's first byte
  std::uint32_t block = ~0u;   // the pool's block (internal)
  VkDeviceSize size = 0;       // as reserved (the requirement's size)
};

// What to allocate for: the requirements, the memory type chosen for them, and whether the driver
// wants the memory dedicated to `buffer` or `image` (at most one of them set).
struct MemoryRequest {
  VkMemoryRequirements requirements{};
  std::uint32_t typeIndex = 0;
  bool forImage = false;
  bool dedicated = false;
  VkBuffer buffer = VK_NULL_HANDLE;
  VkImage image = VK_NULL_HANDLE;
};

class MemoryPool {
 public:
  static constexpr VkDeviceSize kBlockBytes = VkDeviceSize(64) << 20;

  explicit MemoryPool(const Context& ctx);
  ~MemoryPool();
  MemoryPool(const MemoryPool&) = delete;
  MemoryPool& operator=(const MemoryPool&) = delete;

  // What `buffer` needs (memory with `required` flags, preferring `preferred` ones) and what `image`
  // needs (device-local), asked of the driver with its dedicated-allocation wish.
  MemoryRequest bufferRequest(VkBuffer buffer, VkMemoryPropertyFlags required, VkMemoryPropertyFlags preferred) const;
  MemoryRequest imageRequest(VkImage image) const;
  MemoryAllocation allocate(const MemoryRequest& request);
  void free(const MemoryAllocation& allocation) noexcept;
  // vkAllocateMemory calls made so far, and blocks held now (tests and `bench instances`).
  std::uint64_t deviceAllocations() const;
  std::size_t blocksHeld() const;
  // Frees every block still held (the Context, before destroying the device).
  void releaseAll() noexcept;

 private:
  struct Block {
    VkDeviceMemory memory = VK_NULL_HANDLE;
    VkDeviceSize size = 0;
    void* mapped = nullptr;
    std::uint32_t typeIndex = 0;
    bool forImage = false;
    bool dedicated = false;
    std::map<VkDeviceSize, VkDeviceSize> freeRanges;  // offset -> size
    std::uint32_t live = 0;
  };
  std::uint32_t newBlock(const MemoryRequest& request, VkDeviceSize size);
  bool take(Block& block, VkDeviceSize size, VkDeviceSize alignment, VkDeviceSize& offset);
  void release(Block& block) noexcept;

  VkDevice device_;
  const VolkDeviceTable* fn_;
  const Context* ctx_;
  mutable std::mutex mutex_;
  std::vector<Block> blocks_;  // index = MemoryAllocation::block; released blocks stay as empty slots
  std::uint64_t allocations_ = 0;
};
}  // namespace hp::vk
