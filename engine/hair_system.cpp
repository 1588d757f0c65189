#include "engine/hair_system.h"

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

View viewOf(const DrawView& v) { return View{v.camera, v.extent, v.lines, 0}; }
}  // namespace

HairSystem::HairSystem(const vk::Context& ctx, const HairAsset& asset, const HairSystemSettings& settings,
                       const glm::mat4& initialHead)
    : renderer_(ctx, rendererSettings(settings)),
      instance_(renderer_.createInstance(asset, instanceSettings(settings), initialHead)) {}

void HairSystem::recordUpdate(VkCommandBuffer cmd, const HeadMotion& motion, vk::GpuProfiler* profiler) {
  instance_->setMotion(motion);
  HairInstance* one[] = {instance_.get()};
  renderer_.recordUpdate(cmd, frame_ + 1, one, profiler);
}

void HairSystem::recordPrepareDraw(VkCommandBuffer cmd, const DrawView& view, vk::GpuProfiler* profiler) {
  viewOf(view).validate(1);
  view.light.validate();
  instance_->setHeadToWorld(view.headToWorld);
  HairInstance* one[] = {instance_.get()};
  renderer_.recordShadows(cmd, ++frame_, view.light, one, profiler);
}

void HairSystem::recordDraw(VkCommandBuffer cmd, const DrawView& view, vk::GpuProfiler* profiler) {
  HairInstance* one[] = {instance_.get()};
  renderer_.recordDraw(cmd, frame_, viewOf(view), one, profiler);
}
}  // namespace hp
