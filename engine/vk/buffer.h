#pragma once
// Contract: a VkBuffer and its memory (sub-allocated from the Context's MemoryPool), move-only, destroyed
// with its owner. The caller
// guarantees the GPU no longer uses it when it is destroyed (frame owners wait on their fences).
// Host-visible kinds are persistently mapped; `mapped()` is null for device-local memory.
#include "hairpipe_volk.h"

#include <cstdint>

#include <atomic>
#include <memory>
#include <string>

#include "engine/vk/memory_pool.h"

namespace hp::vk {
class Context;

enum class MemoryKind {
  DeviceLocal,  // GPU-only; filled by transfers or shaders
  Upload,       // host-visible, coherent: staging and per-frame constants written by the host
  Readback,     // host-visible, cached where possible: results the host reads
};

class Buffer {
 public:
  Buffer() = default;
  Buffer(const Context& ctx, VkDeviceSize size, VkBufferUsageFlags usage, MemoryKind kind, const std::string& name);
  ~Buffer();
  Buffer(Buffer&& other) noexcept;
  Buffer& operator=(Buffer&& other) noexcept;
  Buffer(const Buffer&) = delete;
  Buffer& operator=(const Buffer&) = delete;

  VkBuffer handle() const { return buffer_; }
  VkDeviceSize size() const { return size_; }
  void* mapped() const { return mapped_; }
  const MemoryAllocation& allocation() const { return memory_; }  // where in the pool's memory it is bound
  const std::string& name() const { return name_; }
  explicit operator bool() const { return buffer_ != VK_NULL_HANDLE; }
  // For host-visible buffers whose memory might not be coherent (Readback): make GPU writes visible.
  void invalidate() const;

 private:
  void release();
  VkDevice device_ = VK_NULL_HANDLE;
  const VolkDeviceTable* fn_ = nullptr;  // the Context's device functions
  VkBuffer buffer_ = VK_NULL_HANDLE;
  MemoryPool* pool_ = nullptr;
  MemoryAllocation memory_;
  std::shared_ptr<std::atomic<std::int64_t>> tally_;  // Context::allocatedBytes
  VkDeviceSize allocated_ = 0;
  VkDeviceSize size_ = 0;
  void* mapped_ = nullptr;
  std::string name_;
};
}  // namespace hp::vk
