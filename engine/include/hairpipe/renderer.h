#pragma once
// Contract: the Renderer is what hairpipe shares per device and attachment formats (pipelines, the fibre
// lookup textures cached by material, the opacity shadow maps of the frame's shadowed lights, the queue of retired
// objects); an Instance is one head of hair on it (simulation state, strand buffers, per-frame constants).
// Every call is noexcept; each that can fail reports it as a Status / Result naming the problem, and a
// failed record call has recorded nothing (its arguments are checked first).
//
// Frames in flight: `frame` is the application's frame number, one more per frame (it may start
// anywhere; a record call whose frame is below one already recorded is refused, except right after
// Renderer::releaseRetired, from which the numbering may start again). When it records frame F the application has waited for frame F - framesInFlight to
// complete, and it submits frames in order on one queue. Setters may be called between frames while
// earlier ones are in flight: what the GPU may still read is retired and destroyed framesInFlight frames
// later by a record call, never by waiting on the device. After the first recorded frame, the device
// work of a change (setMaterial, setDensity, createInstance, setRasterTarget, createRasterTarget: uploads of
// new tables and buffers) makes no submission and no wait on the application's queue: it is recorded into the next
// recordUpdate or recordShadows (executed commands, outside any rendering, in TRANSFER and the shader
// stages), so those two need a primary command buffer with no query active (vkCmdExecuteCommands), unless
// the frame's Renderer::recordChanges recorded that work first (in a primary: then they may be secondaries). A
// change between recordUpdate and recordShadows of one frame runs in recordShadows, after that frame's
// update: new strands (setDensity) are filled by the next frame's recordUpdate. So changes go between frames: recordDraw and recordRaster refuse to run while a change's work
// waits for them. Destroying an Instance is the exception: it makes no such work, and inside a frame the
// raster targets holding it still draw it in that frame (its shadows hold it), then are rebuilt without it by
// the next frame's first recordUpdate or recordShadows (a rebuild that fails there empties the target, and
// its recordRaster names the failure). Before the first frame, construction submits its
// uploads once and waits for them. An instance's strands hold no positions until a recordUpdate has computed
// them (after createInstance and setDensity): recordShadows, recordDraw and recordRaster refuse one before
// that, and recordDraw and recordRaster refuse to run in a frame whose recordShadows has not been recorded.
// Instances are destroyed before their Renderer, and a Renderer before its Context; the application waits
// for the GPU before destroying the Renderer.
//
// Synchronisation with the application, per frame, in this order (hairpipe's own buffers and images are
// synchronised inside the calls; only the application's resources are listed). Every record call binds its
// own pipelines, descriptor sets and push constants (graphics and compute), so the application binds its
// own again afterwards.
//   recordUpdate(cmd, frame, instances)   outside any rendering. Compute dispatches and transfers on
//       hairpipe's buffers. Reads the ScalpInput::RootFrames buffer, if any, in COMPUTE_SHADER
//       (SHADER_STORAGE_READ): the application's writes to it must be made visible to that first.
//   recordShadows(cmd, frame, lights, instances)   outside any rendering, every frame (it also orders the
//       new strands before recordDraw reads them). Begins and ends its own renderings on hairpipe's
//       shadow maps; touches nothing of the application's. The application's shaders may read the maps
//       after it (Renderer::hairShadows says in which stages without a barrier), and with
//       RendererSettings::applicationOccluders it may draw its occluders into the heads' depth map before
//       recordDraw (Renderer::occluderTargets lists the barriers).
//   recordDraw(cmd, frame, view, instances)   inside the application's vkCmdBeginRendering (dynamic
//       rendering, begun by the application) whose attachments have RendererSettings::formats (its colour,
//       then formats.otherColors, which recordDraw leaves unwritten) and cover
//       view.extent from (0, 0): colour in COLOR_ATTACHMENT_OPTIMAL, depth in DEPTH_ATTACHMENT_OPTIMAL or
//       DEPTH_STENCIL_ATTACHMENT_OPTIMAL, a stencil attachment exactly where formats.stencil names one
//       (the depth's combined image; hairpipe neither tests nor writes stencil). Depth convention: test
//       LESS_OR_EQUAL against a depth cleared to 1, or with formats.reversedDepth GREATER_OR_EQUAL against
//       one cleared to 0 (the views' projections reversed too). Draws the heads of instances with InstanceSettings::drawHead
//       (depth test and write, colour write) and, in RasterMode::Graphics, the hair (ribbons, depth
//       tested, blended) in EARLY/LATE_FRAGMENT_TESTS and COLOR_ATTACHMENT_OUTPUT. Sets its own viewport
//       (the whole extent, y up: a negative-height viewport for OpenGL-style projections) and scissor.
// RasterMode::Compute draws the hair after the heads, against the depth (setRasterTarget once, outside
// the frame loop, with a view of the application's depth image: format and samples of
// RendererSettings::formats, usage DEPTH_STENCIL_ATTACHMENT | SAMPLED, the view's aspect DEPTH alone; a new depth image
// needs a new setRasterTarget). One view per frame with this target (more views: createRasterTarget). Per frame:
//   1. recordDraw as above (heads only) in a rendering whose depth attachment has STORE_OP_STORE;
//      the application ends that rendering.
//   2. the application's barrier on the depth image: LATE_FRAGMENT_TESTS, DEPTH_STENCIL_ATTACHMENT_WRITE ->
//      COMPUTE_SHADER, SHADER_SAMPLED_READ; layout from step 1's to SHADER_READ_ONLY_OPTIMAL (a combined
//      depth/stencil format without separateDepthStencilLayouts: aspect DEPTH | STENCIL).
//   3. recordRaster(cmd, frame, view)   outside any rendering: compute dispatches (and a buffer update)
//      reading the depth in COMPUTE_SHADER; hairpipe's raster image is ready for the composite when it returns.
//   4. the application's barriers: depth COMPUTE_SHADER, SHADER_SAMPLED_READ -> EARLY|LATE_FRAGMENT_TESTS,
//      DEPTH_STENCIL_ATTACHMENT_READ|WRITE, layout back to step 1's; colour COLOR_ATTACHMENT_OUTPUT,
//      COLOR_ATTACHMENT_WRITE -> COLOR_ATTACHMENT_OUTPUT, COLOR_ATTACHMENT_READ|WRITE (the heads' colour
//      before the composite's blend; same layout).
//   5. a rendering of the same attachments with LOAD_OP_LOAD on colour (and on the velocity attachment with
//      RendererSettings::velocityOutput: pixels without hair keep what step 1 wrote; the depth attached: the
//      composite's pipeline is made for RendererSettings::formats; it neither tests nor writes depth; the
//      application's resolve attachments, if any, here), in which recordComposite(cmd, extent) blends the
//      hair over the colour (multisampled: per sample, with the coverage recordRaster took from the
//      heads' depth samples) and, with RendererSettings::velocityOutput, writes the hair's motion into that
//      one of the other colour attachments: step 4's colour barrier must then cover that image too (the
//      first rendering and the composite both write it).
// Calls that submit to the context's queue and wait for it: Renderer::create, always; createInstance,
// Instance::setMaterial (a new material's tables), Instance::setDensity, setRasterTarget and
// createRasterTarget until that Renderer's first recorded frame. From then on none of these five submits or
// waits (their device work goes into the next recordUpdate or recordShadows, above), and no record call ever does.
// Threads: a Context and everything made on it (its Renderers, their Instances and RasterTargets) are used by
// one thread at a time; none of these calls is synchronized against another on the same Context (they share its command
// pool and upload batch). Objects of different Contexts may be used on different threads at once, except that
// creating a Context (adopt, createHeadless) and unfitReasons load the process's Vulkan entry points and must
// not overlap any other hairpipe call. A new material's tables are built on hairpipe's own worker thread
// (setMaterial above), which touches none of them.
#include <vulkan/vulkan_core.h>

