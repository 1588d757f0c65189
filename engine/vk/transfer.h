#pragma once
// Contract: blocking host<->device copies through staging buffers, for set-up and readback outside the
// frame loop. Each call records its own barriers: the data is ready for `after` when an upload returns,
// and a readback first waits for the `before` use (the last GPU use of the resource) to finish.
#include <cstring>
#include <span>
#include <string>
#include <vector>

#include "engine/vk/barriers.h"
#include "engine/vk/buffer.h"
#include "engine/vk/image.h"

namespace hp::vk {
class Context;

void uploadBytes(const Context& ctx, const Buffer& dst, const void* data, VkDeviceSize size, BufferUse after,
                 VkDeviceSize dstOffset = 0);
std::vector<std::byte> readbackBytes(const Context& ctx, const Buffer& src, BufferUse before, VkDeviceSize offset = 0,
                                     VkDeviceSize size = VK_WHOLE_SIZE);

template <class T>
void upload(const Context& ctx, const Buffer& dst, std::span<const T> data, BufferUse after) {
  uploadBytes(ctx, dst, data.data(), data.size_bytes(), after);
}

template <class T>
std::vector<T> readback(const Context& ctx, const Buffer& src, BufferUse before, std::size_t count) {
  std::vector<std::byte> bytes = readbackBytes(ctx, src, before, 0, count * sizeof(T));
  std::vector<T> out(count);
  std::memcpy(out.data(), bytes.data(), bytes.size());
  return out;
}

// Fills all layers of a single-sample image from tightly packed texels (layer after layer) and leaves it in `after`.
void uploadImage(const Context& ctx, const Image& image, std::span<const std::byte> texels, ImageUse after);
// Reads one layer of a single-sample image, tightly packed; the image is returned to `current` afterwards.
std::vector<std::byte> readbackImage(const Context& ctx, const Image& image, ImageUse current, std::uint32_t layer = 0);
}  // namespace hp::vk
