#include "engine/vk/memory_pool.h"

#include <utility>

#include "engine/vk/check.h"
#include "engine/vk/context.h"

namespace hp::vk {
namespace {
VkDeviceSize alignUp(VkDeviceSize v, VkDeviceSize a) { return a > 1 ? (v + a - 1) / a * a : v; }
}  // namespace

MemoryPool::MemoryPool(const Context& ctx) : device_(ctx.device()), fn_(&ctx.fn()), ctx_(&ctx) {}

MemoryPool::~MemoryPool() { releaseAll(); }

MemoryRequest MemoryPool::bufferRequest(VkBuffer buffer, VkMemoryPropertyFlags required,
                                        VkMemoryPropertyFlags preferred) const {
  VkBufferMemoryRequirementsInfo2 query{VK_STRUCTURE_TYPE_BUFFER_MEMORY_REQUIREMENTS_INFO_2};
  query.buffer = buffer;
  VkMemoryDedicatedRequirements dedicated{VK_STRUCTURE_TYPE_MEMORY_DEDICATED_REQUIREMENTS};
  VkMemoryRequirements2 req{VK_STRUCTURE_TYPE_MEMORY_REQUIREMENTS_2, &dedicated};
  fn_->vkGetBufferMemoryRequirements2(device_, &query, &req);
  MemoryRequest r;
  r.requirements = req.memoryRequirements;
  r.typeIndex = ctx_->findMemoryType(req.memoryRequirements.memoryTypeBits, required, preferred);
  r.dedicated = dedicated.requiresDedicatedAllocation || dedicated.prefersDedicatedAllocation;
  r.buffer = buffer;
  return r;
}

MemoryRequest MemoryPool::imageRequest(VkImage image) const {
  VkImageMemoryRequirementsInfo2 query{VK_STRUCTURE_TYPE_IMAGE_MEMORY_REQUIREMENTS_INFO_2};
  query.image = image;
  VkMemoryDedicatedRequirements dedicated{VK_STRUCTURE_TYPE_MEMORY_DEDICATED_REQUIREMENTS};
  VkMemoryRequirements2 req{VK_STRUCTURE_TYPE_MEMORY_REQUIREMENTS_2, &dedicated};
  fn_->vkGetImageMemoryRequirements2(device_, &query, &req);
  MemoryRequest r;
  r.requirements = req.memoryRequirements;
  r.typeIndex = ctx_->findMemoryType(req.memoryRequirements.memoryTypeBits, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT);
  r.forImage = true;
  r.dedicated = dedicated.requiresDedicatedAllocation || dedicated.prefersDedicatedAllocation;
  r.image = image;
  return r;
}

std::uint32_t MemoryPool::newBlock(const MemoryRequest& request, VkDeviceSize size) {
  VkMemoryAllocateInfo alloc{VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO};
  alloc.allocationSize = size;
  alloc.memoryTypeIndex = request.typeIndex;
  VkMemoryDedicatedAllocateInfo dedicated{VK_STRUCTURE_TYPE_MEMORY_DEDICATED_ALLOCATE_INFO};
  if (request.dedicated) {
    dedicated.buffer = request.buffer;
    dedicated.image = request.image;
    alloc.pNext = &dedicated;
  }
  Block block;
  block.size = size;
  block.typeIndex = request.typeIndex;
  block.forImage = request.forImage;
  block.dedicated = request.dedicated;
  HP_VK_CHECK(fn_->vkAllocateMemory(device_, &alloc, nullptr, &block.memory));
  ++allocations_;
  const VkMemoryPropertyFlags flags = ctx_->memoryProperties().memoryTypes[request.typeIndex].propertyFlags;
  if (flags & VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT) {
    const VkResult r = fn_->vkMapMemory(device_, block.memory, 0, VK_WHOLE_SIZE, 0, &block.mapped);
    if (r != VK_SUCCESS) fn_->vkFreeMemory(device_, block.memory, nullptr);
    check(r, "vkMapMemory");
  }
  block.freeRanges[0] = size;
  const VkDeviceMemory memory = block.memory;
  std::uint32_t index = std::uint32_t(blocks_.size());
  for (std::uint32_t i = 0; i < blocks_.size(); ++i)
    if (blocks_[i].memory == VK_NULL_HANDLE) {
      index = i;
      break;
    }
  if (index == blocks_.size()) blocks_.emplace_back();
  blocks_[index] = std::move(block);
  // Named once held (a failing name leaves the block to releaseAll, not leaked).
  ctx_->setName(VK_OBJECT_TYPE_DEVICE_MEMORY, reinterpret_cast<std::uint64_t>(memory),
                std::string(request.dedicated ? "hairpipe dedicated memory" : "hairpipe memory block") + " (type " +
                    std::to_string(request.typeIndex) + (request.forImage ? ", images)" : ", buffers)"));
  return index;
}

// First fit: the lowest free range that holds `size` at `alignment`; what is left on either side stays free.
bool MemoryPool::take(Block& block, VkDeviceSize size, VkDeviceSize alignment, VkDeviceSize& offset) {
  for (auto it = block.freeRanges.begin(); it != block.freeRanges.end(); ++it) {
    const VkDeviceSize start = it->first, end = it->first + it->second;
    const VkDeviceSize aligned = alignUp(start, alignment);
    if (aligned + size > end) continue;
    block.freeRanges.erase(it);
    if (aligned > start) block.freeRanges[start] = aligned - start;
    if (aligned + size < end) block.freeRanges[aligned + size] = end - (aligned + size);
    offset = aligned;
    ++block.live;
    return true;
  }
  return false;
}

MemoryAllocation MemoryPool::allocate(const MemoryRequest& request) {
  const VkDeviceSize size = request.requirements.size, alignment = request.requirements.alignment;
  std::lock_guard lock(mutex_);
  MemoryAllocation a;
  a.size = size;
  const bool own = request.dedicated || size > kBlockBytes / 2;
  if (!own)
    for (std::uint32_t i = 0; i < blocks_.size() && a.memory == VK_NULL_HANDLE; ++i) {
      Block& b = blocks_[i];
      if (b.memory && !b.dedicated && b.typeIndex == request.typeIndex && b.forImage == request.forImage &&
          take(b, size, alignment, a.offset)) {
        a.memory = b.memory;
        a.block = i;
      }
    }
  if (a.memory == VK_NULL_HANDLE) {
    a.block = newBlock(request, own ? size : kBlockBytes);
    take(blocks_[a.block], size, alignment, a.offset);  // a fresh block: offset 0
    a.memory = blocks_[a.block].memory;
  }
  if (blocks_[a.block].mapped) a.mapped = static_cast<std::byte*>(blocks_[a.block].mapped) + a.offset;
  return a;
}

void MemoryPool::free(const MemoryAllocation& a) noexcept {
  if (a.memory == VK_NULL_HANDLE) return;
  std::lock_guard lock(mutex_);
  Block& b = blocks_[a.block];
  auto next = b.freeRanges.emplace(a.offset, a.size).first;
  if (auto after = std::next(next); after != b.freeRanges.end() && next->first + next->second == after->first) {
    next->second += after->second;
    b.freeRanges.erase(after);
  }
  if (next != b.freeRanges.begin()) {
    auto before = std::prev(next);
    if (before->first + before->second == next->first) {
      before->second += next->second;
      b.freeRanges.erase(next);
    }
  }
  if (--b.live == 0) release(b);
}

void MemoryPool::release(Block& b) noexcept {
  if (b.memory) fn_->vkFreeMemory(device_, b.memory, nullptr);  // unmaps too
  b = Block{};
}

std::uint64_t MemoryPool::deviceAllocations() const {
  std::lock_guard lock(mutex_);
  return allocations_;
}

std::size_t MemoryPool::blocksHeld() const {
  std::lock_guard lock(mutex_);
  std::size_t n = 0;
  for (const Block& b : blocks_) n += b.memory != VK_NULL_HANDLE;
  return n;
}

void MemoryPool::releaseAll() noexcept {
  std::lock_guard lock(mutex_);
  for (Block& b : blocks_) release(b);
}
}  // namespace hp::vk
