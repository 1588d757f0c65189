#pragma once
// Contract: what the draw passes render into: colour and depth formats and the sample count. Given
// by the embedding application (its own attachments) or by RenderTargets (hairpipe's offscreen ones).
#include "hairpipe_volk.h"

namespace hp::render {
struct AttachmentFormats {
  VkFormat color = VK_FORMAT_R16G16B16A16_SFLOAT;
  VkFormat depth = VK_FORMAT_D32_SFLOAT;
  VkSampleCountFlagBits samples = VK_SAMPLE_COUNT_4_BIT;
};
}  // namespace hp::render
