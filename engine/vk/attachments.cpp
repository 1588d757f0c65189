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
}  // namespace hp::vk
