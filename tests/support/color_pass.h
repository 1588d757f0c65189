#pragma once
// Contract: the tests' one-attachment dynamic rendering: begins rendering into a colour image (already in
// ImageUse::ColorAttachment) cleared to `clear` over its whole extent; the caller draws and ends it.
#include "engine/vk/barriers.h"
#include "engine/vk/context.h"

namespace hp::test {
inline void beginClearedColorPass(const vk::Context& ctx, VkCommandBuffer cmd, VkImageView view, VkExtent2D extent,
                                  VkClearColorValue clear) {
  VkRenderingAttachmentInfo color{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
  color.imageView = view;
  color.imageLayout = vk::imageLayout(vk::ImageUse::ColorAttachment);
  color.loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
  color.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
  color.clearValue.color = clear;
  VkRenderingInfo info{VK_STRUCTURE_TYPE_RENDERING_INFO};
  info.renderArea = {{0, 0}, extent};
  info.layerCount = 1;
  info.colorAttachmentCount = 1;
  info.pColorAttachments = &color;
  ctx.fn().vkCmdBeginRendering(cmd, &info);
}
}  // namespace hp::test
