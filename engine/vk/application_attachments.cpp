#include "engine/vk/application_attachments.h"

#include <bit>
#include <string>

#include "engine/core/error.h"
#include "engine/vk/context.h"
#include "engine/vk/image.h"

namespace hp::vk {
namespace {
std::string formatText(VkFormat format) { return "VkFormat " + std::to_string(int(format)); }
}  // namespace

void validateAttachmentFormats(const hairpipe::AttachmentFormats& formats) {
  const std::string field = "RendererSettings.formats.";
  if (formats.color == VK_FORMAT_UNDEFINED || isDepthFormat(formats.color))
    throw Error(field + "color must be a colour format, got " + formatText(formats.color));
  if (!isDepthFormat(formats.depth))
    throw Error(field + "depth must be a depth format (D16, D32, D16S8, D24S8 or D32S8), got " + formatText(formats.depth));
  if (formats.stencil != VK_FORMAT_UNDEFINED && !(formats.stencil == formats.depth && hasStencilComponent(formats.depth)))
    throw Error(field + "stencil must be VK_FORMAT_UNDEFINED (no stencil attachment) or the depth's own combined "
                "depth/stencil format, got " + formatText(formats.stencil) + " with depth " + formatText(formats.depth));
  const auto samples = std::uint32_t(formats.samples);
  if (samples == 0 || samples > 16 || !std::has_single_bit(samples))
    throw Error(field + "samples must be 1, 2, 4, 8 or 16, got " + std::to_string(samples));
  if (formats.otherColors.size() > kMaxOtherColors)
    throw Error(field + "otherColors holds at most " + std::to_string(kMaxOtherColors) + " formats, got " +
                std::to_string(formats.otherColors.size()));
  for (std::size_t i = 0; i < formats.otherColors.size(); ++i)
    if (isDepthFormat(formats.otherColors[i]))
      throw Error(field + "otherColors[" + std::to_string(i) + "] must be a colour format or VK_FORMAT_UNDEFINED, got " +
                  formatText(formats.otherColors[i]));
}

void requireAttachmentSupport(const Context& ctx, const hairpipe::AttachmentFormats& formats, bool sampledDepth) {
  const std::string device = ctx.properties().deviceName;
  auto features = [&](VkFormat format) {
    VkFormatProperties props{};
    vkGetPhysicalDeviceFormatProperties(ctx.physicalDevice(), format, &props);
    return props.optimalTilingFeatures;
  };
  constexpr VkFormatFeatureFlags kColor = VK_FORMAT_FEATURE_COLOR_ATTACHMENT_BIT | VK_FORMAT_FEATURE_COLOR_ATTACHMENT_BLEND_BIT;
  if ((features(formats.color) & kColor) != kColor)
    throw Error("RendererSettings.formats.color: " + formatText(formats.color) + " is not a blendable colour attachment on " + device);
  const VkFormatFeatureFlags depthNeeds =
      VK_FORMAT_FEATURE_DEPTH_STENCIL_ATTACHMENT_BIT | (sampledDepth ? VK_FORMAT_FEATURE_SAMPLED_IMAGE_BIT : 0);
  if ((features(formats.depth) & depthNeeds) != depthNeeds)
    throw Error("RendererSettings.formats.depth: " + formatText(formats.depth) + " is not a depth attachment" +
                (sampledDepth ? " the compute raster can sample" : "") + " on " + device);
  for (std::size_t i = 0; i < formats.otherColors.size(); ++i)
    if (formats.otherColors[i] != VK_FORMAT_UNDEFINED &&  // an unused slot
        (features(formats.otherColors[i]) & VK_FORMAT_FEATURE_COLOR_ATTACHMENT_BIT) == 0)
      throw Error("RendererSettings.formats.otherColors[" + std::to_string(i) + "]: " + formatText(formats.otherColors[i]) +
                  " is not a colour attachment on " + device);
  const VkPhysicalDeviceLimits& limits = ctx.properties().limits;
  if (1 + formats.otherColors.size() > limits.maxColorAttachments)
    throw Error("RendererSettings.formats.otherColors: " + std::to_string(1 + formats.otherColors.size()) +
                " colour attachments in all, more than the " + std::to_string(limits.maxColorAttachments) + " of " + device);
  if (!formats.otherColors.empty() && !ctx.independentBlend())
    throw Error("RendererSettings.formats.otherColors: the device's independentBlend feature is not enabled on " + device +
                " (hairpipe leaves the other attachments unwritten while it blends into the first)");
  const VkSampleCountFlags counts = limits.framebufferColorSampleCounts & limits.framebufferDepthSampleCounts &
                                    (formats.stencil != VK_FORMAT_UNDEFINED ? limits.framebufferStencilSampleCounts : ~0u) &
                                    (sampledDepth ? limits.sampledImageDepthSampleCounts : ~0u);
  if ((counts & formats.samples) == 0)
    throw Error("RendererSettings.formats.samples: " + std::to_string(int(formats.samples)) +
                " samples are not supported for colour and depth attachments" +
                (sampledDepth ? std::string(" and a sampled depth") : std::string()) + " on " + device);
}

void setApplicationAttachments(GraphicsPipelineDesc& desc, const hairpipe::AttachmentFormats& formats) {
  desc.colorFormats = {formats.color};
  desc.colorFormats.insert(desc.colorFormats.end(), formats.otherColors.begin(), formats.otherColors.end());
  desc.writtenColors = 1u;  // the first only: the others are the application's, untouched
  desc.depthFormat = formats.depth;
  desc.stencilFormat = formats.stencil;
  desc.depthCompare = formats.reversedDepth ? VK_COMPARE_OP_GREATER_OR_EQUAL : VK_COMPARE_OP_LESS_OR_EQUAL;
  desc.samples = formats.samples;
}
}  // namespace hp::vk
