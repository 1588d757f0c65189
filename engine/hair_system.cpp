#include "engine/hair_system.h"

#include <cmath>

#include "engine/error.h"

#include "engine/vk/barriers.h"
#include "engine/vk/transfer.h"
#include "engine/vk/context.h"

namespace hp {
namespace {
vk::Buffer makeFrameBlock(const vk::Context& ctx) {
  return vk::Buffer(ctx, sizeof(gpu::RenderFrame), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                    vk::MemoryKind::DeviceLocal, "render frame");
}

const HairSystemSettings& validated(const HairSystemSettings& s) {
  s.simulation.validate();
  s.material.validate();
  s.look.validate();
  s.opacity.validate();
  // The strand shader builds its coverage sample mask in 32 bits (and gl_SampleMask[0] holds 32).
  if (s.formats.samples > VK_SAMPLE_COUNT_16_BIT) throw Error("HairSystemSettings.formats.samples must be at most 16");
  return s;
}

// The embedding path has no CLI in front of it: a bad view must fail here, not as NaN on the device.
const compute::StrandRasterPass& requireRaster(const std::unique_ptr<compute::StrandRasterPass>& pass) {
  if (!pass) throw Error("HairSystem: the compute raster needs setRasterTarget() before recording");
  return *pass;
}

void validateView(const DrawView& view) {
  view.light.validate();
  if (view.extent.width == 0 || view.extent.height == 0) throw Error("DrawView.extent must be non-zero");
  for (const glm::mat4* m : {&view.camera.view, &view.camera.proj, &view.headToWorld})
    for (int c = 0; c < 4; ++c)
      for (int r = 0; r < 4; ++r)
        if (!std::isfinite((*m)[c][r])) throw Error("DrawView matrices must be finite");
}
}  // namespace

HairSystem::HairSystem(const vk::Context& ctx, const HairAsset& asset, const HairSystemSettings& settings,
                       const glm::mat4& initialHead)
    : ctx_(ctx),
      settings_(validated(settings)),
      simulate_(ctx, asset, settings.simulation, initialHead),
      strands_(ctx, asset.guides.guideCount(), asset.guides.particlesPerGuide, asset.topology, settings.strands),
      tessellate_(ctx, simulate_.positions(), strands_),
      interpolate_(ctx, strands_),
      marschner_(ctx, settings.material, settings.lutMode),
      frameBlock_(makeFrameBlock(ctx)),
      bounds_(ctx, strands_),
      opacity_(ctx, strands_, asset.head, bounds_.lightSpace(), settings.opacity),
      head_(ctx, asset.head, frameBlock_, opacity_.shadowInputs(), settings.formats),
      strandPass_(ctx, strands_, marschner_, frameBlock_, opacity_.shadowInputs(), settings.formats),
      raster_(resolveRasterMode(settings.raster, ctx.properties().deviceType)) {
  settings_.rasterSettings.validate();
  // A valid frame block from the start, so a draw recorded before the first recordPrepareDraw reads
  // sane values (vertex count, matrices) instead of uninitialised memory.
  const gpu::RenderFrame initial =
      render::makeRenderFrame(CameraMatrices{}, {1, 1}, LightSpec{}, settings_.material, settings_.look,
                              strands_.layout().verticesPerStrand, settings_.opacity);
  vk::upload<gpu::RenderFrame>(ctx, frameBlock_, std::span(&initial, 1), vk::BufferUse::GraphicsRead);
}

void HairSystem::recordUpdate(VkCommandBuffer cmd, const HeadMotion& motion, vk::GpuProfiler* profiler) {
  // The previous frame drew the strands and chained compute passes over the same buffers.
  vk::memoryBarrier(cmd, vk::BufferUse::VertexRead, vk::BufferUse::ComputeWrite);
  vk::memoryBarrier(cmd, vk::BufferUse::ComputeWrite, vk::BufferUse::ComputeWrite);
  simulate_.record(cmd, motion, profiler);
  vk::memoryBarrier(cmd, vk::BufferUse::ComputeWrite, vk::BufferUse::ComputeRead);
  tessellate_.record(cmd, profiler);
  vk::memoryBarrier(cmd, vk::BufferUse::ComputeWrite, vk::BufferUse::ComputeRead);
  interpolate_.record(cmd, profiler);
}

void HairSystem::recordPrepareDraw(VkCommandBuffer cmd, const DrawView& view, vk::GpuProfiler* profiler) {
  validateView(view);
  gpu::RenderFrame frame = render::makeRenderFrame(view.camera, view.extent, view.light, settings_.material,
                                                   settings_.look, strands_.layout().verticesPerStrand,
                                                   settings_.opacity);
  vk::bufferBarrier(cmd, frameBlock_.handle(), vk::BufferUse::GraphicsRead, vk::BufferUse::TransferDst);
  vkCmdUpdateBuffer(cmd, frameBlock_.handle(), 0, sizeof(frame), &frame);
  vk::bufferBarrier(cmd, frameBlock_.handle(), vk::BufferUse::TransferDst, vk::BufferUse::GraphicsRead);
  vk::memoryBarrier(cmd, vk::BufferUse::ComputeWrite, vk::BufferUse::VertexRead);
  if (!settings_.opacity.enabled) return;
  compute::BoundsFraming framing;
  framing.resolution = settings_.opacity.resolution;
  framing.marginWorld = 0.5f * settings_.look.strandWidth * gpu::WIDTH_SCALE_MAX;
  recordShadowPasses(cmd, bounds_, opacity_, shadowLightOf(view.light), framing, view.headToWorld, profiler);
}

compute::ShadowLight shadowLightOf(const LightSpec& light) {
  const glm::vec3 toward = glm::normalize(light.direction);
  if (light.type == LightSpec::Type::Directional) return compute::ShadowLight(toward);
  return compute::ShadowLight::makeSpot(light.position, toward, glm::radians(light.coneDeg));
}

void recordShadowPasses(VkCommandBuffer cmd, const compute::BoundsPass& bounds, const render::OpacityPass& opacity,
                        const compute::ShadowLight& shadowLight, const compute::BoundsFraming& framing,
                        const glm::mat4& headToWorld, vk::GpuProfiler* profiler) {
  const VkBuffer light = bounds.lightSpace().handle();
  if (profiler) profiler->begin(cmd, "bounds");
  vk::memoryBarrier(cmd, vk::BufferUse::ComputeWrite, vk::BufferUse::ComputeRead);        // strand positions
  vk::bufferBarrier(cmd, light, vk::BufferUse::VertexRead, vk::BufferUse::ComputeWrite);  // last frame's readers
  bounds.recordReduce(cmd, shadowLight);
  vk::bufferBarrier(cmd, light, vk::BufferUse::ComputeWrite, vk::BufferUse::ComputeWrite);
  bounds.recordFinalize(cmd, shadowLight, framing);
  vk::bufferBarrier(cmd, light, vk::BufferUse::ComputeWrite, vk::BufferUse::VertexRead);
  if (profiler) profiler->end(cmd);

  const vk::Image& maps = opacity.image();
  if (profiler) profiler->begin(cmd, "opacity");
  vk::imageBarrier(cmd, maps.handle(), VK_IMAGE_ASPECT_COLOR_BIT, vk::ImageUse::FragmentSampled,
                   vk::ImageUse::ColorAttachment, gpu::OPACITY_TARGETS);
  opacity.record(cmd, headToWorld);
  vk::imageBarrier(cmd, maps.handle(), VK_IMAGE_ASPECT_COLOR_BIT, vk::ImageUse::ColorAttachment,
                   vk::ImageUse::FragmentSampled, gpu::OPACITY_TARGETS);
  if (profiler) profiler->end(cmd);
}

RasterMode resolveRasterMode(RasterMode mode, VkPhysicalDeviceType type) {
  if (mode != RasterMode::Auto) return mode;
  // Measured on lavapipe (CPU): compute 10-20x faster than MSAA 4 ribbons (docs/PERFORMANCE.md). GPUs
  // are unmeasured here; compute is the default there too, on the brief's fragment-vs-compute evidence.
  (void)type;
  return RasterMode::Compute;
}

void HairSystem::setRasterTarget(VkExtent2D extent, VkImageView depth) {
  if (raster_ != RasterMode::Compute) throw Error("HairSystem::setRasterTarget: the raster mode is not compute");
  if (!rasterPass_ || rasterPass_->extent().width != extent.width || rasterPass_->extent().height != extent.height) {
    rasterPass_ = std::make_unique<compute::StrandRasterPass>(ctx_, strands_, shadingWriter(), extent,
                                                              settings_.rasterSettings);
    if (!composite_) composite_ = std::make_unique<render::CompositePass>(ctx_, settings_.formats);
    composite_->setInput(rasterPass_->output().view());
  }
  rasterPass_->setDepth(depth);
}

compute::ShadingWriter HairSystem::shadingWriter() const {
  return [this](const vk::DescriptorSet& set) {
    set.writeUniformBuffer(gpu::RENDER_BINDING_FRAME, frameBlock_.handle());
    marschner_.writeDescriptors(set, gpu::RENDER_BINDING_MARSCHNER, gpu::RENDER_BINDING_LUT_M,
                                gpu::RENDER_BINDING_LUT_N0, gpu::RENDER_BINDING_LUT_N1);
    const render::ShadowInputs shadows = opacity_.shadowInputs();
    set.writeSampledImage(gpu::RENDER_BINDING_OPACITY, shadows.opacityView, shadows.sampler);
    set.writeStorageBuffer(gpu::RENDER_BINDING_LIGHT, shadows.lightSpace);
  };
}

void HairSystem::recordRaster(VkCommandBuffer cmd, vk::GpuProfiler* profiler) const {
  const compute::StrandRasterPass& pass = requireRaster(rasterPass_);
  // The graphics readers' states (recordPrepareDraw) extended to compute for the pass, then back, so
  // the next frame's barriers (which wait on vertex/fragment readers) still cover these reads.
  const VkBuffer light = opacity_.shadowInputs().lightSpace;
  const VkImage maps = opacity_.image().handle();
  vk::memoryBarrier(cmd, vk::BufferUse::ComputeWrite, vk::BufferUse::ComputeRead);  // strand buffers
  vk::bufferBarrier(cmd, frameBlock_.handle(), vk::BufferUse::GraphicsRead, vk::BufferUse::ComputeRead);
  vk::bufferBarrier(cmd, light, vk::BufferUse::VertexRead, vk::BufferUse::ComputeRead);
  vk::imageBarrier(cmd, maps, VK_IMAGE_ASPECT_COLOR_BIT, vk::ImageUse::FragmentSampled, vk::ImageUse::ComputeSampled,
                   gpu::OPACITY_TARGETS);
  pass.record(cmd, profiler);
  vk::bufferBarrier(cmd, frameBlock_.handle(), vk::BufferUse::ComputeRead, vk::BufferUse::GraphicsRead);
  vk::bufferBarrier(cmd, light, vk::BufferUse::ComputeRead, vk::BufferUse::VertexRead);
  vk::imageBarrier(cmd, maps, VK_IMAGE_ASPECT_COLOR_BIT, vk::ImageUse::ComputeSampled, vk::ImageUse::FragmentSampled,
                   gpu::OPACITY_TARGETS);
}

void HairSystem::recordComposite(VkCommandBuffer cmd, VkExtent2D extent, vk::GpuProfiler* profiler) const {
  requireRaster(rasterPass_);
  if (profiler) profiler->begin(cmd, "composite");
  composite_->draw(cmd, extent);
  if (profiler) profiler->end(cmd);
}

const vk::Image& HairSystem::rasterImage() const { return requireRaster(rasterPass_).output(); }

compute::RasterStats HairSystem::rasterStats() const { return requireRaster(rasterPass_).readStats(); }

void HairSystem::recordDraw(VkCommandBuffer cmd, const DrawView& view, vk::GpuProfiler* profiler) const {
  if (profiler) profiler->begin(cmd, "head");
  head_.draw(cmd, view.extent, view.headToWorld);
  if (profiler) profiler->end(cmd);
  if (raster_ == RasterMode::Compute) return;
  if (profiler) profiler->begin(cmd, "shade");
  strandPass_.draw(cmd, view.extent, view.lines);
  if (profiler) profiler->end(cmd);
}

void HairSystem::setMaterial(const HairMaterial& material, LutMode mode) {
  try {
    if (!marschner_.rebuild(material, mode)) return;
  } catch (...) {
    // A rebuild that failed part-way (out of memory) may have replaced some images: rebind so the
    // strand pass never keeps descriptors to destroyed views, then report the failure.
    rebindShading();
    throw;
  }
  settings_.material = material;
  settings_.lutMode = mode;
  rebindShading();
}

void HairSystem::rebindShading() {
  strandPass_.bind(strands_, marschner_, frameBlock_, opacity_.shadowInputs());
  if (rasterPass_) rasterPass_->bind(strands_, shadingWriter());
}
}  // namespace hp
