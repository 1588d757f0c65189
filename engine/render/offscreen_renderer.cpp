#include "engine/render/offscreen_renderer.h"

#include "engine/vk/barriers.h"
#include "engine/vk/transfer.h"

namespace hp::render {
namespace {
constexpr VkClearColorValue kBackground = {{0.018f, 0.02f, 0.024f, 1.0f}};

VkRenderingAttachmentInfo colorAttachment(VkImageView view, VkClearColorValue clear) {
  VkRenderingAttachmentInfo a{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
  a.imageView = view;
  a.imageLayout = vk::imageLayout(vk::ImageUse::ColorAttachment);
  a.loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
  a.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
  a.clearValue.color = clear;
  return a;
}

VkRenderingInfo renderingInfo(VkExtent2D extent, const VkRenderingAttachmentInfo* color,
                              const VkRenderingAttachmentInfo* depth) {
  VkRenderingInfo info{VK_STRUCTURE_TYPE_RENDERING_INFO};
  info.renderArea = {{0, 0}, extent};
  info.layerCount = 1;
  info.colorAttachmentCount = 1;
  info.pColorAttachments = color;
  info.pDepthAttachment = depth;
  return info;
}
}  // namespace

OffscreenRenderer::OffscreenRenderer(const vk::Context& ctx, std::uint32_t width, std::uint32_t height,
                                     std::uint32_t msaa)
    : ctx_(ctx), targets_(ctx, width, height, msaa), tonemap_(ctx, kDisplayFormat) {
  tonemap_.setInput(hdrInput().view());
}

AttachmentFormats OffscreenRenderer::formats() const { return {kHdrFormat, kDepthFormat, targets_.samples()}; }

void OffscreenRenderer::record(VkCommandBuffer cmd, HairSystem& hair, const DrawView& view, float exposure,
                               vk::GpuProfiler* profiler) const {
  record(cmd, [&](VkCommandBuffer c) { hair.recordDraw(c, view, profiler); }, exposure, profiler);
}

void OffscreenRenderer::record(VkCommandBuffer cmd, const std::function<void(VkCommandBuffer)>& draws,
                               float exposure, vk::GpuProfiler* profiler) const {
  recordScene(cmd, draws);
  if (profiler) profiler->begin(cmd, "tonemap");
  recordTonemap(cmd, exposure);
  if (profiler) profiler->end(cmd);
}

void OffscreenRenderer::recordScene(VkCommandBuffer cmd, const std::function<void(VkCommandBuffer)>& draws) const {
  const bool msaa = bool(targets_.resolved);
  // Earlier frames recorded into the same images: their writes (and, without MSAA, the tonemap's reads
  // of the HDR image) finish before the transitions discard the contents.
  vk::imageBarrier(cmd, targets_.hdr.handle(), VK_IMAGE_ASPECT_COLOR_BIT,
                   msaa ? vk::ImageUse::ColorAttachmentDiscard : vk::ImageUse::FragmentSampledDiscard,
                   vk::ImageUse::ColorAttachment);
  vk::imageBarrier(cmd, targets_.depth.handle(), VK_IMAGE_ASPECT_DEPTH_BIT, vk::ImageUse::DepthAttachmentDiscard,
                   vk::ImageUse::DepthAttachment);
  // The previous frame's tonemap may still sample the HDR input: wait for it before discarding it.
  if (msaa)
    vk::imageBarrier(cmd, targets_.resolved.handle(), VK_IMAGE_ASPECT_COLOR_BIT, vk::ImageUse::FragmentSampledDiscard,
                     vk::ImageUse::ColorAttachment);
  VkRenderingAttachmentInfo color = colorAttachment(targets_.hdr.view(), kBackground);
  if (msaa) {
    color.resolveMode = VK_RESOLVE_MODE_AVERAGE_BIT;
    color.resolveImageView = targets_.resolved.view();
    color.resolveImageLayout = vk::imageLayout(vk::ImageUse::ColorAttachment);
    color.storeOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;  // only the resolve is kept
  }
  VkRenderingAttachmentInfo depth{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
  depth.imageView = targets_.depth.view();
  depth.imageLayout = vk::imageLayout(vk::ImageUse::DepthAttachment);
  depth.loadOp = VK_ATTACHMENT_LOAD_OP_CLEAR;
  depth.storeOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;
  depth.clearValue.depthStencil = {1.0f, 0};
  VkRenderingInfo info = renderingInfo(extent(), &color, &depth);
  vkCmdBeginRendering(cmd, &info);
  draws(cmd);
  vkCmdEndRendering(cmd);
  vk::imageBarrier(cmd, hdrInput().handle(), VK_IMAGE_ASPECT_COLOR_BIT, vk::ImageUse::ColorAttachment,
                   vk::ImageUse::FragmentSampled);
}

void OffscreenRenderer::recordTonemap(VkCommandBuffer cmd, float exposure) const {
  vk::imageBarrier(cmd, targets_.display.handle(), VK_IMAGE_ASPECT_COLOR_BIT, vk::ImageUse::ColorAttachmentDiscard,
                   vk::ImageUse::ColorAttachment);
  VkRenderingAttachmentInfo color = colorAttachment(targets_.display.view(), {{0, 0, 0, 1}});
  VkRenderingInfo info = renderingInfo(extent(), &color, nullptr);
  vkCmdBeginRendering(cmd, &info);
  tonemap_.draw(cmd, extent(), exposure);
  vkCmdEndRendering(cmd);
}

std::vector<std::uint8_t> OffscreenRenderer::readDisplay() const {
  auto bytes = vk::readbackImage(ctx_, targets_.display, vk::ImageUse::ColorAttachment);
  std::vector<std::uint8_t> out(bytes.size());
  std::memcpy(out.data(), bytes.data(), bytes.size());
  return out;
}
}  // namespace hp::render
