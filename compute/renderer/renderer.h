#pragma once
// Contract: what hairpipe shares per device and attachment formats: the pipelines (one PipelineLibrary),
// the Marschner LUT textures (cached by material and mode), the opacity shadow maps of the frame's shadowed
// lights and the retirement queue of frames in flight. It creates HairInstances (one per head) and records
// their frames into the application's command buffers:
//   recordUpdate(cmd, frame, instances)         outside rendering: simulate -> tessellate -> interpolate
//   recordShadows(cmd, frame, lights, instances) outside rendering: the frame's lights (at most
//                                               RENDER_MAX_LIGHTS); per shadowed light (a slot each, up to
//                                               settings.shadowedLights, in order) one framing over all
//                                               instances, every instance's strands and head in that light's
//                                               opacity maps (heads shadow each other); its own
//                                               vkCmdBeginRendering on its maps
//   recordDraw(cmd, frame, view, instances)     inside the application's vkCmdBeginRendering (attachments
//                                               matching settings.formats): heads and (graphics raster)
//                                               hair ribbons
// With the compute raster (settings.raster resolves to Compute), after setRasterTarget(extent, depth,
// instances) outside the frame loop, the hair of those instances is drawn by
//   recordDraw(cmd, frame, view, instances)     heads only; the application ends the rendering and puts
//                                               its depth image in ImageUse::ComputeSampled
//   recordRaster(cmd, frame, view)              outside rendering: the compute rasterizer into rasterImage()
//   recordComposite(cmd, extent)                inside a rendering of the same attachments: hair over colour
// in that order, per view of a frame; each view with the compute raster has its own target (setRasterTarget's
// for one, createRasterTarget's for more, each with its depth image); recordDraw once per view (View::index
// distinct per view of a frame), all views reusing the frame's shadows. Stages touched: COMPUTE_SHADER, COPY/CLEAR, VERTEX_SHADER,
// FRAGMENT_SHADER, early/late fragment tests, colour output; in the application's attachments only colour
// and depth. hairpipe never waits on a queue inside these calls.
//
// Frames in flight: `frame` is the application's frame number, increasing by one per frame (it may start
// anywhere). When it records frame F, the application has waited for the completion of frame
// F - framesInFlight (its own fences), and it submits frames in order on one queue. Per-frame constants
// live in a ring of framesInFlight slots written by the host at record time; resources replaced by a
// setter (material, strands, look) are retired and destroyed by a record call of frame
// retiredAt + framesInFlight, so nothing needs a device idle. destroyInstance() retires an instance the
// same way. The Renderer must outlive its instances and the GPU's use of everything it recorded.
//
// Errors (hp::Error): the constructor, createInstance and the instance setters (invalid parameters, device
// limits, out of memory); recordShadows for an invalid light or too many and recordDraw for an invalid view (checked
// before anything is recorded); any record call for an instance of another Renderer; setRasterTarget and
// createRasterTarget (graphics mode, no instance, device limits) and recordRaster/recordComposite/rasterImage
// without a raster target or with an empty one (none set, its instances destroyed, a rebuild failed, or
// dropped because one of its instances was destroyed without destroyInstance); recordDraw, recordRaster and recordComposite while a change's work waits for the next
// recordUpdate or recordShadows; recordDraw and recordRaster before the frame's recordShadows; recordShadows,
// recordDraw and recordRaster for an instance whose strands no recordUpdate has computed; recordComposite at an
// extent other than its target's or before the frame's recordRaster of it. Nothing else in the record calls throws. In the frame loop, an instance
// destroyed or given new strands has its raster targets rebuilt by the next frame's first recordUpdate or
// recordShadows (the current frame draws the target as it was).
#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "compute/head/skin_transfer_buffer.h"
#include "compute/renderer/compute_raster.h"
#include "compute/renderer/raster_target.h"
#include "compute/renderer/hair_instance.h"
#include "compute/shadows/shadow_maps.h"
#include "compute/renderer/renderer_settings.h"
#include "engine/vk/pipeline_library.h"
#include "engine/vk/submit.h"
#include "engine/vk/profiler.h"

namespace hp {
class Renderer {
 public:
  Renderer(const vk::Context& ctx, const RendererSettings& settings);
  ~Renderer();
  Renderer(const Renderer&) = delete;
  Renderer& operator=(const Renderer&) = delete;

  std::unique_ptr<HairInstance> createInstance(const HairAsset& asset, const InstanceSettings& settings,
                                               const glm::mat4& initialHead = glm::mat4(1.0f));
  // Destroys the instance after the frames that may still use it are done.
  void destroyInstance(std::unique_ptr<HairInstance> instance);

