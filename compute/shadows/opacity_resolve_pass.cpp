#include "compute/shadows/opacity_resolve_pass.h"

#include <string>

#include "engine/core/error.h"
#include "engine/vk/context.h"
#include "shaders/shared/opacity.h"

namespace hp::compute {
namespace {
const vk::Binding kOpacityResolveBindings[] = {
    {gpu::OPACITY_RESOLVE_BINDING_BINS, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, vk::kCompute},
    {gpu::OPACITY_RESOLVE_BINDING_MAPS, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, vk::kCompute},
    {gpu::OPACITY_RESOLVE_BINDING_FIRST, VK_DESCRIPTOR_TYPE_STORAGE_BUFFER, vk::kCompute},
};

VkDeviceSize checkedBinBytes(const vk::Context& ctx, std::uint32_t resolution, OpacityBins layout) {
  const VkDeviceSize bytes = OpacityResolvePass::binBytes(resolution, layout);
  const VkDeviceSize limit = ctx.properties().limits.maxStorageBufferRange;
  if (bytes > limit)
    throw Error("compute opacity maps: " + std::to_string(resolution) + "^2 texels' bins need " +
                std::to_string(bytes) + " bytes of bins, past the device's maxStorageBufferRange (" +
                std::to_string(limit) + " bytes); use a lower resolution, or the graphics or auto opacity raster");
  return bytes;
}

const char* resolveShader(VkFormat format) {
  if (format == VK_FORMAT_R32G32B32A32_SFLOAT) return "opacity_resolve_rgba32f.comp";
  if (format == VK_FORMAT_R16G16B16A16_SFLOAT) return "opacity_resolve_rgba16f.comp";
  throw Error("compute opacity maps: the format must be RGBA32F or RGBA16F");
}
}  // namespace

std::span<const std::uint32_t> splatModes(OpacityBins bins) {
  static constexpr std::uint32_t kGlobal[] = {gpu::OPACITY_SPLAT_MODE_PLAIN};
  static constexpr std::uint32_t kTwoSplats[] = {gpu::OPACITY_SPLAT_MODE_FIRST, gpu::OPACITY_SPLAT_MODE_DEEP};
  static constexpr std::uint32_t kFine[] = {gpu::OPACITY_SPLAT_MODE_DEEP_FINE};
  switch (bins) {
    case OpacityBins::Global: return kGlobal;
    case OpacityBins::DeepTwoSplats: return kTwoSplats;
    case OpacityBins::DeepFine: break;
  }
  return kFine;
}

VkDeviceSize OpacityResolvePass::binBytes(std::uint32_t resolution, OpacityBins layout) {
  const VkDeviceSize texels = VkDeviceSize(resolution) * resolution;
  if (layout != OpacityBins::DeepFine) return texels * gpu::OPACITY_SLICES * sizeof(std::uint32_t);
  // Whole groups of OPACITY_FINE_GROUP texels (gpu::opacityFineBin): the last may be partly past the map.
  const VkDeviceSize groups = (texels + gpu::OPACITY_FINE_GROUP - 1) / gpu::OPACITY_FINE_GROUP;
  return groups * gpu::OPACITY_FINE_GROUP * gpu::OPACITY_DEEP_BINS * sizeof(std::uint32_t);
}

bool OpacityResolvePass::fits(const vk::Context& ctx, std::uint32_t resolution, OpacityBins layout) {
  return binBytes(resolution, layout) <= ctx.properties().limits.maxStorageBufferRange;
}

OpacityBins OpacityResolvePass::binsFor(const vk::Context& ctx, std::uint32_t resolution, bool deep) {
  if (!deep) return OpacityBins::Global;
  return fits(ctx, resolution, OpacityBins::DeepFine) ? OpacityBins::DeepFine : OpacityBins::DeepTwoSplats;
}

OpacityResolvePass::OpacityResolvePass(const vk::Context& ctx, std::uint32_t resolution, VkFormat format,
                                       const std::vector<VkImageView>& slotMaps, OpacityBins layout,
                                       vk::PipelineLibrary* library)
    : ctx_(&ctx),
      resolution_(resolution),
      layout_(layout),
      bins_(ctx, checkedBinBytes(ctx, resolution, layout), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT,
            vk::MemoryKind::DeviceLocal, "opacity bins"),
      first_(ctx, VkDeviceSize(resolution) * resolution * sizeof(std::uint32_t),
             VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT, vk::MemoryKind::DeviceLocal,
             "opacity first hair") {
  for (std::size_t slot = 0; slot < slotMaps.size(); ++slot) {
    vk::DescriptorSet set(ctx, kOpacityResolveBindings, "opacity resolve [slot " + std::to_string(slot) + "]");
    set.writeStorageBuffer(gpu::OPACITY_RESOLVE_BINDING_BINS, bins_.handle());
    set.writeStorageImage(gpu::OPACITY_RESOLVE_BINDING_MAPS, slotMaps[slot]);
    set.writeStorageBuffer(gpu::OPACITY_RESOLVE_BINDING_FIRST, first_.handle());
    sets_.push_back(std::move(set));
  }
  pipeline_ = vk::makeComputePipeline(ctx, library, resolveShader(format), gpu::OPACITY_RESOLVE_WORKGROUP_SIZE,
                                      {sets_.at(0).layout()}, sizeof(gpu::OpacityResolvePush), "opacity resolve",
                                      {static_cast<std::uint32_t>(layout)});  // constant_id 0: the bins' layout
}

void OpacityResolvePass::recordClear(VkCommandBuffer cmd) const {
  ctx_->fn().vkCmdFillBuffer(cmd, bins_.handle(), 0, VK_WHOLE_SIZE, 0u);
  if (deep()) ctx_->fn().vkCmdFillBuffer(cmd, first_.handle(), 0, VK_WHOLE_SIZE, 0xFFFFFFFFu);  // no hair yet
}

void OpacityResolvePass::recordResolve(VkCommandBuffer cmd, std::uint32_t slot) const {
  const gpu::OpacityResolvePush push{resolution_, 0};
  pipeline_->bind(cmd, sets_.at(slot).set());
  pipeline_->push(cmd, push);
  pipeline_->dispatch(cmd, resolution_ * resolution_);
}
}  // namespace hp::compute
