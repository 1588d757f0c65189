#include "compute/shadows/shadow_maps.h"

#include <string>
#include <vector>

#include "compute/shadows/bounds_pass.h"
#include "engine/core/error.h"
#include "engine/vk/attachments.h"
#include "engine/vk/barriers.h"
#include "engine/vk/context.h"
#include "engine/vk/submit.h"
#include "shaders/shared/opacity.h"

namespace hp::render {
namespace {
const OpacitySettings& validated(const OpacitySettings& s) {
  validate(s);
  return s;
}

bool onCompute(const vk::Context& ctx, const OpacitySettings& s) {
  if (s.raster == OpacityRaster::Auto) return compute::OpacityResolvePass::fits(ctx, s.resolution);
  return s.raster == OpacityRaster::Compute;
}

std::uint32_t validatedSlots(std::uint32_t slots) {
  if (slots == 0 || slots > gpu::OPACITY_MAX_LIGHTS)
    throw Error("shadow maps: " + std::to_string(slots) + " shadowed lights asked for, 1 to " +
                std::to_string(gpu::OPACITY_MAX_LIGHTS) + " supported");
  return slots;
}

vk::Image makeShadowMapImage(const vk::Context& ctx, const OpacitySettings& settings, std::uint32_t slots) {
  vk::ImageDesc desc;
  desc.width = desc.height = settings.resolution;
  desc.layers = gpu::OPACITY_LAYERS * slots;
  desc.groupLayers = gpu::OPACITY_LAYERS;  // a view per slot: the compute resolve writes one slot's layers
  desc.format = settings.format;
  desc.usage = VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT |
               VK_IMAGE_USAGE_TRANSFER_DST_BIT;
  if (onCompute(ctx, settings)) desc.usage |= VK_IMAGE_USAGE_STORAGE_BIT;
  desc.name = "opacity maps";
  return vk::Image(ctx, desc);
}

vk::Image makeHeadImage(const vk::Context& ctx, const OpacitySettings& settings, std::uint32_t slots) {
  vk::ImageDesc desc;
  desc.width = desc.height = settings.headShadowResolution;
  desc.layers = slots;
  desc.arrayView = true;  // the shaders declare a sampler2DArrayShadow
  desc.format = ShadowMaps::kHeadDepthFormat;
  desc.usage = VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT | VK_IMAGE_USAGE_SAMPLED_BIT;
  desc.name = "head shadow map";
  return vk::Image(ctx, desc);
}

}  // namespace

ShadowMaps::ShadowMaps(const vk::Context& ctx, const OpacitySettings& settings, vk::PipelineLibrary* library,
                       std::uint32_t slots, DeepSplats deepSplats)
    : ctx_(&ctx),
      settings_(validated(settings)),
      slots_(validatedSlots(slots)),
      lightSpace_(ctx, sizeof(gpu::LightSpace) * slots,
                  VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT | VK_BUFFER_USAGE_TRANSFER_SRC_BIT,
                  vk::MemoryKind::DeviceLocal, "light space"),
      image_(makeShadowMapImage(ctx, settings_, slots)),
      sampler_(ctx, "opacity sampler"),
      headImage_(makeHeadImage(ctx, settings_, slots)),
      headSampler_(ctx, "head shadow sampler", VK_COMPARE_OP_LESS_OR_EQUAL),
      bounce_(ctx) {
  if (onCompute(ctx, settings_)) {
    std::vector<VkImageView> slotViews;
    for (std::uint32_t slot = 0; slot < slots_; ++slot) slotViews.push_back(image_.groupView(slot));
    const compute::OpacityBins bins = deepSplats == DeepSplats::Two && settings_.deep
                                          ? compute::OpacityBins::DeepTwoSplats
                                          : compute::OpacityResolvePass::binsFor(ctx, settings_.resolution, settings_.deep);
    resolve_ = std::make_unique<compute::OpacityResolvePass>(ctx, settings_.resolution, settings_.format, slotViews,
                                                             bins, library);
  }
  settings_.deep = settings_.deep && resolve_ != nullptr;  // the graphics path draws global slices
  const std::vector<gpu::LightSpace> initial(slots_, compute::initialLightSpace());
  const std::uint32_t layers = gpu::OPACITY_LAYERS * slots_;
  vk::submitAndWait(ctx, [&](VkCommandBuffer cmd) {
    ctx.fn().vkCmdUpdateBuffer(cmd, lightSpace_.handle(), 0, initial.size() * sizeof(gpu::LightSpace), initial.data());
    vk::bufferBarrier(ctx, cmd, lightSpace_.handle(), vk::BufferUse::TransferDst, vk::BufferUse::GraphicsRead);
    vk::imageBarrier(ctx, cmd, image_.handle(), VK_IMAGE_ASPECT_COLOR_BIT, vk::ImageUse::Undefined,
                     vk::ImageUse::TransferDst, layers);
    const VkClearColorValue zero{{0.0f, 0.0f, 0.0f, 0.0f}};
    const VkImageSubresourceRange range{VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, layers};
    ctx.fn().vkCmdClearColorImage(cmd, image_.handle(), vk::imageLayout(vk::ImageUse::TransferDst), &zero, 1, &range);
    vk::imageBarrier(ctx, cmd, image_.handle(), VK_IMAGE_ASPECT_COLOR_BIT, vk::ImageUse::TransferDst,
                     vk::ImageUse::FragmentSampled, layers);
    vk::imageBarrier(ctx, cmd, headImage_.handle(), VK_IMAGE_ASPECT_DEPTH_BIT, vk::ImageUse::Undefined,
                     vk::ImageUse::DepthAttachment, slots_);
    for (std::uint32_t slot = 0; slot < slots_; ++slot) {
      beginHeadRendering(cmd, slot);
      endRendering(cmd);
    }
    vk::imageBarrier(ctx, cmd, headImage_.handle(), VK_IMAGE_ASPECT_DEPTH_BIT, vk::ImageUse::DepthAttachment,
                     vk::ImageUse::FragmentSampled, slots_);
  }, "clear opacity maps");
}

void ShadowMaps::beginRendering(VkCommandBuffer cmd, std::uint32_t slot, bool keep) const {
  VkRenderingAttachmentInfo attachments[gpu::OPACITY_TARGETS];
  for (std::uint32_t t = 0; t < gpu::OPACITY_TARGETS; ++t)
    attachments[t] = vk::colorAttachment(image_.layerView(slot * gpu::OPACITY_LAYERS + t), keep ? VK_ATTACHMENT_LOAD_OP_LOAD : VK_ATTACHMENT_LOAD_OP_CLEAR);
  VkRenderingInfo info{VK_STRUCTURE_TYPE_RENDERING_INFO};
  info.renderArea = {{0, 0}, image_.extent()};
  info.layerCount = 1;
  info.colorAttachmentCount = gpu::OPACITY_TARGETS;
  info.pColorAttachments = attachments;
  ctx_->fn().vkCmdBeginRendering(cmd, &info);
}

void ShadowMaps::endRendering(VkCommandBuffer cmd) const { ctx_->fn().vkCmdEndRendering(cmd); }

void ShadowMaps::beginHeadRendering(VkCommandBuffer cmd, std::uint32_t slot) const {
  VkRenderingAttachmentInfo depth =
      vk::depthAttachment(headImage_.layerView(slot), VK_ATTACHMENT_LOAD_OP_CLEAR, VK_ATTACHMENT_STORE_OP_STORE);
  VkRenderingInfo info{VK_STRUCTURE_TYPE_RENDERING_INFO};
  info.renderArea = {{0, 0}, headImage_.extent()};
  info.layerCount = 1;
  info.pDepthAttachment = &depth;
  ctx_->fn().vkCmdBeginRendering(cmd, &info);
}
}  // namespace hp::render
