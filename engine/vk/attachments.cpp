#include "engine/vk/attachments.h"

#include "engine/vk/barriers.h"

namespace hp::vk {
VkRenderingAttachmentInfo depthAttachment(VkImageView view, VkAttachmentLoadOp load, VkAttachmentStoreOp store) {
  VkRenderingAttachmentInfo a{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
  a.imageView = view;
  a.imageLayout = imageLayout(ImageUse::DepthAttachment);
  a.loadOp = load;
  a.storeOp = store;
  a.clearValue.depthStencil = {1.0f, 0};
  return a;
}

VkRenderingAttachmentInfo colorAttachment(VkImageView view, VkAttachmentLoadOp load, VkClearColorValue clear) {
  VkRenderingAttachmentInfo a{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
  a.imageView = view;
  a.imageLayout = imageLayout(ImageUse::ColorAttachment);
  a.loadOp = load;
  a.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
  a.clearValue.color = clear;
  return a;
}
}  // namespace hp::vk
