#include "engine/vk/attachments.h"

#include "engine/vk/barriers.h"

namespace hp::vk {
namespace {
VkRenderingAttachmentInfo attachment(VkImageView view, ImageUse use, VkAttachmentLoadOp load, VkAttachmentStoreOp store) {
  VkRenderingAttachmentInfo a{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
  a.imageView = view;
  a.imageLayout = imageLayout(use);
  a.loadOp = load;
  a.storeOp = store;
  return a;
}
}  // namespace

VkRenderingAttachmentInfo depthAttachment(VkImageView view, VkAttachmentLoadOp load, VkAttachmentStoreOp store,
                                          float clear) {
  VkRenderingAttachmentInfo a = attachment(view, ImageUse::DepthAttachment, load, store);
  a.clearValue.depthStencil = {clear, 0};
  return a;
}

VkRenderingAttachmentInfo colorAttachment(VkImageView view, VkAttachmentLoadOp load, VkClearColorValue clear) {
  VkRenderingAttachmentInfo a = attachment(view, ImageUse::ColorAttachment, load, VK_ATTACHMENT_STORE_OP_STORE);
  a.clearValue.color = clear;
  return a;
}
}  // namespace hp::vk
