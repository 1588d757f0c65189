#pragma once
// Contract: the dynamic-rendering attachment description of a depth image in the DepthAttachment layout
// (engine/vk/barriers.h), cleared to 1 (the far plane) when `load` is CLEAR. One definition for every
// depth target hairpipe and its tools draw into (the head shadow map, the offscreen renderer).
#include <volk.h>

namespace hp::vk {
VkRenderingAttachmentInfo depthAttachment(VkImageView view, VkAttachmentLoadOp load, VkAttachmentStoreOp store);
}  // namespace hp::vk
