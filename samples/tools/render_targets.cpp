#include "samples/tools/render_targets.h"

#include "engine/core/error.h"
#include "engine/vk/context.h"

namespace hp {
VkSampleCountFlagBits sampleCountFlag(std::uint32_t msaa) {
  switch (msaa) {
    case 1: return VK_SAMPLE_COUNT_1_BIT;
    case 2: return VK_SAMPLE_COUNT_2_BIT;
    case 4: return VK_SAMPLE_COUNT_4_BIT;
    case 8: return VK_SAMPLE_COUNT_8_BIT;
    default: throw Error("msaa must be 1, 2, 4 or 8 (got " + std::to_string(msaa) + ")");
  }
}

namespace {
void checkFits(const vk::Context& ctx, std::uint32_t width, std::uint32_t height, std::uint32_t msaa) {
  // HDR colour + depth per sample, resolve + display per pixel.
  const double bytes = double(width) * height * (msaa * (8.0 + 4.0) + (msaa > 1 ? 8.0 : 0.0) + 4.0);
  // Half the largest device-local heap: room is left for the hair's own buffers and everything else.
  const double budget = 0.5 * double(ctx.deviceLocalHeapBytes());
  if (bytes > budget)
    throw Error("render targets of " + std::to_string(width) + "x" + std::to_string(height) + " at msaa " +
                std::to_string(msaa) + " need " + std::to_string(std::uint64_t(bytes / (1 << 20))) +
                " MiB, more than half of this device's " + std::to_string(ctx.deviceLocalHeapBytes() >> 20) +
                " MiB device-local heap");
}
}  // namespace

RenderTargets::RenderTargets(const vk::Context& ctx, std::uint32_t width, std::uint32_t height, std::uint32_t msaa,
                             bool sampledDepth) {
  const VkSampleCountFlagBits samples = sampleCountFlag(msaa);
  checkFits(ctx, width, height, msaa);
  const auto& limits = ctx.properties().limits;
  if (!(limits.framebufferColorSampleCounts & samples) || !(limits.framebufferDepthSampleCounts & samples))
    throw Error("msaa " + std::to_string(msaa) + "x is not supported by this device");
  if (sampledDepth && !(limits.sampledImageDepthSampleCounts & samples))
    throw Error("msaa " + std::to_string(msaa) + "x: this device cannot sample a depth image of that many samples "
                "(the compute raster reads the head's depth); use a lower --msaa");
  // Transfer source: the linear HDR image is read back for frame exports (render --export-frame).
  const VkImageUsageFlags resolveUsage =
      VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT;
  hdr = vk::Image(ctx, {width, height, 1, kHdrFormat,
                        VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | (samples == VK_SAMPLE_COUNT_1_BIT ? resolveUsage : 0),
                        samples, "hdr colour"});
  const VkImageUsageFlags depthUsage =
      VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT | (sampledDepth ? VK_IMAGE_USAGE_SAMPLED_BIT : 0);
  depth = vk::Image(ctx, {width, height, 1, kDepthFormat, depthUsage, samples, "depth"});
  if (samples != VK_SAMPLE_COUNT_1_BIT)
    resolved = vk::Image(ctx, {width, height, 1, kHdrFormat, resolveUsage, VK_SAMPLE_COUNT_1_BIT, "hdr resolved"});
  display = vk::Image(ctx, {width, height, 1, kDisplayFormat,
                            VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT,
                            VK_SAMPLE_COUNT_1_BIT, "display"});
}
}  // namespace hp