#include <cstdint>
#include <memory>
#include <span>

#include "hairpipe/asset.h"
#include "hairpipe/context.h"
#include "hairpipe/math.h"
#include "hairpipe/result.h"
#include "hairpipe/settings.h"

namespace hp {
class Renderer;
}

namespace hairpipe {
struct Access;

class Instance {
 public:
  Instance(Instance&&) noexcept;
  // Retires the instance held before (as the destructor does), then takes the other's.
  Instance& operator=(Instance&&) noexcept;
  // Retires the instance's GPU objects through its Renderer (destroyed after the frames in flight); may run
  // at any point of a frame (see the frame contract above: a raster target draws it until the next frame). The
  // Renderer's shared objects live on while any of its instances does. A moved-from Instance holds
  // nothing: its setters return a failure.
  ~Instance();

  // This frame's head motion (from -> to); the frame's draws and shadows use `to`.
  Status setMotion(const HeadMotion& motion) noexcept;
  // Where the head is drawn and casts its shadow when it is not simulated this frame.
  Status setHeadToWorld(const Mat4& headToWorld) noexcept;
  // Colliders for the next frames, in head space (replacing the asset's spheres).
  Status setColliders(std::span<const SphereCollider> spheres,
                      std::span<const CapsuleCollider> capsules = {}) noexcept;
  // ScalpInput::Kind::Bones: the bone matrices (head-space rest pose to world) at the end of the next frame.
  Status setBones(std::span<const Mat4> bones) noexcept;
  // ScalpInput::Kind::RootFrames: the buffer (from offset, bytes of it) the next recordUpdate reads the root
  // frames from, e.g. this frame's slot of a ring the application's skinning writes; frames already recorded
  // keep reading the former one. Refused in another mode, or for a buffer ScalpInput would refuse.
  Status setRootFrames(VkBuffer buffer, VkDeviceSize offset, VkDeviceSize bytes) noexcept;
  // An asset with a skinned character mesh (AssetSource::mesh): its pose at the end of the next frame, one
  // head-space matrix per joint (bind pose to pose: meshClipPose, or the application's skinning in head space).
  // The next recordUpdate skins the mesh and rebuilds the distance grid the hair collides with on the device,
  // and the head recordDraw draws (and the shadows) take the pose. Without a call the last pose stays.
  // Fails for an asset without a skinned mesh, or one whose collisions scene colliders replaced.
  Status setMeshPose(std::span<const Mat4> bones) noexcept;
  // A material whose lookup tables the Renderer holds (one an instance uses or used) applies at once.
  // Another one, after the first recorded frame, has its tables built on a worker thread (tens of ms of
  // CPU) while the instance keeps drawing its current material; the first recordUpdate or recordShadows
  // after they are done applies it (materialPending() is false from then). Before the first frame it
  // applies at once. A later setMaterial replaces a pending one. A raster target holding the instance is
  // kept (it takes the new tables frame slot by frame slot; a new fibre model shades with its run-time form,
  // the same image, slower on CPU devices, until the target is set or created again: docs/API.md "Frames in
  // flight, lifetimes").
  Status setMaterial(const Material& material, FibreModel fibre) noexcept;
  bool materialPending() const noexcept;
  // What this instance's hair passes on forward to a diffuse receiver beneath it, for
  // hairpipeHairShadow's `forward` (hairpipe/hair_shadows.glsl): with dual scattering the material's mean
  // forward albedo and its weight, with single scattering all 0. It follows setLook at once and setMaterial
  // once the new material applies (materialPending() false: in the frame loop, the recordUpdate or
  // recordShadows that applies it), so an application asks after those calls, each frame.
  struct HairShadowForward {
    Vec3 albedo;
    float weight = 0.0f;
  };
  Result<HairShadowForward> hairShadowForward() const noexcept;
  // A failure naming why the last setMaterial made in the frame loop did not apply once it left
  // materialPending() (its tables could not be built or uploaded; the instance keeps its former material);
  // ok while it is pending, once it applied, or when none failed. A later setMaterial clears it.
  Status materialStatus() const noexcept;
  Status setLook(const LookSettings& look) noexcept;
  Status setLod(const LodSettings& lod) noexcept;
  // Clumps, curl and frizz from the next recordUpdate on (push constants: nothing is rebuilt).
  Status setGroom(const GroomSettings& groom) noexcept;
  // From the next recordUpdate on; cheap (nothing is rebuilt), so an application with a varying frame time
  // sets each frame's dt here before recording it (gridResolution is fixed at creation).
  Status setSimulation(const SimulationSettings& simulation) noexcept;
  // Another density of render strands between the same guides (new strand buffers, filled by the next
  // recordUpdate; a raster target holding the instance is rebuilt).
  Status setDensity(const Density& density) noexcept;
  std::uint32_t strandCount() const noexcept;

