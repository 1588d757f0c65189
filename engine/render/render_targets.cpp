#include "engine/render/render_targets.h"

#include "engine/error.h"
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

RenderTargets::RenderTargets(const vk::Context& ctx, std::uint32_t width, std::uint32_t height, std::uint32_t msaa) {
  const VkSampleCountFlagBits samples = sampleCountFlag(msaa);
  const auto& limits = ctx.properties().limits;
  if (!(limits.framebufferColorSampleCounts & samples) || !(limits.framebufferDepthSampleCounts & samples))
    throw Error("msaa " + std::to_string(msaa) + "x is not supported by this device");
  const VkImageUsageFlags resolveUsage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT;
  hdr = vk::Image(ctx, {width, height, 1, kHdrFormat,
                        VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | (samples == VK_SAMPLE_COUNT_1_BIT ? resolveUsage : 0),
                        samples, "hdr colour"});
  depth = vk::Image(ctx, {width, height, 1, kDepthFormat, VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT, samples, "depth"});
  if (samples != VK_SAMPLE_COUNT_1_BIT)
    resolved = vk::Image(ctx, {width, height, 1, kHdrFormat, resolveUsage, VK_SAMPLE_COUNT_1_BIT, "hdr resolved"});
  display = vk::Image(ctx, {width, height, 1, kDisplayFormat,
                            VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT,
                            VK_SAMPLE_COUNT_1_BIT, "display"});
}
}  // namespace hp