  // Optional, before the frame's other record calls, in a primary command buffer outside any rendering: the
  // changes' waiting work (new materials whose tables are ready for `instances`, uploads, raster target
  // rebuilds; vkCmdExecuteCommands of secondaries). That frame's recordUpdate and recordShadows then execute
  // none, so they may be recorded into secondary command buffers; changes made after it wait for the next frame.
  void recordChanges(VkCommandBuffer cmd, std::uint64_t frame, std::span<HairInstance* const> instances);
  void recordUpdate(VkCommandBuffer cmd, std::uint64_t frame, std::span<HairInstance* const> instances,
                    vk::GpuProfiler* profiler = nullptr);
  void recordShadows(VkCommandBuffer cmd, std::uint64_t frame, std::span<const LightSpec> lights,
                     std::span<HairInstance* const> instances, vk::GpuProfiler* profiler = nullptr);
  void recordShadows(VkCommandBuffer cmd, std::uint64_t frame, const LightSpec& light,
                     std::span<HairInstance* const> instances, vk::GpuProfiler* profiler = nullptr) {
    recordShadows(cmd, frame, std::span(&light, 1), instances, profiler);
  }
  void recordDraw(VkCommandBuffer cmd, std::uint64_t frame, const View& view,
                  std::span<HairInstance* const> instances, vk::GpuProfiler* profiler = nullptr);

  // Compute raster only, outside the frame loop: rasterize `instances` (all in one set of tile lists)
  // into an image of `extent` against the depth image view `depth`, which has the settings'
  // AttachmentFormats sample count: multisampled, the head's edges over the hair are antialiased by its
  // samples (the composite then draws into attachments of that count). Rebuilt by the Renderer when one of
  // them changes strands or is destroyed; a material change rebinds its tables from the next frame on (a
  // change between two views of a frame shows in the next frame); call again for another extent or set.
  // This is the Renderer's own target, which the calls without a target draw; createRasterTarget makes more.
  void setRasterTarget(VkExtent2D extent, VkImageView depth, std::span<HairInstance* const> instances);
  // Another target like setRasterTarget's, for another view of a frame (its own extent and depth image: a
  // second eye, a split screen, a mirror). The Renderer rebuilds it as it does its own while the caller holds
  // it; destroyRasterTarget retires it after the frames that may use it.
  std::shared_ptr<RasterTarget> createRasterTarget(VkExtent2D extent, VkImageView depth,
                                                   std::span<HairInstance* const> instances);
  void destroyRasterTarget(const std::shared_ptr<RasterTarget>& target);
  // After recordDraw of the target's view (heads drawn, depth in ImageUse::ComputeSampled), with the
  // lights recordShadows was given; leaves the target's image in ImageUse::FragmentSampled. View::index is
  // unused: a target draws one view of a frame (another view takes another target).
  void recordRaster(VkCommandBuffer cmd, std::uint64_t frame, const View& view, RasterTarget& target,
                    vk::GpuProfiler* profiler = nullptr);
  void recordRaster(VkCommandBuffer cmd, std::uint64_t frame, const View& view, vk::GpuProfiler* profiler = nullptr) {
    recordRaster(cmd, frame, view, const_cast<RasterTarget&>(ownTarget()), profiler);
  }
  void recordComposite(VkCommandBuffer cmd, VkExtent2D extent, const RasterTarget& target,
                       vk::GpuProfiler* profiler = nullptr) const;
  void recordComposite(VkCommandBuffer cmd, VkExtent2D extent, vk::GpuProfiler* profiler = nullptr) const {
    recordComposite(cmd, extent, ownTarget(), profiler);
  }
  RasterMode raster() const { return raster_; }
  // The Renderer's own target's (setRasterTarget):
  const vk::Image& rasterImage() const;
  compute::RasterStats rasterStats() const;  // blocking readback of the last frame's tile-list statistics
  // Blocking readback of the last frame's hair coverage per pixel (rows top to bottom), averaged over the
  // depth's samples (compute::StrandRasterPass::readCoverage).
  std::vector<float> rasterCoverage() const;
  // With settings.motionVectors: the hair's motion image of a raster target (RG16F, pixels, current
  // unjittered minus previous, coverage-weighted; 0 without hair), left by recordRaster in
  // ImageUse::FragmentSampled like rasterImage(); and its blocking readback (x, y per pixel, rows top to bottom).
  const vk::Image& motionImage(const RasterTarget& target) const;
  const vk::Image& motionImage() const;
  std::vector<glm::vec2> rasterMotion() const;