  struct Impl;  // hairpipe's implementation (opaque)

 private:
  friend struct Access;
  explicit Instance(std::unique_ptr<Impl> impl) noexcept;
  std::unique_ptr<Impl> impl_;
};

// A compute raster target of the application's own (Renderer::createRasterTarget), for the views of a frame
// beyond the one setRasterTarget's target draws: a second eye, a split screen, a mirror, an editor's second
// viewport, each with its own extent and depth image. It draws one view per frame, and its Renderer rebuilds
// it as it does its own (an instance in it changing density or destroyed); once none of its instances is
// left it refuses to draw. Destroying it retires its buffers and images through its Renderer (destroyed after
// the frames in flight); it keeps that Renderer's shared objects alive as an Instance does. A moved-from
// RasterTarget holds nothing, and the calls given it return failures.
class RasterTarget {
 public:
  RasterTarget(RasterTarget&&) noexcept;
  // Retires the target held before (as the destructor does), then takes the other's.
  RasterTarget& operator=(RasterTarget&&) noexcept;
  ~RasterTarget();

  struct Impl;  // hairpipe's implementation (opaque)

 private:
  friend struct Access;
  explicit RasterTarget(std::unique_ptr<Impl> impl) noexcept;
  std::unique_ptr<Impl> impl_;
};

class Renderer {
 public:
  // The context must outlive the Renderer, its instances and its raster targets (a temporary cannot be given).
  static Result<Renderer> create(const Context& context, const RendererSettings& settings) noexcept;
  static Result<Renderer> create(Context&& context, const RendererSettings& settings) = delete;
  Renderer(Renderer&&) noexcept;
  Renderer& operator=(Renderer&&) noexcept;
  // The shared objects are destroyed with the last of the Renderer and its instances; the application has
  // waited for the GPU to finish the frames that used them. A moved-from Renderer returns failures.
  ~Renderer();

