#include "compute/shadows/head_bounce_map.h"

#include "engine/vk/attachments.h"
#include "engine/vk/barriers.h"
#include "engine/vk/context.h"
#include "engine/vk/submit.h"
#include "shaders/shared/render.h"

namespace hp::render {
namespace {
vk::Image makeBounceMapImage(const vk::Context& ctx, VkFormat format, VkImageUsageFlags usage, const char* name) {
  vk::ImageDesc desc;
  desc.width = desc.height = gpu::RENDER_BOUNCE_RESOLUTION;
  desc.format = format;
  desc.usage = usage;
  desc.name = name;
  return vk::Image(ctx, desc);
}

constexpr VkImageUsageFlags kColorUsage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT;
}  // namespace

HeadBounceMap::HeadBounceMap(const vk::Context& ctx)
    : ctx_(&ctx),
      flux_(makeBounceMapImage(ctx, kFormat, kColorUsage, "head bounce flux")),
      position_(makeBounceMapImage(ctx, kFormat, kColorUsage, "head bounce position")),
      depth_(makeBounceMapImage(ctx, kDepthFormat, VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT, "head bounce depth")),
      sampler_(ctx, "head bounce sampler", VK_FILTER_NEAREST) {
  vk::submitAndWait(ctx, [&](VkCommandBuffer cmd) {
    transition(cmd, vk::ImageUse::Undefined, vk::ImageUse::FragmentSampled);
    vk::imageBarrier(ctx, cmd, depth_.handle(), VK_IMAGE_ASPECT_DEPTH_BIT, vk::ImageUse::Undefined,
                     vk::ImageUse::DepthAttachment);
    begin(cmd);  // clears: no skin until a frame draws it
    end(cmd);
  }, "clear head bounce map");
}

void HeadBounceMap::transition(VkCommandBuffer cmd, vk::ImageUse from, vk::ImageUse to) const {
  for (VkImage image : {flux_.handle(), position_.handle()})
    vk::imageBarrier(*ctx_, cmd, image, VK_IMAGE_ASPECT_COLOR_BIT, from, to);
}

void HeadBounceMap::begin(VkCommandBuffer cmd) const {
  transition(cmd, vk::ImageUse::FragmentSampled, vk::ImageUse::ColorAttachment);
  // The last draw's depth writes finish before this one's clear.
  vk::imageBarrier(*ctx_, cmd, depth_.handle(), VK_IMAGE_ASPECT_DEPTH_BIT, vk::ImageUse::DepthAttachmentDiscard,
                   vk::ImageUse::DepthAttachment);
  const VkRenderingAttachmentInfo colors[] = {vk::colorAttachment(flux_.view(), VK_ATTACHMENT_LOAD_OP_CLEAR),
                                              vk::colorAttachment(position_.view(), VK_ATTACHMENT_LOAD_OP_CLEAR)};
  const VkRenderingAttachmentInfo depth =
      vk::depthAttachment(depth_.view(), VK_ATTACHMENT_LOAD_OP_CLEAR, VK_ATTACHMENT_STORE_OP_DONT_CARE);
  VkRenderingInfo info{VK_STRUCTURE_TYPE_RENDERING_INFO};
  info.renderArea = {{0, 0}, flux_.extent()};
  info.layerCount = 1;
  info.colorAttachmentCount = 2;
  info.pColorAttachments = colors;
  info.pDepthAttachment = &depth;
  ctx_->fn().vkCmdBeginRendering(cmd, &info);
}

void HeadBounceMap::end(VkCommandBuffer cmd) const {
  ctx_->fn().vkCmdEndRendering(cmd);
  transition(cmd, vk::ImageUse::ColorAttachment, vk::ImageUse::FragmentSampled);
}
}  // namespace hp::render