  // Shadow tuning that keeps the maps' resolution and format (strand/head opacity, k, bias, on/off).
  void setOpacityTuning(const render::OpacitySettings& opacity);

  const RendererSettings& settings() const { return settings_; }
  const vk::Context& context() const { return ctx_; }
  const render::ShadowMaps& shadows() const { return *shadows_; }
  // The lights recordShadows was given for `frame`, with their slots and head map framings (for a caller's
  // own frame block).
  const render::FrameLights& lightsOf(std::uint64_t frame) const { return frameLights_[frame % settings_.framesInFlight]; }
  vk::PipelineLibrary& pipelines() { return pipelines_; }
  std::vector<std::uint8_t> pipelineCacheData() const { return pipelines_.cacheData(); }
  // The LUT textures of a material and mode, built once and shared while any instance uses them.
  std::shared_ptr<render::MarschnerTextures> marschner(const HairMaterial& material, LutMode mode);
  // The cached textures of a material and mode, or null (nothing built).
  std::shared_ptr<render::MarschnerTextures> cachedMarschner(const HairMaterial& material, LutMode mode);
  // Textures from tables built elsewhere (a worker thread), cached like marschner()'s.
  std::shared_ptr<render::MarschnerTextures> marschnerFrom(const MarschnerLut& lut,
                                                           const gpu::MarschnerParams* params = nullptr);
  // A head mesh's skin transfer, computed once and shared while any instance draws that mesh (keyed by its
  // contents); null for an empty mesh.
  std::shared_ptr<const render::SkinTransferBuffer> skinTransfer(const HeadMesh& mesh);
  // Whether a frame was recorded: changes then defer their uploads, and new LUTs are built off this thread.
  bool inFrameLoop() const { return lastFrame_.has_value(); }
  // Keeps `resource` alive until the frames that may use it now are done.
  void retire(std::shared_ptr<void> resource);
  // Runs `change` (construction or a setter) with its device work batched: before the first frame, one
  // submission waited on; after it (the frame loop), recorded into a deferred batch that the next
  // recordUpdate or recordShadows executes in the application's command buffer: no submission, no wait.
  // `change` must not fail after it swapped in an object whose uploads it recorded: a failure discards
  // them. (The setters swap last; a raster target follows after the change, in a batch of its own.)
  void withUploads(const std::string& name, const std::function<void()>& change);
  std::size_t retiredCount() const { return retired_.size(); }
  // The caller waited for every frame recorded so far: what was retired is destroyed now instead of by a
  // later record call (a level unloaded, the Renderer kept). What changes' waiting uploads need stays.
  // The frame numbers may then start again anywhere (an application that resets its counter).
  void releaseRetired() {
    retired_.clear();
    numberingRestarts_ = true;
    ++recordEpoch_;
    shadowsFrame_.reset();
    changesFrame_.reset();
  }
  // The lights and heads' depth map framings of the current frame's recordShadows: none before it (a later
  // frame's recordUpdate, or a restarted numbering, makes the latest one another frame's).
  const render::FrameLights* currentShadowLights() const {
    if (!shadowsFrame_ || shadowsFrame_ != lastFrame_) return nullptr;
    return &frameLights_[*shadowsFrame_ % settings_.framesInFlight];
  }
  // How many times the frame numbering may have started again (releaseRetired): a frame number means the
  // same frame only within one epoch.
  std::uint64_t recordEpoch() const { return recordEpoch_; }