  // Uploads the asset's data for one head (submits to the context's queue and waits for that upload).
  Result<Instance> createInstance(const Asset& asset, const InstanceSettings& settings,
                                  const Mat4& initialHeadToWorld = {}) noexcept;

  // Optional, first in a frame, in a primary command buffer outside any rendering with no query active: the
  // work that changes since the last frame left waiting (new materials' tables once built, new buffers,
  // raster targets rebuilt: vkCmdExecuteCommands of hairpipe's secondaries). That frame's recordUpdate and
  // recordShadows then record none of it, so an engine may record them into secondary command buffers or
  // inside a query; a change made after it waits for the next frame.
  Status recordChanges(VkCommandBuffer cmd, std::uint64_t frame, std::span<Instance* const> instances) noexcept;
  Status recordUpdate(VkCommandBuffer cmd, std::uint64_t frame, std::span<Instance* const> instances) noexcept;
  // The frame's lights (at most 8; shadow slots as hairpipe::Light says), or one light.
  Status recordShadows(VkCommandBuffer cmd, std::uint64_t frame, std::span<const Light> lights,
                       std::span<Instance* const> instances) noexcept;
  Status recordShadows(VkCommandBuffer cmd, std::uint64_t frame, const Light& light,
                       std::span<Instance* const> instances) noexcept;
  Status recordDraw(VkCommandBuffer cmd, std::uint64_t frame, const View& view,
                    std::span<Instance* const> instances) noexcept;

  // Compute raster (raster() == RasterMode::Compute): the instances whose hair recordRaster draws, all in
  // one set of tile lists, into an image of `extent` against `depth`. Rebuilt by the Renderer when one of
  // them changes density or is destroyed (after the first frame: by the next frame's first recordUpdate or
  // recordShadows; a material change keeps it: it takes the new tables from the next frame on); call again
  // for another extent or set (which replaces such a waiting rebuild).
  Status setRasterTarget(VkExtent2D extent, VkImageView depth, std::span<Instance* const> instances) noexcept;
  Status recordRaster(VkCommandBuffer cmd, std::uint64_t frame, const View& view) noexcept;
  // `extent`: the raster target's (the composite reads its image pixel for pixel); another is refused, as is
  // a composite before the frame's recordRaster of that target (it would draw the previous frame's hair).
  Status recordComposite(VkCommandBuffer cmd, VkExtent2D extent) noexcept;
  // More views of a frame with the compute raster: a target for each, made like setRasterTarget's (outside the
  // frame loop, or in it: its uploads then go into the next recordUpdate or recordShadows), and the same
  // per-view sequence as above with the target named: recordDraw of the view's heads into its depth image,
  // the application's barriers, recordRaster(cmd, frame, view, target), recordComposite(cmd, extent, target).
  // Every view of a frame reuses that frame's update and shadows; each target costs its own tile lists and
  // images (docs/API.md "Several views of a frame").
  Result<RasterTarget> createRasterTarget(VkExtent2D extent, VkImageView depth,
                                          std::span<Instance* const> instances) noexcept;
  Status recordRaster(VkCommandBuffer cmd, std::uint64_t frame, const View& view, RasterTarget& target) noexcept;
  Status recordComposite(VkCommandBuffer cmd, VkExtent2D extent, const RasterTarget& target) noexcept;

