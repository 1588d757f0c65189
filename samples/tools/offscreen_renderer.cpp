#include "samples/tools/offscreen_renderer.h"

#include <cstring>
#include <string>

#include "engine/core/error.h"
#include "engine/core/shading/half_float.h"
#include "engine/vk/attachments.h"
#include "engine/vk/barriers.h"
#include "engine/vk/context.h"
#include "engine/vk/transfer.h"

namespace hp::render {
namespace {
constexpr VkClearColorValue kBackground = {{kBackgroundRadiance.x, kBackgroundRadiance.y, kBackgroundRadiance.z, 1.0f}};


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
                                     std::uint32_t msaa, RasterMode raster, bool reversedDepth)
    : ctx_(ctx),
      raster_(raster),
      reversedDepth_(reversedDepth),
      targets_(ctx, width, height, msaa, raster == RasterMode::Compute),
      tonemap_(ctx, kDisplayFormat) {
  if (raster == RasterMode::Auto) throw Error("OffscreenRenderer: resolve RasterMode::Auto first (resolveRasterMode)");
  tonemap_.setInput(hdrInput().view());
}

void OffscreenRenderer::attach(HairSystem& hair) const {
  if (hair.raster() != raster_) throw Error("OffscreenRenderer: the hair system's raster mode differs from the renderer's");
  if (raster_ == RasterMode::Compute) hair.setRasterTarget(extent(), targets_.depth.view());
}

void OffscreenRenderer::requireCompute(const Renderer& renderer, const char* call) const {
  if (raster_ != RasterMode::Compute || renderer.raster() != RasterMode::Compute)
    throw Error(std::string("OffscreenRenderer::") + call + ": the renderer and this target must both use the compute raster");
}

void OffscreenRenderer::attach(Renderer& renderer, std::span<HairInstance* const> instances) const {
  requireCompute(renderer, "attach");
  renderer.setRasterTarget(extent(), targets_.depth.view(), instances);
}

std::shared_ptr<RasterTarget> OffscreenRenderer::createTarget(Renderer& renderer,
                                                             std::span<HairInstance* const> instances) const {
  requireCompute(renderer, "createTarget");
  return renderer.createRasterTarget(extent(), targets_.depth.view(), instances);
}

hairpipe::AttachmentFormats OffscreenRenderer::formats() const {
  hairpipe::AttachmentFormats f{kHdrFormat, kDepthFormat, targets_.samples()};
  f.reversedDepth = reversedDepth_;
  return f;
}

VkRenderingAttachmentInfo OffscreenRenderer::sceneDepth(VkAttachmentLoadOp load, VkAttachmentStoreOp store) const {
  return vk::depthAttachment(targets_.depth.view(), load, store, reversedDepth_ ? 0.0f : 1.0f);
}

void OffscreenRenderer::record(VkCommandBuffer cmd, HairSystem& hair, const DrawView& view, float exposure,
                               vk::GpuProfiler* profiler) const {
  if (hair.raster() != raster_) throw Error("OffscreenRenderer: the hair system's raster mode differs from the renderer's");
  if (raster_ != RasterMode::Compute) {
    record(cmd, [&](VkCommandBuffer c) { hair.recordDraw(c, view, profiler); }, exposure, profiler);
    return;
  }
  recordComputeScene(
      cmd, [&](VkCommandBuffer c) { hair.recordDraw(c, view, profiler); },  // the head only
      [&](VkCommandBuffer c) { hair.recordRaster(c, view, profiler); },
      [&](VkCommandBuffer c) { hair.recordComposite(c, extent(), profiler); }, profiler);
  if (profiler) profiler->begin(cmd, "tonemap");
  recordTonemap(cmd, exposure);
  if (profiler) profiler->end(cmd);
}

void OffscreenRenderer::record(VkCommandBuffer cmd, Renderer& renderer, std::uint64_t frame, const View& view,
                               std::span<HairInstance* const> instances, float exposure,
                               vk::GpuProfiler* profiler, const Record& applicationDraws, RasterTarget* target) const {
  requireCompute(renderer, "record");
  recordComputeScene(
      cmd,
      [&](VkCommandBuffer c) {
        if (applicationDraws) applicationDraws(c);
        renderer.recordDraw(c, frame, view, instances, profiler);
      },
      [&](VkCommandBuffer c) {
        if (target) return renderer.recordRaster(c, frame, view, *target, profiler);
        renderer.recordRaster(c, frame, view, profiler);
      },
      [&](VkCommandBuffer c) {
        if (target) return renderer.recordComposite(c, extent(), *target, profiler);
        renderer.recordComposite(c, extent(), profiler);
      },
      profiler);
  recordTonemap(cmd, exposure);
}

// Head (depth stored), the rasterizer reads the depth, then the composite over the colour (and, with
// MSAA, the resolve: the head's samples antialias its edges over the background and over the hair).
void OffscreenRenderer::recordComputeScene(VkCommandBuffer cmd, const Record& drawHeads, const Record& raster,
                                           const Record& composite, vk::GpuProfiler* profiler) const {
  const VkImage hdr = targets_.hdr.handle(), depthImage = targets_.depth.handle();
  discardTargets(cmd);
  VkRenderingAttachmentInfo color = vk::colorAttachment(targets_.hdr.view(), VK_ATTACHMENT_LOAD_OP_CLEAR, kBackground);
  VkRenderingAttachmentInfo depth = sceneDepth(VK_ATTACHMENT_LOAD_OP_CLEAR, VK_ATTACHMENT_STORE_OP_STORE);
  VkRenderingInfo info = renderingInfo(extent(), &color, &depth);
  ctx_.fn().vkCmdBeginRendering(cmd, &info);
  drawHeads(cmd);
  ctx_.fn().vkCmdEndRendering(cmd);
  vk::imageBarrier(ctx_, cmd, depthImage, VK_IMAGE_ASPECT_DEPTH_BIT, vk::ImageUse::DepthAttachment,
                   vk::ImageUse::ComputeSampled);
  raster(cmd);
  vk::imageBarrier(ctx_, cmd, depthImage, VK_IMAGE_ASPECT_DEPTH_BIT, vk::ImageUse::ComputeSampled,
                   vk::ImageUse::DepthAttachment);
  // The head's colour writes before the composite's blend reads them (separate rendering instances).
  vk::imageBarrier(ctx_, cmd, hdr, VK_IMAGE_ASPECT_COLOR_BIT, vk::ImageUse::ColorAttachment, vk::ImageUse::ColorAttachment);
  color.loadOp = VK_ATTACHMENT_LOAD_OP_LOAD;
  resolveInto(color);
  depth = sceneDepth(VK_ATTACHMENT_LOAD_OP_LOAD, VK_ATTACHMENT_STORE_OP_DONT_CARE);
  // The composite's own scope lies inside the rendering instance, where lavapipe stamps before it runs the
  // draw (and the MSAA resolve at its end): this one, outside, times them (docs/PERFORMANCE.md).
  if (profiler) profiler->begin(cmd, "composite pass");
  ctx_.fn().vkCmdBeginRendering(cmd, &info);
  composite(cmd);
  ctx_.fn().vkCmdEndRendering(cmd);
  if (profiler) profiler->end(cmd);
  vk::imageBarrier(ctx_, cmd, hdrInput().handle(), VK_IMAGE_ASPECT_COLOR_BIT, vk::ImageUse::ColorAttachment,
                   vk::ImageUse::FragmentSampled);
}

void OffscreenRenderer::discardTargets(VkCommandBuffer cmd) const {
  const bool msaa = bool(targets_.resolved);
  // Earlier frames recorded into the same images: their writes (and, without MSAA, the tonemap's reads
  // of the HDR image) finish before the transitions discard the contents.
  vk::imageBarrier(ctx_, cmd, targets_.hdr.handle(), VK_IMAGE_ASPECT_COLOR_BIT,
                   msaa ? vk::ImageUse::ColorAttachmentDiscard : vk::ImageUse::FragmentSampledDiscard,
                   vk::ImageUse::ColorAttachment);
  vk::imageBarrier(ctx_, cmd, targets_.depth.handle(), VK_IMAGE_ASPECT_DEPTH_BIT, vk::ImageUse::DepthAttachmentDiscard,
                   vk::ImageUse::DepthAttachment);
  // The previous frame's tonemap may still sample the resolve target: wait for it before discarding it.
  if (msaa)
    vk::imageBarrier(ctx_, cmd, targets_.resolved.handle(), VK_IMAGE_ASPECT_COLOR_BIT, vk::ImageUse::FragmentSampledDiscard,
                     vk::ImageUse::ColorAttachment);
}

void OffscreenRenderer::resolveInto(VkRenderingAttachmentInfo& color) const {
  if (!targets_.resolved) return;
  color.resolveMode = VK_RESOLVE_MODE_AVERAGE_BIT;
  color.resolveImageView = targets_.resolved.view();
  color.resolveImageLayout = vk::imageLayout(vk::ImageUse::ColorAttachment);
  color.storeOp = VK_ATTACHMENT_STORE_OP_DONT_CARE;  // only the resolve is kept
}

void OffscreenRenderer::record(VkCommandBuffer cmd, const std::function<void(VkCommandBuffer)>& draws,
                               float exposure, vk::GpuProfiler* profiler) const {
  recordScene(cmd, draws);
  if (profiler) profiler->begin(cmd, "tonemap");
  recordTonemap(cmd, exposure);
  if (profiler) profiler->end(cmd);
}

void OffscreenRenderer::recordScene(VkCommandBuffer cmd, const std::function<void(VkCommandBuffer)>& draws) const {
  discardTargets(cmd);
  VkRenderingAttachmentInfo color = vk::colorAttachment(targets_.hdr.view(), VK_ATTACHMENT_LOAD_OP_CLEAR, kBackground);
  resolveInto(color);
  VkRenderingAttachmentInfo depth = sceneDepth(VK_ATTACHMENT_LOAD_OP_CLEAR, VK_ATTACHMENT_STORE_OP_DONT_CARE);
  VkRenderingInfo info = renderingInfo(extent(), &color, &depth);
  ctx_.fn().vkCmdBeginRendering(cmd, &info);
  draws(cmd);
  ctx_.fn().vkCmdEndRendering(cmd);
  vk::imageBarrier(ctx_, cmd, hdrInput().handle(), VK_IMAGE_ASPECT_COLOR_BIT, vk::ImageUse::ColorAttachment,
                   vk::ImageUse::FragmentSampled);
}

void OffscreenRenderer::recordTonemap(VkCommandBuffer cmd, float exposure) const {
  vk::imageBarrier(ctx_, cmd, targets_.display.handle(), VK_IMAGE_ASPECT_COLOR_BIT, vk::ImageUse::ColorAttachmentDiscard,
                   vk::ImageUse::ColorAttachment);
  VkRenderingAttachmentInfo color = vk::colorAttachment(targets_.display.view(), VK_ATTACHMENT_LOAD_OP_CLEAR, {{0, 0, 0, 1}});
  VkRenderingInfo info = renderingInfo(extent(), &color, nullptr);
  ctx_.fn().vkCmdBeginRendering(cmd, &info);
  tonemap_.draw(cmd, extent(), exposure);
  ctx_.fn().vkCmdEndRendering(cmd);
}

std::vector<std::uint8_t> OffscreenRenderer::readDisplay() const {
  auto bytes = vk::readbackImage(ctx_, targets_.display, vk::ImageUse::ColorAttachment);
  std::vector<std::uint8_t> out(bytes.size());
  std::memcpy(out.data(), bytes.data(), bytes.size());
  return out;
}

LinearImage OffscreenRenderer::readLinear() const {
  return rgbOfHalfRgba(vk::readbackImage(ctx_, hdrInput(), vk::ImageUse::FragmentSampled), extent(), 0, 3);
}

LinearImage rgbOfHalfRgba(const std::vector<std::byte>& bytes, VkExtent2D extent, std::uint32_t first,
                          std::uint32_t channels) {
  const std::size_t pixels = std::size_t(extent.width) * extent.height;
  if (bytes.size() != pixels * 4 * sizeof(std::uint16_t)) throw Error("rgbOfHalfRgba: not an RGBA16F image of this size");
  std::vector<std::uint16_t> halves(pixels * 4);
  std::memcpy(halves.data(), bytes.data(), bytes.size());
  LinearImage image(extent.width, extent.height, channels);
  for (std::size_t i = 0; i < pixels; ++i)
    for (std::uint32_t c = 0; c < channels; ++c) image.values[i * channels + c] = shading::halfToFloat(halves[i * 4 + first + c]);
  return image;
}
}  // namespace hp::render
