#pragma once
// Contract: the dynamic-rendering attachment descriptions hairpipe and its tools draw into, one definition
// each: a depth image in the DepthAttachment layout, cleared to `clear` when `load` is CLEAR (1, the far
// plane: the head shadow map, the head bounce map, the offscreen renderer; 0 for a reversed-Z one); a colour image in the ColorAttachment
// layout, stored, cleared to `clear` when `load` is CLEAR (the opacity slices, the head bounce map, the
// offscreen renderer).
#include "hairpipe_volk.h"

namespace hp::vk {
VkRenderingAttachmentInfo depthAttachment(VkImageView view, VkAttachmentLoadOp load, VkAttachmentStoreOp store,
                                          float clear = 1.0f);
VkRenderingAttachmentInfo colorAttachment(VkImageView view, VkAttachmentLoadOp load, VkClearColorValue clear = {});
}  // namespace hp::vk