  // Shadow tuning that keeps the maps' resolution, format and raster (opacity, k, bias, on/off).
  Status setOpacityTuning(const OpacitySettings& opacity) noexcept;
  // The raster mode in effect (Auto resolved for the device).
  RasterMode raster() const noexcept;
  // Every frame recorded so far is complete (the application waited on its fences or its device): what
  // destroyed instances and replaced resources left retired is destroyed now, rather than by the record
  // calls framesInFlight frames later (a level unloaded while the Renderer is kept: its device memory comes
  // back at once). Work recorded for the next frame (changes since the last one) keeps what it needs. The
  // next record call may then number its frame from anywhere (a frame counter reset with the level).
  Status releaseRetired() noexcept;
  // The pipeline cache's data now (vkGetPipelineCacheData), for RendererSettings::pipelineCache of a later run.
  Result<std::vector<std::uint8_t>> pipelineCacheData() const noexcept;

  // RendererSettings::motionVectors with the compute raster: the hair's motion image of the raster target
  // (changes with setRasterTarget). RG16F, the raster target's extent: per pixel the hair's screen motion in
  // pixels, this frame's unjittered position minus the previous frame's (x right, y down), weighted by each
  // strand's visible coverage of the pixel; 0 where there is no hair (the hair's coverage is the alpha
  // recordComposite blends with). recordRaster writes it in COMPUTE_SHADER (SHADER_STORAGE_WRITE) and leaves
  // it in SHADER_READ_ONLY_OPTIMAL, visible to FRAGMENT_SHADER sampled reads; another stage needs the
  // application's barrier from FRAGMENT_SHADER. The next recordRaster rewrites it after a barrier from
  // FRAGMENT_SHADER only: an application that reads it in another stage (a compute TAA resolve) leaves it in
  // SHADER_READ_ONLY_OPTIMAL with a barrier from that stage to FRAGMENT_SHADER after its reads.
  // The motion is that of the latest recordUpdate of each instance: an instance not updated for a frame
  // shows its last step's motion again; a teleport (HeadMotion::teleport) shows the jump itself (the hair
  // carried rigidly: its true screen motion, which a TAA may reject as a cut).
  struct MotionImage {
    VkImage image = VK_NULL_HANDLE;
    VkImageView view = VK_NULL_HANDLE;
    VkFormat format = VK_FORMAT_R16G16_SFLOAT;
    VkExtent2D extent{};
  };
  Result<MotionImage> motionImage() const noexcept;
  Result<MotionImage> motionImage(const RasterTarget& target) const noexcept;  // a createRasterTarget target's

  // The hair's opacity shadow maps, for the application's own shaders: receivers hairpipe does not draw (a
  // body, clothes, a floor) darken under the hair as hairpipe's heads do, through hairpipeHairShadow
  // (hairpipe/hair_shadows.glsl, installed beside this header; docs/API.md "Hair shadows in your shaders").
  // Shadow slot i is the i-th light with Light::shadows of the latest recordShadows (at most `slots`); a slot
  // no light took there (or every slot, in a frame without instances or with hair shadows off) keeps an
  // earlier frame's contents, so read only the slots of that frame's shadowed lights.
  // Synchronisation: recordShadows leaves `view` in SHADER_READ_ONLY_OPTIMAL with its writes visible to
  // FRAGMENT_SHADER sampled reads, and `lightSpaces` (bound as a storage buffer) with its writes visible to
  // VERTEX_SHADER, FRAGMENT_SHADER and COMPUTE_SHADER storage reads; so a rendering after recordShadows reads
  // them in those stages without a barrier of the application's. The next recordShadows rewrites them after a
  // barrier from those stages: an application that samples the maps in another stage (a compute lighting
  // pass) adds a barrier FRAGMENT_SHADER -> its stage before, and its stage -> FRAGMENT_SHADER after its
  // reads, with the layout kept. The handles live as long as the Renderer; the parameters change with
  // setOpacityTuning (ask again after it).
  struct HairShadows {
    VkImage image = VK_NULL_HANDLE;
    VkImageView view = VK_NULL_HANDLE;  // 2D array: layersPerSlot layers per slot, from layer slot x layersPerSlot
    VkSampler sampler = VK_NULL_HANDLE;  // linear, clamped to the edge: the one hairpipe samples them with
    VkFormat format = VK_FORMAT_UNDEFINED;
    std::uint32_t resolution = 0;  // texels per side
    std::uint32_t slots = 0;       // RendererSettings::shadowedLights
    std::uint32_t layersPerSlot = 0;
    VkBuffer lightSpaces = VK_NULL_HANDLE;  // HairpipeLightSpace[slots] (std430, 128 bytes each) from offset 0
    VkDeviceSize lightSpacesBytes = 0;
    float opacityScale = 0.0f;  // k: optical depth per unit of the maps' opacity (0 while shadows are off)
    float bias = 0.0f;          // slices the lookup moves toward the light
    bool deep = false;          // deep opacity maps: slices from each texel's first hair
  };
  Result<HairShadows> hairShadows() const noexcept;

