#pragma once
// Contract: a VkBufferView over a whole Buffer (uniform texel buffer reads), move-only, named, destroyed with
// its owner; the buffer outlives it, and the caller guarantees the GPU no longer reads it when it goes.
// The element count floor(size / texel size) must be within the device's maxTexelBufferElements
// (texelBufferFits says beforehand; the constructor throws an Error naming the buffer otherwise).
#include "hairpipe_volk.h"

#include <cstdint>

#include <string>

namespace hp::vk {
class Buffer;
class Context;

// Bytes per texel of the formats hairpipe reads through texel buffers (R32G32_UINT, R32G32B32A32_SFLOAT).
std::uint32_t texelBufferTexelBytes(VkFormat format);
// Whether `elements` texels fit one texel buffer view on this device.
bool texelBufferFits(const Context& ctx, std::uint64_t elements);

class BufferView {
 public:
  BufferView() = default;
  BufferView(const Context& ctx, const Buffer& buffer, VkFormat format, const std::string& name);
  ~BufferView();
  BufferView(BufferView&& other) noexcept;
  BufferView& operator=(BufferView&& other) noexcept;
  BufferView(const BufferView&) = delete;
  BufferView& operator=(const BufferView&) = delete;
  VkBufferView handle() const { return view_; }
  explicit operator bool() const { return view_ != VK_NULL_HANDLE; }

 private:
  VkDevice device_ = VK_NULL_HANDLE;
  const VolkDeviceTable* fn_ = nullptr;  // the Context's device functions
  VkBufferView view_ = VK_NULL_HANDLE;
};
}  // namespace hp::vk
