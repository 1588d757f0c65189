#include "engine/vk/transfer.h"

#include "engine/core/error.h"
#include "engine/vk/context.h"
#include "engine/vk/submit.h"

namespace hp::vk {
void uploadBytes(const Context& ctx, const Buffer& dst, const void* data, VkDeviceSize size, BufferUse after,
                 VkDeviceSize dstOffset) {
  if (size == 0) return;
  // Written as subtractions: offset + size could wrap past the check.
  if (dstOffset > dst.size() || size > dst.size() - dstOffset)
    throw Error("upload of " + std::to_string(size) + " bytes overruns buffer '" + dst.name() + "'");
  Buffer staging(ctx, size, VK_BUFFER_USAGE_TRANSFER_SRC_BIT, MemoryKind::Upload, dst.name() + " staging");
  std::memcpy(staging.mapped(), data, size);
  submitAndWait(ctx, [&](VkCommandBuffer cmd) {
    VkBufferCopy region{0, dstOffset, size};
    ctx.fn().vkCmdCopyBuffer(cmd, staging.handle(), dst.handle(), 1, &region);
    bufferBarrier(ctx, cmd, dst.handle(), BufferUse::TransferDst, after);
  }, "upload " + dst.name());
  keepUntilSubmitted(ctx, std::move(staging));
}

std::vector<std::byte> readbackBytes(const Context& ctx, const Buffer& src, BufferUse before, VkDeviceSize offset,
                                     VkDeviceSize size) {
  if (offset > src.size()) throw Error("readback offset " + std::to_string(offset) + " is past buffer '" + src.name() + "'");
  if (size == VK_WHOLE_SIZE) size = src.size() - offset;
  if (size > src.size() - offset)
    throw Error("readback of " + std::to_string(size) + " bytes overruns buffer '" + src.name() + "'");
  std::vector<std::byte> out(size);
  if (size == 0) return out;
  Buffer staging(ctx, size, VK_BUFFER_USAGE_TRANSFER_DST_BIT, MemoryKind::Readback, src.name() + " readback");
  submitAndWait(ctx, [&](VkCommandBuffer cmd) {
    bufferBarrier(ctx, cmd, src.handle(), before, BufferUse::TransferSrc);
    VkBufferCopy region{offset, 0, size};
    ctx.fn().vkCmdCopyBuffer(cmd, src.handle(), staging.handle(), 1, &region);
    bufferBarrier(ctx, cmd, staging.handle(), BufferUse::TransferDst, BufferUse::HostRead);
  }, "readback " + src.name());
  submitOpenBatch(ctx);
  staging.invalidate();
  std::memcpy(out.data(), staging.mapped(), size);
  return out;
}

namespace {
VkBufferImageCopy layerRegion(const Image& image, std::uint32_t layer, std::uint32_t layerCount) {
  VkBufferImageCopy region{};
  region.imageSubresource = {image.aspect(), 0, layer, layerCount};
  region.imageExtent = {image.desc().width, image.desc().height, 1};
  return region;
}
VkDeviceSize layerBytes(const Image& image) {
  return VkDeviceSize(image.desc().width) * image.desc().height * formatBytesPerPixel(image.desc().format);
}
}  // namespace

void uploadImage(const Context& ctx, const Image& image, std::span<const std::byte> texels, ImageUse after) {
  const VkDeviceSize expected = layerBytes(image) * image.desc().layers;
  if (texels.size() != expected)
    throw Error("image upload to '" + image.desc().name + "': got " + std::to_string(texels.size()) +
                " bytes, expected " + std::to_string(expected));
  Buffer staging(ctx, expected, VK_BUFFER_USAGE_TRANSFER_SRC_BIT, MemoryKind::Upload, image.desc().name + " staging");
  std::memcpy(staging.mapped(), texels.data(), expected);
  submitAndWait(ctx, [&](VkCommandBuffer cmd) {
    const std::uint32_t layers = image.desc().layers;
    imageBarrier(ctx, cmd, image.handle(), image.aspect(), ImageUse::Undefined, ImageUse::TransferDst, layers);
    VkBufferImageCopy region = layerRegion(image, 0, layers);
    ctx.fn().vkCmdCopyBufferToImage(cmd, staging.handle(), image.handle(), VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region);
    imageBarrier(ctx, cmd, image.handle(), image.aspect(), ImageUse::TransferDst, after, layers);
  }, "upload " + image.desc().name);
  keepUntilSubmitted(ctx, std::move(staging));
}

std::vector<std::byte> readbackImage(const Context& ctx, const Image& image, ImageUse current, std::uint32_t layer) {
  if (image.desc().samples != VK_SAMPLE_COUNT_1_BIT)
    throw Error("readbackImage: '" + image.desc().name + "' is multisampled; resolve it first");
  if (layer >= image.desc().layers)
    throw Error("readbackImage: '" + image.desc().name + "' has no layer " + std::to_string(layer));
  const VkDeviceSize bytes = layerBytes(image);
  Buffer staging(ctx, bytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT, MemoryKind::Readback, image.desc().name + " readback");
  submitAndWait(ctx, [&](VkCommandBuffer cmd) {
    const std::uint32_t layers = image.desc().layers;
    imageBarrier(ctx, cmd, image.handle(), image.aspect(), current, ImageUse::TransferSrc, layers);
    VkBufferImageCopy region = layerRegion(image, layer, 1);
    ctx.fn().vkCmdCopyImageToBuffer(cmd, image.handle(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, staging.handle(), 1, &region);
    bufferBarrier(ctx, cmd, staging.handle(), BufferUse::TransferDst, BufferUse::HostRead);
    if (current != ImageUse::Undefined)
      imageBarrier(ctx, cmd, image.handle(), image.aspect(), ImageUse::TransferSrc, current, layers);
  }, "readback " + image.desc().name);
  submitOpenBatch(ctx);
  staging.invalidate();
  std::vector<std::byte> out(bytes);
  std::memcpy(out.data(), staging.mapped(), bytes);
  return out;
}
}  // namespace hp::vk
