#pragma once
// Contract: the offscreen images hairpipe's own renderer draws into (the CLI, tests, benchmarks):
// a multisampled HDR colour + depth pair, the single-sample HDR resolve, and the 8-bit sRGB image the
// tonemap pass writes and the host reads back. An embedding application uses its own attachments.
#include <glm/glm.hpp>

#include "engine/vk/image.h"

namespace hp {
inline constexpr VkFormat kHdrFormat = VK_FORMAT_R16G16B16A16_SFLOAT;
inline constexpr VkFormat kDepthFormat = VK_FORMAT_D32_SFLOAT;
inline constexpr VkFormat kDisplayFormat = VK_FORMAT_R8G8B8A8_SRGB;
// The linear radiance the HDR image is cleared to: where nothing is drawn (frame exports carry it).
inline constexpr glm::vec3 kBackgroundRadiance{0.018f, 0.02f, 0.024f};

struct RenderTargets {
  // Throws hp::Error for a size past the device's limits or an unsupported sample count. With
  // sampledDepth the depth image can also be sampled (the compute rasterizer reads the head's depth).
  RenderTargets(const vk::Context& ctx, std::uint32_t width, std::uint32_t height, std::uint32_t msaa,
                bool sampledDepth = false);

  VkExtent2D extent() const { return display.extent(); }
  VkSampleCountFlagBits samples() const { return hdr.desc().samples; }
  vk::Image hdr;       // multisampled (or not, for msaa 1), colour attachment
  vk::Image depth;     // same sample count
  vk::Image resolved;  // single-sample HDR, resolve target and tonemap input (when msaa > 1)
  vk::Image display;   // sRGB, tonemap output, read back
};

VkSampleCountFlagBits sampleCountFlag(std::uint32_t msaa);
}  // namespace hp
