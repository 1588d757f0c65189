#include "engine/hair_system.h"

#include "engine/error.h"
#include "engine/vk/barriers.h"
#include "engine/vk/context.h"
#include "shaders/shared/render.h"

namespace hp {
namespace {
RendererSettings rendererSettings(const HairSystemSettings& s) {
  RendererSettings r;
  r.formats = s.formats;
  r.opacity = s.opacity;
  r.framesInFlight = s.framesInFlight;
  r.maxViewsPerFrame = 1;
  return r;
}

InstanceSettings instanceSettings(const HairSystemSettings& s) {
  return InstanceSettings{s.simulation, s.material, s.lutMode, s.strands, s.look};
}

View viewOf(const DrawView& v, bool ribbons) {
  View view;
  view.camera = v.camera;
  view.extent = v.extent;
  view.lines = v.lines;
  view.ribbons = ribbons;
  return view;
}
}  // namespace

RasterMode resolveRasterMode(RasterMode mode, VkPhysicalDeviceType type) {
  if (mode != RasterMode::Auto) return mode;
  // Measured on lavapipe (CPU): compute 10x cheaper than MSAA 4 ribbons (docs/PERFORMANCE.md). GPUs are
  // unmeasured here; compute is the default there too, on the fragment-vs-compute evidence.
  (void)type;
  return RasterMode::Compute;
}

HairSystem::HairSystem(const vk::Context& ctx, const HairAsset& asset, const HairSystemSettings& settings,
                       const glm::mat4& initialHead)
    : renderer_(ctx, rendererSettings(settings)),
      instance_(renderer_.createInstance(asset, instanceSettings(settings), initialHead)),
      settings_(settings),
      raster_(resolveRasterMode(settings.raster, ctx.properties().deviceType)),
      rasterFrame_(ctx, sizeof(gpu::RenderFrame), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                   vk::MemoryKind::DeviceLocal, "raster frame") {
  settings.rasterSettings.validate();
}

void HairSystem::recordUpdate(VkCommandBuffer cmd, const HeadMotion& motion, vk::GpuProfiler* profiler) {
  instance_->setMotion(motion);
  HairInstance* one[] = {instance_.get()};
  renderer_.recordUpdate(cmd, frame_ + 1, one, profiler);
}

void HairSystem::recordPrepareDraw(VkCommandBuffer cmd, const DrawView& view, vk::GpuProfiler* profiler) {
  viewOf(view, true).validate(1);
  view.light.validate();
  instance_->setHeadToWorld(view.headToWorld);
  HairInstance* one[] = {instance_.get()};
  renderer_.recordShadows(cmd, ++frame_, view.light, one, profiler);
}

void HairSystem::recordDraw(VkCommandBuffer cmd, const DrawView& view, vk::GpuProfiler* profiler) {
  HairInstance* one[] = {instance_.get()};
  renderer_.recordDraw(cmd, frame_, viewOf(view, raster_ != RasterMode::Compute), one, profiler);
}

void HairSystem::setMaterial(const HairMaterial& material, LutMode mode) {
  instance_->setMaterial(material, mode);
  settings_.material = material;
  settings_.lutMode = mode;
  // The rasterizer's descriptors name the old LUTs: a new pass, the old one retired after its frames.
  if (rasterPass_) rebuildRaster(rasterPass_->extent());
}

void HairSystem::setLook(const render::LookSettings& look) {
  instance_->setLook(look);
  settings_.look = look;  // the compute raster's frame constants read it
}

void HairSystem::setStrands(const InterpolationTopology& topology) {
  instance_->setStrands(topology, settings_.strands);
  if (rasterPass_) rebuildRaster(rasterPass_->extent());
}

compute::ShadingWriter HairSystem::shadingWriter() const {
  return [this](const vk::DescriptorSet& set) {
    // Storage buffers: the raster shaders read no uniform blocks (compute/strand_raster_pass.cpp).
    set.writeStorageBuffer(gpu::RENDER_BINDING_FRAME, rasterFrame_.handle());
    instance_->marschner().writeDescriptors(set, gpu::RENDER_BINDING_MARSCHNER, gpu::RENDER_BINDING_LUT_M,
                                            gpu::RENDER_BINDING_LUT_N0, gpu::RENDER_BINDING_LUT_N1,
                                            VK_DESCRIPTOR_TYPE_STORAGE_BUFFER);
    const render::ShadowInputs shadows = renderer_.shadows().inputs();
    set.writeSampledImage(gpu::RENDER_BINDING_OPACITY, shadows.opacityView, shadows.sampler);
    set.writeStorageBuffer(gpu::RENDER_BINDING_LIGHT, shadows.lightSpace);
    set.writeSampledImage(gpu::RENDER_BINDING_HEAD_SHADOW, shadows.headShadowView, shadows.headShadowSampler);
  };
}

void HairSystem::rebuildRaster(VkExtent2D extent) {
  auto pass = std::make_shared<compute::StrandRasterPass>(renderer_.context(), instance_->strands(), shadingWriter(),
                                                          extent, settings_.rasterSettings);
  if (rasterDepth_ != VK_NULL_HANDLE) pass->setDepth(rasterDepth_);
  if (!composite_) composite_ = std::make_unique<render::CompositePass>(renderer_.context(), settings_.formats);
  if (rasterPass_) renderer_.retire(rasterPass_);
  rasterPass_ = std::move(pass);
  composite_->setInput(rasterPass_->output().view());
}

void HairSystem::setRasterTarget(VkExtent2D extent, VkImageView depth) {
  if (raster_ != RasterMode::Compute) throw Error("HairSystem::setRasterTarget: the raster mode is not compute");
  rasterDepth_ = depth;
  if (!rasterPass_ || rasterPass_->extent().width != extent.width || rasterPass_->extent().height != extent.height)
    rebuildRaster(extent);
  else
    rasterPass_->setDepth(depth);
}

void HairSystem::recordRaster(VkCommandBuffer cmd, const DrawView& view, vk::GpuProfiler* profiler) {
  if (!rasterPass_) throw Error("HairSystem: the compute raster needs setRasterTarget() before recording");
  const vk::Context& ctx = renderer_.context();
  gpu::RenderFrame frame =
      render::makeRenderFrame(view.camera, view.extent, view.light, settings_.material, settings_.look,
                              instance_->strands().layout().verticesPerStrand, renderer_.shadows().settings());
  const render::HeadShadowView& headView = renderer_.headShadowOf(frame_);
  frame.headShadowViewProj = headView.viewProj;
  frame.headShadow = headView.params;
  vk::bufferBarrier(ctx, cmd, rasterFrame_.handle(), vk::BufferUse::ComputeRead, vk::BufferUse::TransferDst);
  ctx.fn().vkCmdUpdateBuffer(cmd, rasterFrame_.handle(), 0, sizeof(frame), &frame);
  vk::bufferBarrier(ctx, cmd, rasterFrame_.handle(), vk::BufferUse::TransferDst, vk::BufferUse::ComputeRead);
  // The graphics readers' states (recordShadows) extended to compute for the pass, then back, so the
  // next frame's barriers (which wait on vertex/fragment readers) still cover these reads.
  const render::ShadowMaps& shadows = renderer_.shadows();
  const VkBuffer light = shadows.lightSpace().handle();
  const VkImage maps = shadows.image().handle();
  const VkImage head = shadows.headImage().handle();
  vk::memoryBarrier(ctx, cmd, vk::BufferUse::ComputeWrite, vk::BufferUse::ComputeRead);  // strand buffers
  vk::imageBarrier(ctx, cmd, head, VK_IMAGE_ASPECT_DEPTH_BIT, vk::ImageUse::FragmentSampled, vk::ImageUse::ComputeSampled);
  vk::bufferBarrier(ctx, cmd, light, vk::BufferUse::VertexRead, vk::BufferUse::ComputeRead);
  vk::imageBarrier(ctx, cmd, maps, VK_IMAGE_ASPECT_COLOR_BIT, vk::ImageUse::FragmentSampled, vk::ImageUse::ComputeSampled,
                   gpu::OPACITY_TARGETS);
  rasterPass_->record(cmd, profiler);
  vk::bufferBarrier(ctx, cmd, light, vk::BufferUse::ComputeRead, vk::BufferUse::VertexRead);
  vk::imageBarrier(ctx, cmd, maps, VK_IMAGE_ASPECT_COLOR_BIT, vk::ImageUse::ComputeSampled, vk::ImageUse::FragmentSampled,
                   gpu::OPACITY_TARGETS);
  vk::imageBarrier(ctx, cmd, head, VK_IMAGE_ASPECT_DEPTH_BIT, vk::ImageUse::ComputeSampled, vk::ImageUse::FragmentSampled);
}

void HairSystem::recordComposite(VkCommandBuffer cmd, VkExtent2D extent, vk::GpuProfiler* profiler) const {
  if (!rasterPass_) throw Error("HairSystem: the compute raster needs setRasterTarget() before recording");
  if (profiler) profiler->begin(cmd, "composite");
  composite_->draw(cmd, extent);
  if (profiler) profiler->end(cmd);
}

const vk::Image& HairSystem::rasterImage() const {
  if (!rasterPass_) throw Error("HairSystem: no compute raster target");
  return rasterPass_->output();
}

compute::RasterStats HairSystem::rasterStats() const {
  if (!rasterPass_) throw Error("HairSystem: no compute raster target");
  return rasterPass_->readStats();
}
}  // namespace hp
