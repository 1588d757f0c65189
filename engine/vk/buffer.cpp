#include "engine/vk/buffer.h"

#include <utility>

#include "engine/core/error.h"
#include "engine/vk/check.h"
#include "engine/vk/context.h"

namespace hp::vk {
namespace {
VkMemoryPropertyFlags requiredFlags(MemoryKind kind) {
  switch (kind) {
    case MemoryKind::DeviceLocal: return VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT;
    case MemoryKind::Upload: return VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT;
    case MemoryKind::Readback: return VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT;
  }
  return 0;
}
VkMemoryPropertyFlags preferredFlags(MemoryKind kind) {
  return kind == MemoryKind::Readback ? VK_MEMORY_PROPERTY_HOST_CACHED_BIT : 0;
}
}  // namespace

Buffer::Buffer(const Context& ctx, VkDeviceSize size, VkBufferUsageFlags usage, MemoryKind kind,
               const std::string& name)
    : device_(ctx.device()), fn_(&ctx.fn()), size_(size), name_(name) {
  if (size == 0) throw Error("buffer '" + name + "': size must be positive");
  VkBufferCreateInfo info{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO};
  info.size = size;
  info.usage = usage;
  info.sharingMode = VK_SHARING_MODE_EXCLUSIVE;
  HP_VK_CHECK(fn_->vkCreateBuffer(device_, &info, nullptr, &buffer_));
  try {
    ctx.setName(VK_OBJECT_TYPE_BUFFER, reinterpret_cast<std::uint64_t>(buffer_), name);
    const MemoryRequest request = ctx.memoryPool().bufferRequest(buffer_, requiredFlags(kind), preferredFlags(kind));
    ctx.checkDeviceMemoryBudget(request.requirements.size, "buffer '" + name + "'");
    pool_ = &ctx.memoryPool();
    memory_ = pool_->allocate(request);
    tally_ = ctx.allocationTally();
    allocated_ = request.requirements.size;
    *tally_ += std::int64_t(allocated_);
    HP_VK_CHECK(fn_->vkBindBufferMemory(device_, buffer_, memory_.memory, memory_.offset));
    if (kind != MemoryKind::DeviceLocal) mapped_ = memory_.mapped;
  } catch (...) {
    release();
    throw;
  }
}

Buffer::~Buffer() { release(); }

Buffer::Buffer(Buffer&& other) noexcept { *this = std::move(other); }

Buffer& Buffer::operator=(Buffer&& other) noexcept {
  if (this != &other) {
    release();
    device_ = std::exchange(other.device_, VK_NULL_HANDLE);
    fn_ = std::exchange(other.fn_, nullptr);
    buffer_ = std::exchange(other.buffer_, VK_NULL_HANDLE);
    pool_ = std::exchange(other.pool_, nullptr);
    memory_ = std::exchange(other.memory_, MemoryAllocation{});
    tally_ = std::move(other.tally_);
    allocated_ = std::exchange(other.allocated_, 0);
    size_ = std::exchange(other.size_, 0);
    mapped_ = std::exchange(other.mapped_, nullptr);
    name_ = std::move(other.name_);
  }
  return *this;
}

void Buffer::invalidate() const {
  if (!mapped_) return;
  VkMappedMemoryRange range{VK_STRUCTURE_TYPE_MAPPED_MEMORY_RANGE};
  range.memory = memory_.memory;  // the whole block: offsets would need nonCoherentAtomSize alignment
  range.size = VK_WHOLE_SIZE;
  HP_VK_CHECK(fn_->vkInvalidateMappedMemoryRanges(device_, 1, &range));
}

void Buffer::release() {
  if (buffer_) fn_->vkDestroyBuffer(device_, buffer_, nullptr);
  if (pool_) pool_->free(memory_);
  if (tally_) *tally_ -= std::int64_t(allocated_);
  tally_.reset();
  allocated_ = 0;
  buffer_ = VK_NULL_HANDLE;
  pool_ = nullptr;
  memory_ = {};
  mapped_ = nullptr;
}
}  // namespace hp::vk