  // RendererSettings::applicationOccluders: the heads' depth shadow map, into which the application draws its
  // own occluders (its character's head and body, a hat) after recordShadows, so that they shadow the hair and
  // hairpipe's heads. Per shadow slot the frame's recordShadows framed (`framed`): a 2D view of the slot's
  // layer and this frame's world-to-clip matrix (orthographic along a directional light, perspective from a
  // spot or point light; depth [0, 1], y up: draw with the negative-height viewport hairpipe's draws use,
  // front faces counter-clockwise). The map holds BACK faces (cull front faces; a receiver moves a few texels
  // toward the light before its comparison, so a lit surface never shadows itself), depth test
  // LESS_OR_EQUAL with writes, no colour attachment. It covers a sphere around hairpipe's heads, or around
  // each hair-only instance's guides at rest (placed by its head transform): an occluder outside it casts
  // nothing (one nearer the light is clipped, unless the application's pipeline clamps depth), and hair that
  // leaves it is not shadowed. Synchronisation, per framed slot, between recordShadows and the frame's
  // recordDraw / recordRaster: the layer is in SHADER_READ_ONLY_OPTIMAL; the application's barrier
  // FRAGMENT_SHADER | COMPUTE_SHADER (SHADER_SAMPLED_READ) -> EARLY|LATE_FRAGMENT_TESTS
  // (DEPTH_STENCIL_ATTACHMENT_READ | WRITE), to DEPTH_STENCIL_ATTACHMENT_OPTIMAL (DEPTH_ATTACHMENT_OPTIMAL
  // needs separateDepthStencilLayouts);
  // a rendering of the view with LOAD_OP_LOAD and STORE_OP_STORE (hairpipe's heads are already in it); then
  // LATE_FRAGMENT_TESTS (DEPTH_STENCIL_ATTACHMENT_WRITE) -> FRAGMENT_SHADER (SHADER_SAMPLED_READ), back to
  // SHADER_READ_ONLY_OPTIMAL. Fails without applicationOccluders, or before the current frame's recordShadows.
  struct OccluderTargets {
    VkImage image = VK_NULL_HANDLE;  // 2D array, a layer per slot
    VkFormat format = VK_FORMAT_UNDEFINED;  // VK_FORMAT_D32_SFLOAT
    VkExtent2D extent{};
    std::uint32_t slots = 0;
    VkImageView layers[4] = {};      // per slot: a 2D view of its layer, for the depth attachment
    Mat4 viewProjection[4];          // per slot: world to the map's clip space, this frame
    bool framed[4] = {};             // per slot: framed and cleared by this frame's recordShadows
  };
  Result<OccluderTargets> occluderTargets() const noexcept;

 private:
  friend struct Access;
  explicit Renderer(std::shared_ptr<hp::Renderer> impl) noexcept;
  std::shared_ptr<hp::Renderer> impl_;  // shared with its instances
};

// The CPU start-up work of createInstance(asset, settings), done now on the calling thread, which may be any
// thread (a loading thread: it touches no Context, Renderer or Instance): the material's lookup tables with
// their parameter block and, with drawHead, the head mesh's skin transfer go into the process's caches (the last 4 of each), so a
// createInstance of the same asset and material soon after, on the thread that records frames, takes them
// instead of computing them there (~0.5 s and ~0.16 s of CPU for the default head's on a 2-core machine). A
// failure names the settings createInstance would refuse.
Status prepareInstance(const Asset& asset, const InstanceSettings& settings) noexcept;

// A view for hairpipe's conventions (right-handed view, Vulkan [0, 1] depth) from a camera; a failure
// names a degenerate camera (eye at target, up along the view direction, fovY outside (0, pi), bad planes).
Result<View> makeView(const Camera& camera, VkExtent2D extent, std::uint32_t index = 0) noexcept;
}  // namespace hairpipe
