#include "engine/vk/buffer_view.h"

#include <utility>

#include "engine/core/error.h"
#include "engine/vk/buffer.h"
#include "engine/vk/check.h"
#include "engine/vk/context.h"

namespace hp::vk {
std::uint32_t texelBufferTexelBytes(VkFormat format) {
  switch (format) {
    case VK_FORMAT_R32G32_UINT: return 8;
    case VK_FORMAT_R32G32B32A32_SFLOAT: return 16;
    default: throw Error("texel buffer: format " + std::to_string(format) + " is not one hairpipe reads");
  }
}

bool texelBufferFits(const Context& ctx, std::uint64_t elements) {
  return elements <= ctx.properties().limits.maxTexelBufferElements;
}

BufferView::BufferView(const Context& ctx, const Buffer& buffer, VkFormat format, const std::string& name)
    : device_(ctx.device()), fn_(&ctx.fn()) {
  const std::uint64_t elements = buffer.size() / texelBufferTexelBytes(format);
  if (!texelBufferFits(ctx, elements))
    throw Error("texel buffer " + name + ": " + std::to_string(elements) + " texels, more than the device's " +
                "maxTexelBufferElements (" + std::to_string(ctx.properties().limits.maxTexelBufferElements) + ")");
  VkBufferViewCreateInfo info{VK_STRUCTURE_TYPE_BUFFER_VIEW_CREATE_INFO};
  info.buffer = buffer.handle();
  info.format = format;
  info.offset = 0;
  info.range = elements * texelBufferTexelBytes(format);
  HP_VK_CHECK(fn_->vkCreateBufferView(device_, &info, nullptr, &view_));
  try {
    ctx.setName(VK_OBJECT_TYPE_BUFFER_VIEW, reinterpret_cast<std::uint64_t>(view_), name);
  } catch (...) {
    fn_->vkDestroyBufferView(device_, view_, nullptr);
    throw;
  }
}

BufferView::~BufferView() {
  if (view_) fn_->vkDestroyBufferView(device_, view_, nullptr);
}

BufferView::BufferView(BufferView&& other) noexcept { *this = std::move(other); }

BufferView& BufferView::operator=(BufferView&& other) noexcept {
  if (this != &other) {
    if (view_) fn_->vkDestroyBufferView(device_, view_, nullptr);
    device_ = std::exchange(other.device_, VK_NULL_HANDLE);
    fn_ = std::exchange(other.fn_, nullptr);
    view_ = std::exchange(other.view_, VK_NULL_HANDLE);
  }
  return *this;
}
}  // namespace hp::vk
