// hairpipe::Renderer and hairpipe::Instance over hp::Renderer and hp::HairInstance.
#include "compute/api/access.h"
#include "compute/api/convert.h"
#include "compute/renderer/instance_preparation.h"
#include "engine/core/hair/strand_topology.h"

namespace hairpipe {
namespace {
// The implementation's instances behind a span of public ones (null and foreign ones are refused by the
// implementation, which names them).
std::vector<hp::HairInstance*> implementations(std::span<Instance* const> instances) {
  std::vector<hp::HairInstance*> out;
  out.reserve(instances.size());
  for (Instance* i : instances) {
    const Instance::Impl* impl = i ? Access::impl(*i) : nullptr;
    if (!impl) throw hp::Error("an instance is null or was moved from");
    out.push_back(impl->instance.get());
  }
  return out;
}

hp::HairInstance& implementation(const Instance::Impl* impl) {
  if (!impl) throw hp::Error("the instance was moved from");
  return *impl->instance;
}

hp::Renderer& implementation(const std::shared_ptr<hp::Renderer>& renderer) {
  if (!renderer) throw hp::Error("the Renderer was moved from");
  return *renderer;
}

// The implementation's target behind a public one of this Renderer (`renderer`).
hp::RasterTarget& implementation(const RasterTarget& target, const hp::Renderer& renderer) {
  const RasterTarget::Impl* impl = Access::impl(target);
  if (!impl) throw hp::Error("the raster target was moved from");
  if (impl->renderer.get() != &renderer) throw hp::Error("the raster target belongs to another Renderer");
  return *impl->target;
}

// Retires a target's raster through its Renderer (after the frames in flight).
void retire(std::unique_ptr<RasterTarget::Impl> impl) noexcept {
  if (!impl) return;
  try {
    impl->renderer->destroyRasterTarget(impl->target);
  } catch (...) {
    // Out of host memory while queueing it: the target's objects go with the last reference, the Impl's.
  }
}

// Retires the instance through its Renderer, which keeps it until the frames in flight are done
// (destroyInstance retires it before it rebuilds a raster target, which may fail before the first frame; in
// the frame loop the rebuild waits for the next frame, where a failure empties the target, named by recordRaster).
void retire(std::unique_ptr<Instance::Impl> impl) noexcept {
  if (!impl) return;
  try {
    impl->renderer->destroyInstance(std::move(impl->instance));
  } catch (...) {
    // The raster target holding it could not be rebuilt: it was dropped (recordRaster asks for
    // setRasterTarget); the instance itself is retired already.
  }
}
}  // namespace

Instance::Instance(std::unique_ptr<Impl> impl) noexcept : impl_(std::move(impl)) {}
Instance::Instance(Instance&&) noexcept = default;
Instance& Instance::operator=(Instance&& other) noexcept {
  if (this != &other) {
    retire(std::move(impl_));
    impl_ = std::move(other.impl_);
  }
  return *this;
}
Instance::~Instance() { retire(std::move(impl_)); }

Status Instance::setMotion(const HeadMotion& motion) noexcept {
  return guardedStatus("hairpipe::Instance::setMotion", [&] { implementation(impl_.get()).setMotion(convert::motion(motion)); });
}
Status Instance::setHeadToWorld(const Mat4& headToWorld) noexcept {
  return guardedStatus("hairpipe::Instance::setHeadToWorld",
                       [&] { implementation(impl_.get()).setHeadToWorld(convert::mat(headToWorld)); });
}
Status Instance::setColliders(std::span<const SphereCollider> spheres, std::span<const CapsuleCollider> capsules) noexcept {
  return guardedStatus("hairpipe::Instance::setColliders", [&] {
    implementation(impl_.get()).setColliders(convert::spheres(spheres), convert::capsules(capsules));
  });
}
Status Instance::setRootFrames(VkBuffer buffer, VkDeviceSize offset, VkDeviceSize bytes) noexcept {
  return guardedStatus("hairpipe::Instance::setRootFrames",
                       [&] { implementation(impl_.get()).setRootFrames(buffer, offset, bytes); });
}
Status Instance::setBones(std::span<const Mat4> bones) noexcept {
  return guardedStatus("hairpipe::Instance::setBones",
                       [&] { implementation(impl_.get()).setBones(convert::mats(bones)); });
}
Status Instance::setMeshPose(std::span<const Mat4> bones) noexcept {
  return guardedStatus("hairpipe::Instance::setMeshPose",
                       [&] { implementation(impl_.get()).setCharacterPose(convert::mats(bones)); });
}
Status Instance::setMaterial(const Material& material, FibreModel fibre) noexcept {
  return guardedStatus("hairpipe::Instance::setMaterial", [&] {
    implementation(impl_.get()).setMaterial(convert::material(material), convert::fibre(fibre));
  });
}
Status Instance::setLod(const LodSettings& lod) noexcept {
  return guardedStatus("hairpipe::Instance::setLod", [&] { implementation(impl_.get()).setLod(lod); });
}

Status Instance::setGroom(const GroomSettings& groom) noexcept {
  return guardedStatus("hairpipe::Instance::setGroom", [&] { implementation(impl_.get()).setGroom(convert::groom(groom)); });
}

Status Instance::setLook(const LookSettings& look) noexcept {
  return guardedStatus("hairpipe::Instance::setLook", [&] { implementation(impl_.get()).setLook(convert::look(look)); });
}
Status Instance::setSimulation(const SimulationSettings& simulation) noexcept {
  return guardedStatus("hairpipe::Instance::setSimulation",
                       [&] { implementation(impl_.get()).setSimulation(convert::simulation(simulation)); });
}
Status Instance::setDensity(const Density& density) noexcept {
  return guardedStatus("hairpipe::Instance::setDensity", [&] {
    hp::HairInstance& instance = implementation(impl_.get());
    const hp::HairAsset& asset = Access::asset(impl_->asset);
    instance.setStrands(hp::buildInterpolationTopology(asset.guides.roots(), asset.topology.triangles,
                                                       convert::density(density)),
                        instance.settings().strands);
  });
}
bool Instance::materialPending() const noexcept { return impl_ && impl_->instance->materialPending(); }
Status Instance::materialStatus() const noexcept {
  return guardedStatus("hairpipe::Instance::materialStatus", [&] {
    const std::string& error = implementation(impl_.get()).materialError();
    if (!error.empty()) throw hp::Error(error);
  });
}
Result<Instance::HairShadowForward> Instance::hairShadowForward() const noexcept {
  return guarded<HairShadowForward>("hairpipe::Instance::hairShadowForward", [&] {
    const glm::vec4 forward = implementation(impl_.get()).shadowForward();
    return HairShadowForward{{forward.r, forward.g, forward.b}, forward.a};
  });
}
std::uint32_t Instance::strandCount() const noexcept {
  return impl_ ? impl_->instance->strands().layout().strandCount : 0;  // 0: moved from
}

RasterTarget::RasterTarget(std::unique_ptr<Impl> impl) noexcept : impl_(std::move(impl)) {}
RasterTarget::RasterTarget(RasterTarget&&) noexcept = default;
RasterTarget& RasterTarget::operator=(RasterTarget&& other) noexcept {
  if (this != &other) {
    retire(std::move(impl_));
    impl_ = std::move(other.impl_);
  }
  return *this;
}
RasterTarget::~RasterTarget() { retire(std::move(impl_)); }

Renderer::Renderer(std::shared_ptr<hp::Renderer> impl) noexcept : impl_(std::move(impl)) {}
Renderer::Renderer(Renderer&&) noexcept = default;
Renderer& Renderer::operator=(Renderer&&) noexcept = default;
Renderer::~Renderer() = default;

Result<Renderer> Renderer::create(const Context& context, const RendererSettings& settings) noexcept {
  return guarded<Renderer>("hairpipe::Renderer::create", [&] {
    return Access::makeRenderer(std::make_shared<hp::Renderer>(Access::context(context), convert::renderer(settings)));
  });
}

Status prepareInstance(const Asset& asset, const InstanceSettings& settings) noexcept {
  return guardedStatus("hairpipe::prepareInstance",
                       [&] { hp::prepareInstance(Access::asset(asset), convert::instance(settings)); });
}

Result<Instance> Renderer::createInstance(const Asset& asset, const InstanceSettings& settings,
                                          const Mat4& initialHeadToWorld) noexcept {
  return guarded<Instance>("hairpipe::Renderer::createInstance", [&] {
    auto impl = std::make_unique<Instance::Impl>(Instance::Impl{impl_, asset, nullptr});
    impl->instance = implementation(impl_).createInstance(Access::asset(asset), convert::instance(settings),
                                           convert::mat(initialHeadToWorld));
    return Access::makeInstance(std::move(impl));
  });
}

Status Renderer::releaseRetired() noexcept {
  return guardedStatus("hairpipe::Renderer::releaseRetired", [&] { implementation(impl_).releaseRetired(); });
}

Status Renderer::recordChanges(VkCommandBuffer cmd, std::uint64_t frame, std::span<Instance* const> instances) noexcept {
  return guardedStatus("hairpipe::Renderer::recordChanges",
                       [&] { implementation(impl_).recordChanges(cmd, frame, implementations(instances)); });
}
Status Renderer::recordUpdate(VkCommandBuffer cmd, std::uint64_t frame, std::span<Instance* const> instances) noexcept {
  return guardedStatus("hairpipe::Renderer::recordUpdate",
                       [&] { implementation(impl_).recordUpdate(cmd, frame, implementations(instances)); });
}
Status Renderer::recordShadows(VkCommandBuffer cmd, std::uint64_t frame, std::span<const Light> lights,
                               std::span<Instance* const> instances) noexcept {
  return guardedStatus("hairpipe::Renderer::recordShadows", [&] {
    std::vector<hp::LightSpec> converted;
    for (const Light& l : lights) converted.push_back(convert::light(l));
    implementation(impl_).recordShadows(cmd, frame, converted, implementations(instances));
  });
}
Status Renderer::recordShadows(VkCommandBuffer cmd, std::uint64_t frame, const Light& light,
                               std::span<Instance* const> instances) noexcept {
  return recordShadows(cmd, frame, std::span(&light, 1), instances);
}
Status Renderer::recordDraw(VkCommandBuffer cmd, std::uint64_t frame, const View& view,
                            std::span<Instance* const> instances) noexcept {
  return guardedStatus("hairpipe::Renderer::recordDraw",
                       [&] { implementation(impl_).recordDraw(cmd, frame, convert::view(view), implementations(instances)); });
}
Status Renderer::setRasterTarget(VkExtent2D extent, VkImageView depth, std::span<Instance* const> instances) noexcept {
  return guardedStatus("hairpipe::Renderer::setRasterTarget",
                       [&] { implementation(impl_).setRasterTarget(extent, depth, implementations(instances)); });
}
Status Renderer::recordRaster(VkCommandBuffer cmd, std::uint64_t frame, const View& view) noexcept {
  return guardedStatus("hairpipe::Renderer::recordRaster", [&] { implementation(impl_).recordRaster(cmd, frame, convert::view(view)); });
}
Status Renderer::recordComposite(VkCommandBuffer cmd, VkExtent2D extent) noexcept {
  return guardedStatus("hairpipe::Renderer::recordComposite", [&] { implementation(impl_).recordComposite(cmd, extent); });
}
Result<RasterTarget> Renderer::createRasterTarget(VkExtent2D extent, VkImageView depth,
                                                  std::span<Instance* const> instances) noexcept {
  return guarded<RasterTarget>("hairpipe::Renderer::createRasterTarget", [&] {
    hp::Renderer& renderer = implementation(impl_);
    const std::vector<hp::HairInstance*> held = implementations(instances);
    // Allocated first: nothing may throw once the target is built (its uploads may be batched for the frame).
    auto impl = std::make_unique<RasterTarget::Impl>(RasterTarget::Impl{impl_, nullptr});
    impl->target = renderer.createRasterTarget(extent, depth, held);
    return Access::makeRasterTarget(std::move(impl));
  });
}
Status Renderer::recordRaster(VkCommandBuffer cmd, std::uint64_t frame, const View& view, RasterTarget& target) noexcept {
  return guardedStatus("hairpipe::Renderer::recordRaster", [&] {
    hp::Renderer& renderer = implementation(impl_);
    renderer.recordRaster(cmd, frame, convert::view(view), implementation(target, renderer));
  });
}
Status Renderer::recordComposite(VkCommandBuffer cmd, VkExtent2D extent, const RasterTarget& target) noexcept {
  return guardedStatus("hairpipe::Renderer::recordComposite", [&] {
    const hp::Renderer& renderer = implementation(impl_);
    renderer.recordComposite(cmd, extent, implementation(target, renderer));
  });
}
Status Renderer::setOpacityTuning(const OpacitySettings& opacity) noexcept {
  return guardedStatus("hairpipe::Renderer::setOpacityTuning", [&] { implementation(impl_).setOpacityTuning(opacity); });
}
RasterMode Renderer::raster() const noexcept {
  return impl_ ? convert::raster(impl_->raster()) : RasterMode::Auto;  // Auto: a moved-from Renderer
}
namespace {
Renderer::MotionImage motionImageOf(const hp::vk::Image& image) {
  return {image.handle(), image.view(), image.desc().format, image.extent()};
}
}  // namespace
Result<Renderer::MotionImage> Renderer::motionImage() const noexcept {
  return guarded<MotionImage>("hairpipe::Renderer::motionImage",
                              [&] { return motionImageOf(implementation(impl_).motionImage()); });
}
Result<Renderer::MotionImage> Renderer::motionImage(const RasterTarget& target) const noexcept {
  return guarded<MotionImage>("hairpipe::Renderer::motionImage", [&] {
    const hp::Renderer& renderer = implementation(impl_);
    return motionImageOf(renderer.motionImage(implementation(target, renderer)));
  });
}
Result<Renderer::HairShadows> Renderer::hairShadows() const noexcept {
  return guarded<HairShadows>("hairpipe::Renderer::hairShadows", [&] {
    const hp::render::ShadowMaps& maps = implementation(impl_).shadows();
    const hp::render::OpacitySettings& opacity = maps.settings();
    const hp::render::ShadowInputs inputs = maps.inputs();
    return HairShadows{maps.image().handle(),
                       inputs.opacityView,
                       inputs.sampler,
                       maps.image().desc().format,
                       maps.image().extent().width,
                       maps.slots(),
                       hp::gpu::OPACITY_LAYERS,
                       maps.lightSpace().handle(),
                       maps.lightSpace().size(),
                       opacity.enabled ? opacity.k : 0.0f,
                       hp::render::lookupBias(opacity),
                       opacity.deep};
  });
}
Result<Renderer::OccluderTargets> Renderer::occluderTargets() const noexcept {
  return guarded<OccluderTargets>("hairpipe::Renderer::occluderTargets", [&] {
    const hp::Renderer& renderer = implementation(impl_);
    if (!renderer.settings().applicationOccluders) throw hp::Error("RendererSettings::applicationOccluders is off");
    const hp::render::FrameLights* lights = renderer.currentShadowLights();
    if (!lights) throw hp::Error("the current frame's shadows are not recorded yet (call it after its recordShadows)");
    const hp::render::ShadowMaps& maps = renderer.shadows();
    OccluderTargets targets;
    targets.image = maps.headImage().handle();
    targets.format = hp::render::ShadowMaps::kHeadDepthFormat;
    targets.extent = maps.headImage().extent();
    targets.slots = maps.slots();
    static_assert(std::size(OccluderTargets{}.layers) == hp::gpu::OPACITY_MAX_LIGHTS);
    for (std::uint32_t slot = 0; slot < maps.slots(); ++slot) {
      const hp::render::HeadShadowView& view = lights->headViews[slot];
      targets.layers[slot] = maps.headImage().layerView(slot);
      targets.framed[slot] = view.params.x != 0.0f;  // off for a slot no light took, or with shadows off
      targets.viewProjection[slot] = convert::mat(view.viewProj);
    }
    return targets;
  });
}
Result<std::vector<std::uint8_t>> Renderer::pipelineCacheData() const noexcept {
  return guarded<std::vector<std::uint8_t>>("hairpipe::Renderer::pipelineCacheData",
                                            [&] { return implementation(impl_).pipelineCacheData(); });
}

}  // namespace hairpipe