 private:
  friend class HairInstance;
  void beginFrame(std::uint64_t frame, std::span<HairInstance* const> instances);
  // Instances whose new material's tables a worker finished take them (before the frame's deferred work).
  void applyReadyMaterials(std::span<HairInstance* const> instances);
  // An instance's strands changed, or it goes (`removed`): a raster target holding it is rebuilt (in the frame
  // loop at the next frame's first record call).
  void instanceChanged(const HairInstance& instance, bool removed = false);
  // The target's raster rebuilt for `instances` (the old one retired; none: the target is empty).
  void rebuildTarget(RasterTarget& target, std::span<HairInstance* const> instances);
  // The rebuilds changes in the frame loop left waiting, before the deferred work is executed (a failed one
  // leaves its target empty, with the reason for recordRaster's refusal).
  void rebuildChangedTargets();
  // An instance's material changed: a raster target holding it rebinds its LUTs slot by slot (not rebuilt).
  void materialChanged(const HairInstance& instance);
  // An instance destroyed without destroyInstance(): a raster target holding it is dropped (retired, not
  // rebuilt: nothing may throw here); recordRaster then asks for setRasterTarget().
  void forgetInstance(const HairInstance& instance) noexcept;
  // setRasterTarget's (throws before it was called).
  const RasterTarget& ownTarget() const;
  // Checks a target's instances and builds its raster (uploads batched by withUploads).
  // `previous`: the raster the new one replaces, if any (its growing lists' size carries over).
  std::shared_ptr<ComputeRaster> buildRaster(VkExtent2D extent, VkImageView depth, std::span<HairInstance* const> instances,
                                             const ComputeRaster* previous = nullptr);
  // f(RasterTarget&) for each target someone still holds (the own one and createRasterTarget's), forgetting
  // the others; allocates nothing (the material and strand changes that call it must not fail after their swap).
  template <class F>
  void forEachTarget(F&& f);
  void requireMotionVectors() const;
  // The deferred work of changes since the last frame into `cmd` (outside any rendering), retired after it.
  void executeDeferred(VkCommandBuffer cmd);
  // recordUpdate / recordShadows: ready materials applied and the deferred work executed, unless the frame's
  // recordChanges did it.
  void applyChanges(VkCommandBuffer cmd, std::uint64_t frame, std::span<HairInstance* const> instances);
  // recordDraw / recordRaster: every change's work was executed (a change between a frame's record calls
  // would draw resources not yet uploaded).
  void requireNoDeferredWork(const char* call) const;
  // recordRaster / recordComposite: `extent` is the target's ("<what> WxH differs from the raster target's WxH").
  static void requireTargetExtent(const char* what, VkExtent2D extent, const ComputeRaster& target);
  // recordDraw / recordRaster: this frame's recordShadows came first (its lights, and the barrier that makes the
  // strands drawable).
  void requireShadows(const char* call, std::uint64_t frame) const;
  // Every instance's strands were computed by a recordUpdate (a new instance's or setDensity's buffers hold no
  // positions before it).
  static void requireComputedStrands(const char* call, std::span<HairInstance* const> instances);
  // The heads into the head bounce map when an instance's look asks for the skin's bounce (after the shadows).
  void recordHeadBounce(VkCommandBuffer cmd, const render::FrameLights& lights,
                        std::span<HairInstance* const> instances, vk::GpuProfiler* profiler);
  // One shadowed light's maps over every instance (its slot's opacity maps and head depth map).
  void recordLightShadows(VkCommandBuffer cmd, render::FrameLights& lights, std::uint32_t slot,
                          std::span<HairInstance* const> instances, const render::HeadSphere& heads,
                          vk::GpuProfiler* profiler);

  struct Lut {
    HairMaterial material;
    LutMode mode;
    std::weak_ptr<render::MarschnerTextures> textures;
  };
  struct Transfer {
    std::uint64_t fingerprint;
    std::weak_ptr<const render::SkinTransferBuffer> buffer;
  };
  struct Retired {
    std::optional<std::uint64_t> after;  // last frame recorded when it was retired
    std::shared_ptr<void> resource;
  };

  const vk::Context& ctx_;
  RendererSettings settings_;
  RasterMode raster_;
  vk::PipelineLibrary pipelines_;
  std::unique_ptr<render::ShadowMaps> shadows_;
  std::vector<Lut> luts_;
  std::vector<Transfer> transfers_;  // skinTransfer()'s, by mesh fingerprint
  std::vector<render::FrameLights> frameLights_;  // per ring slot: the lights recordShadows was given
  std::vector<Retired> retired_;
  std::optional<std::uint64_t> lastFrame_;
  bool numberingRestarts_ = false;  // releaseRetired: the next frame number may be below lastFrame_
  std::uint64_t recordEpoch_ = 0;
  std::optional<std::uint64_t> shadowsFrame_;  // the frame of the latest recordShadows
  std::optional<std::uint64_t> changesFrame_;  // the frame of the latest recordChanges
  std::shared_ptr<RasterTarget> ownTarget_;  // setRasterTarget's; a replaced raster is retired through retire()
  std::vector<std::weak_ptr<RasterTarget>> targets_;  // every target made, the own one too: rebuilt on changes
  std::vector<std::shared_ptr<vk::DeferredWork>> deferred_;  // changes' uploads not yet executed
  std::vector<std::shared_ptr<void>> retiredWithDeferred_;   // retired while such work waited
};
}  // namespace hp
