#include "compute/renderer/renderer.h"

#include <algorithm>
#include <utility>

#include "engine/vk/submit.h"

#include "engine/core/error.h"
#include "engine/core/shading/lut_cache.h"
#include "compute/renderer/frame_recorder.h"
#include "engine/vk/application_attachments.h"
#include "engine/vk/check.h"
#include "engine/vk/context.h"

namespace hp {
namespace {
const RendererSettings& validated(const vk::Context& ctx, const RendererSettings& s) {
  s.validate();
  const bool compute = resolveRasterMode(s.raster, ctx.properties().deviceType) == RasterMode::Compute;
  vk::requireAttachmentSupport(ctx, s.formats, compute);
  if (s.motionVectors && !compute)
    throw Error("RendererSettings.motionVectors needs the compute raster: the graphics raster writes no motion");
  const std::uint32_t outputs = ctx.properties().limits.maxFragmentOutputAttachments;
  if (s.velocityOutput.attachment >= 0 && std::uint32_t(s.velocityOutput.attachment) + 1 >= outputs)
    throw Error("RendererSettings.velocityOutput.attachment: colour location " + std::to_string(s.velocityOutput.attachment + 1) +
                " is past the " + std::to_string(outputs) + " fragment outputs of " + ctx.properties().deviceName);
  return s;
}
}  // namespace

Renderer::Renderer(const vk::Context& ctx, const RendererSettings& settings)
    : ctx_(ctx),
      settings_(validated(ctx, settings)),
      raster_(resolveRasterMode(settings.raster, ctx.properties().deviceType)),
      pipelines_(ctx, settings.pipelineCache),
      shadows_(std::make_unique<render::ShadowMaps>(ctx, settings.opacity, &pipelines_, settings.shadowedLights)),
      frameLights_(settings.framesInFlight) {}

// Retired instances go while every member is alive: their destructors tell the Renderer (forgetInstance).
// The raster targets first: they refer to instances, and nothing may draw from them any more.
Renderer::~Renderer() {
  for (const std::weak_ptr<RasterTarget>& weak : targets_)
    if (const std::shared_ptr<RasterTarget> target = weak.lock()) {
      target->raster_.reset();
      target->rebuild_.reset();
    }
  ownTarget_.reset();
  retired_.clear();
  retiredWithDeferred_.clear();
  deferred_.clear();
}

std::unique_ptr<HairInstance> Renderer::createInstance(const HairAsset& asset, const InstanceSettings& settings,
                                                       const glm::mat4& initialHead) {
  // Every upload of the instance (and of a new material's LUTs) in one batch.
  std::unique_ptr<HairInstance> instance;
  withUploads("create instance", [&] { instance.reset(new HairInstance(*this, asset, settings, initialHead)); });
  return instance;
}

void Renderer::withUploads(const std::string& name, const std::function<void()>& change) {
  const bool frameLoop = lastFrame_.has_value();
  vk::OneShotBatch batch(ctx_, name, frameLoop ? vk::OneShotBatch::Mode::Defer : vk::OneShotBatch::Mode::Submit);
  change();  // a failure unwinds past the batch, which discards what it recorded (for objects now gone)
  if (!frameLoop) return batch.submit();
  if (std::shared_ptr<vk::DeferredWork> work = batch.take()) deferred_.push_back(std::move(work));
}

void Renderer::executeDeferred(VkCommandBuffer cmd) {
  rebuildChangedTargets();
  if (deferred_.empty()) return;
  std::vector<VkCommandBuffer> buffers;
  for (const auto& work : deferred_) buffers.push_back(work->commandBuffer());
  ctx_.fn().vkCmdExecuteCommands(cmd, std::uint32_t(buffers.size()), buffers.data());
  for (auto& work : deferred_) retired_.push_back({lastFrame_, std::move(work)});
  for (auto& resource : retiredWithDeferred_) retired_.push_back({lastFrame_, std::move(resource)});
  deferred_.clear();
  retiredWithDeferred_.clear();
}

void Renderer::requireNoDeferredWork(const char* call) const {
  if (!deferred_.empty())
    throw Error(std::string("Renderer::") + call + ": a change made since this frame's recordShadows (or its "
                "recordChanges) waits for the next frame's recordChanges, recordUpdate or recordShadows (make changes "
                "between frames)");
}

void Renderer::requireTargetExtent(const char* what, VkExtent2D extent, const ComputeRaster& target) {
  if (extent.width != target.extent().width || extent.height != target.extent().height)
    throw Error(std::string(what) + " " + std::to_string(extent.width) + "x" + std::to_string(extent.height) +
                " differs from the raster target's " + std::to_string(target.extent().width) + "x" +
                std::to_string(target.extent().height));
}

void Renderer::requireShadows(const char* call, std::uint64_t frame) const {
  if (shadowsFrame_ != frame)
    throw Error(std::string("Renderer::") + call + ": frame " + std::to_string(frame) +
                " has no recordShadows before it (its lights, its shadow maps and the barrier that makes the strands "
                "drawable come from that call, after recordUpdate)");
}

void Renderer::requireComputedStrands(const char* call, std::span<HairInstance* const> instances) {
  for (std::size_t n = 0; n < instances.size(); ++n)
    if (instances[n] && !instances[n]->geometry_->computed)
      throw Error(std::string("Renderer::") + call + ": instance " + std::to_string(n) +
                  " has strands no recordUpdate has computed yet (new since createInstance or setDensity): give it to "
                  "a recordUpdate first");
}

void Renderer::destroyInstance(std::unique_ptr<HairInstance> instance) {
  if (!instance) return;
  // Retired first: if rebuilding a raster target without it fails, it is still kept for the frames in flight.
  const std::shared_ptr<HairInstance> retired(std::move(instance));
  retire(retired);
  instanceChanged(*retired, true);
}

std::shared_ptr<ComputeRaster> Renderer::buildRaster(VkExtent2D extent, VkImageView depth,
                                                     std::span<HairInstance* const> instances,
                                                     const ComputeRaster* previous) {
  if (raster_ != RasterMode::Compute) throw Error("Renderer: a raster target needs the compute raster (the raster mode is not compute)");
  if (depth == VK_NULL_HANDLE) throw Error("Renderer: the depth view is VK_NULL_HANDLE");
  for (const HairInstance* i : instances)
    if (!i || &i->renderer_ != this) throw Error("Renderer: an instance is null or belongs to another Renderer");
  std::shared_ptr<ComputeRaster> raster;
  withUploads("raster target", [&] {
    raster = std::make_shared<ComputeRaster>(ctx_, settings_, *shadows_, extent, depth, instances, pipelines_.cache(),
                                             previous);
  });
  return raster;
}

template <class F>
void Renderer::forEachTarget(F&& f) {
  std::erase_if(targets_, [](const std::weak_ptr<RasterTarget>& t) { return t.expired(); });
  for (const std::weak_ptr<RasterTarget>& weak : targets_)
    if (const std::shared_ptr<RasterTarget> target = weak.lock()) f(*target);
}

// The target and its place in targets_ are made before the raster: once the raster is built (its uploads
// batched), nothing may throw, or it would be destroyed while those uploads still write it.
void Renderer::setRasterTarget(VkExtent2D extent, VkImageView depth, std::span<HairInstance* const> instances) {
  if (!ownTarget_) {
    targets_.reserve(targets_.size() + 1);
    auto target = std::make_shared<RasterTarget>(nullptr, "call setRasterTarget() again");
    target->raster_ = buildRaster(extent, depth, instances);
    ownTarget_ = std::move(target);
    targets_.push_back(ownTarget_);
    return;
  }
  std::shared_ptr<ComputeRaster> raster = buildRaster(extent, depth, instances, ownTarget_->raster_.get());
  if (ownTarget_->raster_) retire(ownTarget_->raster_);  // frames in flight may still use its buffers and descriptors
  ownTarget_->raster_ = std::move(raster);
  ownTarget_->rebuild_.reset();  // the application's new set of instances replaces a waiting rebuild's
  ownTarget_->failure_.clear();
}

std::shared_ptr<RasterTarget> Renderer::createRasterTarget(VkExtent2D extent, VkImageView depth,
                                                          std::span<HairInstance* const> instances) {
  targets_.reserve(targets_.size() + 1);
  auto target = std::make_shared<RasterTarget>(nullptr, "create another with createRasterTarget()");
  target->raster_ = buildRaster(extent, depth, instances);
  targets_.push_back(target);
  return target;
}

void Renderer::destroyRasterTarget(const std::shared_ptr<RasterTarget>& target) {
  if (!target) return;
  if (target->raster_) retire(std::move(target->raster_));
  target->raster_.reset();
  target->rebuild_.reset();
  std::erase_if(targets_, [&](const std::weak_ptr<RasterTarget>& t) { return t.lock() == target; });
}

// Every target holding the instance is rebuilt, each on its own. In the frame loop the rebuild waits for the
// next frame's first record call (rebuildChangedTargets): this frame's draws and shadows already hold the
// instance, and several changes of one frame then cost one rebuild. Before it, a failed rebuild leaves that
// target empty, the others are still rebuilt, and the first failure is thrown once all were tried.
void Renderer::instanceChanged(const HairInstance& instance, bool removed) {
  std::exception_ptr failure;
  forEachTarget([&](RasterTarget& target) {
    if (!target.holds(&instance)) return;
    try {  // (the list too: nothing may escape a setter after its swap)
      std::vector<HairInstance*> kept = target.rebuild_ ? *target.rebuild_ : target.raster_->instances();
      if (removed) std::erase(kept, &instance);
      if (lastFrame_)
        target.rebuild_ = std::move(kept);
      else
        rebuildTarget(target, kept);
    } catch (...) {
      if (!failure) failure = std::current_exception();
    }
  });
  if (failure) std::rethrow_exception(failure);
}

void Renderer::rebuildTarget(RasterTarget& target, std::span<HairInstance* const> instances) {
  const std::shared_ptr<ComputeRaster> old = std::move(target.raster_);
  target.raster_.reset();
  target.rebuild_.reset();
  if (!old) return;
  retire(old);
  if (!instances.empty()) target.raster_ = buildRaster(old->extent(), old->depth(), instances, old.get());
}

void Renderer::rebuildChangedTargets() {
  forEachTarget([&](RasterTarget& target) {
    if (!target.rebuild_) return;
    const std::vector<HairInstance*> instances = *target.rebuild_;
    try {
      rebuildTarget(target, instances);
      target.failure_.clear();
    } catch (const vk::DeviceLost&) {
      throw;  // the application's recovery needs to see it
    } catch (const std::exception& e) {
      target.failure_ = e.what();  // the target is empty: recordRaster says why
    }
  });
}

void Renderer::materialChanged(const HairInstance& instance) {
  forEachTarget([&](RasterTarget& target) {
    if (target.holds(&instance) && target.raster_ && target.raster_->holds(&instance))
      target.raster_->shadingChanged(&instance);
  });
}

void Renderer::forgetInstance(const HairInstance& instance) noexcept {
  for (const std::weak_ptr<RasterTarget>& weak : targets_) {
    const std::shared_ptr<RasterTarget> target = weak.lock();
    // A target waiting to be rebuilt without it is not dropped: its raster draws nothing before the rebuild.
    if (!target || !target->holds(&instance)) continue;
    retire(std::move(target->raster_));  // only allocates: out of memory here ends the process (noexcept)
    target->raster_.reset();
    target->rebuild_.reset();
  }
}

const RasterTarget& Renderer::ownTarget() const {
  if (!ownTarget_) throw Error("Renderer: the compute raster needs setRasterTarget() before recording");
  return *ownTarget_;
}

void Renderer::recordRaster(VkCommandBuffer cmd, std::uint64_t frame, const View& view, RasterTarget& target,
                            vk::GpuProfiler* profiler) {
  requireNoDeferredWork("recordRaster");
  ComputeRaster& t = target.raster();
  view.validate(settings_.maxViewsPerFrame, settings_.formats.reversedDepth);
  // The strands' width in pixels comes from the view's extent, the tiles from the target's: they must agree.
  requireTargetExtent("Renderer::recordRaster: View.extent", view.extent, t);
  requireShadows("recordRaster", frame);
  requireComputedStrands("recordRaster", t.instances());
  beginFrame(frame, t.instances());
  for (HairInstance* i : t.instances()) i->noteViewFraction(frame, i->lodFraction(view.camera.position));
  t.record(cmd, {recordEpoch_, frame}, view, frameLights_[frame % settings_.framesInFlight], profiler);
}

void Renderer::recordComposite(VkCommandBuffer cmd, VkExtent2D extent, const RasterTarget& target,
                               vk::GpuProfiler* profiler) const {
  requireNoDeferredWork("recordComposite");
  const ComputeRaster& t = target.raster();
  // The composite fetches the hair image at each fragment's pixel: an attachment of another size would read
  // past the image or leave hair out.
  requireTargetExtent("Renderer::recordComposite: the extent", extent, t);
  // Its image is the frame recordRaster last drew: without this frame's, an older frame's hair would be
  // composited (the hair a frame behind its heads).
  if (!lastFrame_ || t.drawnFrame() != ComputeRaster::FrameId{recordEpoch_, *lastFrame_})
    throw Error("Renderer::recordComposite: the raster target has not drawn this frame (recordRaster comes first)");
  t.recordComposite(cmd, extent, profiler);
}

void Renderer::requireMotionVectors() const {
  if (!settings_.motionVectors) throw Error("Renderer::motionImage: RendererSettings::motionVectors is off");
}

const vk::Image& Renderer::motionImage(const RasterTarget& target) const {
  requireMotionVectors();
  return target.raster().motionImage();
}

const vk::Image& Renderer::motionImage() const {
  requireMotionVectors();  // before asking for the target: the settings are the first refusal
  return motionImage(ownTarget());
}

const vk::Image& Renderer::rasterImage() const { return ownTarget().raster().image(); }
compute::RasterStats Renderer::rasterStats() const { return ownTarget().raster().readStats(); }
std::vector<glm::vec2> Renderer::rasterMotion() const {
  motionImage();  // the same refusals, in the same order
  return ownTarget().raster().readMotion();
}
std::vector<float> Renderer::rasterCoverage() const { return ownTarget().raster().readCoverage(); }

std::shared_ptr<render::MarschnerTextures> Renderer::cachedMarschner(const HairMaterial& material, LutMode mode) {
  std::erase_if(luts_, [](const Lut& l) { return l.textures.expired(); });
  for (const Lut& l : luts_)
    if (l.mode == mode && l.material == material) return l.textures.lock();
  return nullptr;
}

std::shared_ptr<render::MarschnerTextures> Renderer::marschner(const HairMaterial& material, LutMode mode) {
  if (auto cached = cachedMarschner(material, mode)) return cached;
  return marschnerFrom(*sharedLut(mode, material), sharedMarschnerParams(mode, material).get());
}

std::shared_ptr<render::MarschnerTextures> Renderer::marschnerFrom(const MarschnerLut& lut,
                                                                   const gpu::MarschnerParams* params) {
  if (auto cached = cachedMarschner(lut.material, lut.mode)) return cached;
  auto textures = std::make_shared<render::MarschnerTextures>(ctx_, lut, LutBuildOptions{}, params);
  luts_.push_back({lut.material, lut.mode, textures});
  return textures;
}

std::shared_ptr<const render::SkinTransferBuffer> Renderer::skinTransfer(const HeadMesh& mesh) {
  if (mesh.positions.empty()) return nullptr;
  const std::uint64_t key = render::fingerprint(mesh);
  std::erase_if(transfers_, [](const Transfer& t) { return t.buffer.expired(); });
  for (const Transfer& t : transfers_) {
    auto buffer = t.buffer.lock();
    if (buffer && t.fingerprint == key && buffer->vertexCount() == mesh.positions.size()) return buffer;
  }
  auto buffer = std::make_shared<const render::SkinTransferBuffer>(ctx_, mesh, key);
  transfers_.push_back({key, buffer});
  return buffer;
}

void Renderer::applyReadyMaterials(std::span<HairInstance* const> instances) {
  for (HairInstance* i : instances) i->applyReadyMaterial();
}

void Renderer::retire(std::shared_ptr<void> resource) {
  // While changes' work waits for the next frame, what is retired now may be what that work writes (a
  // second setMaterial before the frame retires the first one's tables): it stays until that frame is done.
  if (!deferred_.empty()) {
    retiredWithDeferred_.push_back(std::move(resource));
    return;
  }
  if (!lastFrame_) return;  // nothing recorded yet: nothing can be in flight
  retired_.push_back({lastFrame_, std::move(resource)});
}

void Renderer::setOpacityTuning(const render::OpacitySettings& opacity) {
  const render::OpacitySettings& current = settings_.opacity;  // as asked for (the maps' may differ in `deep`)
  if (opacity.resolution != current.resolution || opacity.format != current.format ||
      opacity.headShadowResolution != current.headShadowResolution || opacity.raster != current.raster ||
      opacity.deep != current.deep)
    throw Error("setOpacityTuning: the opacity maps' resolution, format, raster and depth mode are fixed for a Renderer");
  render::validate(opacity);
  shadows_->setTuning(opacity);
  settings_.opacity = opacity;
}

void Renderer::beginFrame(std::uint64_t frame, std::span<HairInstance* const> instances) {
  for (const HairInstance* i : instances)
    if (!i || &i->renderer_ != this) throw Error("Renderer: an instance is null or belongs to another Renderer");
  // Retirement counts frames: a number that went back would free what frames in flight still read (after
  // releaseRetired nothing is in flight and nothing retired: the numbering may start again).
  if (lastFrame_ && frame < *lastFrame_ && !numberingRestarts_)
    throw Error("Renderer: frame " + std::to_string(frame) + " comes after frame " + std::to_string(*lastFrame_) +
                " was recorded: frame numbers must not go back (after releaseRetired they may start again)");
  if (!lastFrame_ || frame > *lastFrame_ || numberingRestarts_) lastFrame_ = frame;
  numberingRestarts_ = false;
  // Frame `frame - framesInFlight` is complete (the application waited for it): what was retired by then goes.
  std::erase_if(retired_, [&](const Retired& r) { return !r.after || frame >= *r.after + settings_.framesInFlight; });
}

void Renderer::recordChanges(VkCommandBuffer cmd, std::uint64_t frame, std::span<HairInstance* const> instances) {
  beginFrame(frame, instances);
  applyReadyMaterials(instances);
  executeDeferred(cmd);
  changesFrame_ = frame;
}

void Renderer::applyChanges(VkCommandBuffer cmd, std::uint64_t frame, std::span<HairInstance* const> instances) {
  if (changesFrame_ == frame) return;  // the application's recordChanges took them
  applyReadyMaterials(instances);
  executeDeferred(cmd);
}

void Renderer::recordUpdate(VkCommandBuffer cmd, std::uint64_t frame, std::span<HairInstance* const> instances,
                            vk::GpuProfiler* profiler) {
  beginFrame(frame, instances);
  applyChanges(cmd, frame, instances);
  std::vector<UpdateWork> work;
  work.reserve(instances.size());
  for (HairInstance* i : instances)
    work.push_back({&i->simulate_, i->motion_, &i->geometry_->tessellate, &i->geometry_->interpolate,
                    &i->geometry_->buffers, i->geometry_->previousKept});
  recordUpdatePasses(ctx_, cmd, work, profiler);
  for (HairInstance* i : instances) {
    i->geometry_->previousKept = i->geometry_->buffers.keepsPrevious();
    i->geometry_->computed = true;
    i->recordCharacterCopies(ctx_, cmd);
  }
}

void Renderer::recordShadows(VkCommandBuffer cmd, std::uint64_t frame, std::span<const LightSpec> lights,
                             std::span<HairInstance* const> instances, vk::GpuProfiler* profiler) {
  render::FrameLights frameLights = render::assignShadowSlots(lights, shadows_->slots());  // validates them
  requireComputedStrands("recordShadows", instances);
  beginFrame(frame, instances);
  applyChanges(cmd, frame, instances);
  render::FrameLights& current = frameLights_[frame % settings_.framesInFlight];
  current = std::move(frameLights);
  shadowsFrame_ = frame;
  makeStrandsDrawable(ctx_, cmd);
  if (!shadows_->settings().enabled) return;
  render::HeadSphere heads;
  for (HairInstance* i : instances) heads = render::enclose(heads, i->geometry_->opacity.headSphere(i->headToWorld()));
  for (std::uint32_t slot = 0; slot < current.shadowed(); ++slot)
    recordLightShadows(cmd, current, slot, instances, heads, profiler);
  recordHeadBounce(cmd, current, instances, profiler);
}

void Renderer::recordLightShadows(VkCommandBuffer cmd, render::FrameLights& lights, std::uint32_t slot,
                                  std::span<HairInstance* const> instances, const render::HeadSphere& heads,
                                  vk::GpuProfiler* profiler) {
  const render::OpacitySettings& opacity = shadows_->settings();
  const LightSpec framed = render::shadowFrustum(lights.lights[lights.lightOfSlot(slot)], heads);
  lights.headViews[slot] = render::headShadowView(framed, heads, opacity.headShadowResolution);
  std::vector<ShadowCaster> casters;
  float widest = 0.0f;
  for (HairInstance* i : instances) {
    const render::LookSettings& look = i->settings_.look;
    // Thinned strands (a far view's level of detail, or the maps' strand budget) are widened by 1 / fraction.
    const ShadowSample sample =
        shadowSample(i->shadowLodFraction(), i->strands().layout().strandCount, opacity.shadowStrands);
    const float width = look.strandWidth / sample.fraction;
    casters.push_back({&i->geometry_->bounds, &i->geometry_->opacity, i->headToWorld(),
                       glm::vec2(width, look.tipWidthFraction), sample.drawn});
    widest = std::max(widest, width);
  }
  compute::BoundsFraming framing;
  framing.resolution = opacity.resolution;
  framing.marginWorld = 0.5f * widest * gpu::WIDTH_SCALE_MAX;
  compute::ShadowLight shadowLight = shadowLightOf(framed);
  shadowLight.slot = slot;
  recordShadowPasses(ctx_, cmd, *shadows_, casters, shadowLight, framing, profiler, lights.headViews[slot]);
}

void Renderer::recordHeadBounce(VkCommandBuffer cmd, const render::FrameLights& lights,
                                std::span<HairInstance* const> instances, vk::GpuProfiler* profiler) {
  const bool wanted = std::any_of(instances.begin(), instances.end(),
                                  [](const HairInstance* i) { return i->settings_.look.skinBounce; });
  // No shadowed light, no head (or shadows off): nothing to bounce from.
  if (!wanted || lights.shadowed() == 0 || lights.headViews[0].params.x == 0.0f) return;
  if (profiler) profiler->begin(cmd, "head bounce");
  // The blocks the bounce draws read: the lights, colours and opacity settings, the map's framing.
  for (HairInstance* i : instances) {
    const gpu::RenderFrame block = i->frameBlock(CameraMatrices{}, {1, 1}, lights, i->settings_.look);
    const VkBuffer buffer = i->bounceFrame_.handle();
    // The last frame's readers: the map's draw and the bounce along the strands.
    vk::bufferBarrier(ctx_, cmd, buffer, vk::BufferUse::GraphicsRead, vk::BufferUse::TransferDst);
    vk::bufferBarrier(ctx_, cmd, buffer, vk::BufferUse::ComputeRead, vk::BufferUse::TransferDst);
    ctx_.fn().vkCmdUpdateBuffer(cmd, buffer, 0, sizeof(block), &block);
    vk::bufferBarrier(ctx_, cmd, buffer, vk::BufferUse::TransferDst, vk::BufferUse::GraphicsRead);
    vk::bufferBarrier(ctx_, cmd, buffer, vk::BufferUse::TransferDst, vk::BufferUse::ComputeRead);
  }
  const render::HeadBounceMap& map = shadows_->bounceMap();
  map.begin(cmd);
  for (HairInstance* i : instances) i->bounce_->draw(cmd, i->headToWorld());
  map.end(cmd);
  if (profiler) profiler->end(cmd);
  // Every strand of each instance that takes the bounce (StrandBouncePass::record).
  if (profiler) profiler->begin(cmd, "strand bounce");
  std::vector<const render::StrandBouncePass*> passes;
  for (HairInstance* i : instances)
    if (i->settings_.look.skinBounce) passes.push_back(&i->geometry_->bounce);
  recordStrandBounce(ctx_, cmd, *shadows_, passes);
  if (profiler) profiler->end(cmd);
}

void Renderer::recordDraw(VkCommandBuffer cmd, std::uint64_t frame, const View& view,
                          std::span<HairInstance* const> instances, vk::GpuProfiler* profiler) {
  requireNoDeferredWork("recordDraw");
  view.validate(settings_.maxViewsPerFrame, settings_.formats.reversedDepth);
  requireShadows("recordDraw", frame);
  requireComputedStrands("recordDraw", instances);
  beginFrame(frame, instances);
  const render::FrameLights& lights = frameLights_[frame % settings_.framesInFlight];
  // Every instance's block first: a view index another view of this frame took is refused before anything is
  // written or recorded.
  std::vector<gpu::RenderFrame> blocks;
  std::vector<float> fractions;
  for (HairInstance* i : instances) {
    fractions.push_back(i->lodFraction(view.camera.position));
    blocks.push_back(i->frameBlock(view.camera, view.extent, lights, lodLook(i->settings_.look, fractions.back())));
    render::setViewMotion(blocks.back(), view.extent, view.jitter, view.previousViewProj);
    i->checkFrameBlock(frame, view.index, blocks.back());
  }
  for (std::size_t n = 0; n < instances.size(); ++n) {
    HairInstance* i = instances[n];
    const float fraction = fractions[n];
    i->noteViewFraction(frame, fraction);
    i->writeFrameBlock(frame, view.index, blocks[n]);
    const std::uint32_t offset = i->frameOffset(frame, view.index);
    if (profiler) profiler->beginInRendering(cmd, "head");
    i->head_->draw(cmd, view.extent, i->headToWorld(), offset, lights.lights.size() <= 1);
    if (profiler) profiler->end(cmd);
    if (!view.ribbons || raster_ == RasterMode::Compute) continue;
    if (profiler) profiler->beginInRendering(cmd, "shade");
    i->strandPass_->draw(cmd, view.extent, view.lines, offset, i->lodStrands(fraction));
    if (profiler) profiler->end(cmd);
  }
}
}  // namespace hp
