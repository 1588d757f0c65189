#include "samples/tools/hair_system.h"

#include "engine/core/error.h"

namespace hp {
namespace {
RendererSettings rendererSettings(const HairSystemSettings& s) {
  RendererSettings r;
  r.formats = s.formats;
  r.opacity = s.opacity;
  r.shadowedLights = s.shadowedLights;
  r.motionVectors = s.motionVectors;
  r.framesInFlight = s.framesInFlight;
  r.maxViewsPerFrame = 1;
  r.raster = s.raster;
  r.rasterSettings = s.rasterSettings;
  return r;
}

InstanceSettings instanceSettings(const HairSystemSettings& s) {
  InstanceSettings i{s.simulation, s.material, s.lutMode, s.strands, s.look};
  i.drawHead = s.drawHead;
  i.lod = s.lod;
  i.groom = s.groom;
  i.scalp = s.scalp;
  return i;
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

HairSystem::HairSystem(const vk::Context& ctx, const HairAsset& asset, const HairSystemSettings& settings,
                       const glm::mat4& initialHead)
    : renderer_(ctx, rendererSettings(settings)),
      instance_(renderer_.createInstance(asset, instanceSettings(settings), initialHead)),
      settings_(settings) {}

void HairSystem::recordUpdate(VkCommandBuffer cmd, const HeadMotion& motion, vk::GpuProfiler* profiler) {
  instance_->setMotion(motion);
  HairInstance* one[] = {instance_.get()};
  renderer_.recordUpdate(cmd, frame_ + 1, one, profiler);
}

void HairSystem::recordPrepareDraw(VkCommandBuffer cmd, const DrawView& view, vk::GpuProfiler* profiler) {
  viewOf(view, true).validate(1, false);
  validateLights(view.lights);  // names the bad light by index, before anything is recorded
  instance_->setHeadToWorld(view.headToWorld);
  HairInstance* one[] = {instance_.get()};
  renderer_.recordShadows(cmd, ++frame_, view.lights, one, profiler);
}

void HairSystem::recordDraw(VkCommandBuffer cmd, const DrawView& view, vk::GpuProfiler* profiler) {
  HairInstance* one[] = {instance_.get()};
  renderer_.recordDraw(cmd, frame_, viewOf(view, true), one, profiler);
}

void HairSystem::setMaterial(const HairMaterial& material, LutMode mode) {
  instance_->setMaterial(material, mode);  // a raster target rebinds the new LUTs from the next frame on
  settings_.material = material;
  settings_.lutMode = mode;
}

void HairSystem::setLook(const render::LookSettings& look) {
  instance_->setLook(look);
  settings_.look = look;
}

void HairSystem::setGroom(const GroomSettings& groom) {
  instance_->setGroom(groom);
  settings_.groom = groom;
}

void HairSystem::setStrands(const InterpolationTopology& topology) {
  instance_->setStrands(topology, settings_.strands);  // the raster target follows at the next frame
}

void HairSystem::setRasterTarget(VkExtent2D extent, VkImageView depth) {
  HairInstance* one[] = {instance_.get()};
  renderer_.setRasterTarget(extent, depth, one);
}

void HairSystem::recordRaster(VkCommandBuffer cmd, const DrawView& view, vk::GpuProfiler* profiler) {
  renderer_.recordRaster(cmd, frame_, viewOf(view, false), profiler);
}

void HairSystem::recordComposite(VkCommandBuffer cmd, VkExtent2D extent, vk::GpuProfiler* profiler) const {
  renderer_.recordComposite(cmd, extent, profiler);
}
}  // namespace hp
