#include "compute/renderer/hair_instance.h"

#include <algorithm>
#include <cmath>
#include <cstring>

#include "engine/core/error.h"
#include "engine/core/hair/finite.h"
#include "compute/renderer/renderer.h"
#include "engine/vk/barriers.h"
#include "engine/vk/context.h"

namespace hp {
namespace {
const InstanceSettings& validated(const InstanceSettings& s) {
  s.validate();
  return s;
}

void checkFinite(const glm::mat4& m, const char* what) {
  if (!allFinite(m)) throw Error(std::string(what) + " must be finite");
}

// Motion vectors read the previous frame's positions: the strand buffers keep them.
compute::StrandOptions strandOptions(const Renderer& r, compute::StrandOptions options) {
  options.previousPositions = options.previousPositions || r.settings().motionVectors;
  return options;
}

vk::Buffer makeBounceFrame(const vk::Context& ctx) {
  return vk::Buffer(ctx, sizeof(gpu::RenderFrame), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                    vk::MemoryKind::DeviceLocal, "head bounce frame");
}

std::uint32_t alignedSize(std::size_t size, VkDeviceSize alignment) {
  return static_cast<std::uint32_t>((size + alignment - 1) / alignment * alignment);
}
}  // namespace

HairInstance::Geometry::Geometry(Renderer& r, const SimulatePass& sim, const InterpolationTopology& topology,
                                 const HeadMesh& head, const render::HeadSphere& occluders, const InstanceSettings& s,
                                 const vk::Buffer& bounceFrame)
    : buffers(r.context(), sim.guideCount(), sim.particlesPerGuide(), topology, strandOptions(r, s.strands)),
      tessellate(r.context(), sim.positions(), buffers, &r.pipelines()),
      interpolate(r.context(), buffers, &r.pipelines(), s.groom),
      bounds(r.context(), buffers, r.shadows().lightSpace(), &r.pipelines()),
      opacity(r.context(), buffers, head, r.shadows(), &r.pipelines()),
      bounce(r.context(), buffers, bounceFrame.handle(), r.shadows().inputs(), &r.pipelines()) {
  // A posed character reaches past its rest mesh: its shadows are framed on the grid that covers its poses.
  if (sim.character() && sim.sdf() && !head.indices.empty()) {
    const SdfGrid& g = *sim.sdf();
    opacity.encloseHead({0.5f * (g.origin + g.upper()), 0.5f * glm::length(g.upper() - g.origin)});
  }
  opacity.encloseHead(occluders);
}

HairInstance::HairInstance(Renderer& renderer, const HairAsset& asset, const InstanceSettings& settings,
                           const glm::mat4& initialHead)
    : renderer_(renderer),
      settings_(validated(settings)),
      headMesh_(settings.drawHead ? asset.head : HeadMesh{}),
      // Hair only (drawHead false, or an asset without a head mesh), with the application's occluders: the heads'
      // depth map is framed around the guides (the application draws its character there), so it exists without
      // hairpipe's head.
      occluderSphere_(headMesh_.indices.empty() && renderer.settings().applicationOccluders
                          ? render::boundingSphere(asset.guides.positions)
                          : render::HeadSphere{}),
      motion_{initialHead, initialHead, 0.0, false},
      simulate_(renderer.context(), asset, settings.simulation, initialHead, &renderer.pipelines(), settings.scalp),
      bounceFrame_(makeBounceFrame(renderer.context())),
      geometry_(std::make_shared<Geometry>(renderer, simulate_, asset.topology, headMesh_, occluderSphere_, settings_,
                                           bounceFrame_)),
      marschner_(renderer.marschner(settings.material, settings.lutMode)) {
  const vk::Context& ctx = renderer.context();
  const RendererSettings& rs = renderer.settings();
  // Read as a storage buffer with dynamic offsets (no shader reads a uniform block: docs/DESIGN.md, driver notes).
  frameStride_ = alignedSize(sizeof(gpu::RenderFrame), ctx.properties().limits.minStorageBufferOffsetAlignment);
  frames_ = vk::Buffer(ctx, VkDeviceSize(frameStride_) * rs.framesInFlight * rs.maxViewsPerFrame,
                       VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, vk::MemoryKind::Upload, "render frame ring");
  // Valid blocks from the start, so a draw before any prepared view reads sane values.
  blockWrites_.resize(rs.maxViewsPerFrame);
  for (std::uint32_t slot = 0; slot < rs.framesInFlight * rs.maxViewsPerFrame; ++slot)
    *frameSlot(slot / rs.maxViewsPerFrame, slot % rs.maxViewsPerFrame) =
        frameBlock(CameraMatrices{}, {1, 1}, render::FrameLights{}, settings_.look);
  head_ = std::make_shared<render::HeadPass>(ctx, headMesh_, renderer.skinTransfer(headMesh_), frames_,
                                             renderer.shadows().inputs(), rs.formats, &renderer.pipelines());
  bounce_ = std::make_unique<render::HeadBouncePass>(ctx, *head_, bounceFrame_.handle(), renderer.shadows().inputs(),
                                                     &renderer.pipelines());
  strandPass_ = makeStrandPass(*geometry_, *marschner_);
}

HairInstance::~HairInstance() { renderer_.forgetInstance(*this); }

glm::vec4 HairInstance::shadowForward() const {
  return render::hairForward(settings_.look, glm::vec3(marschner_->params().forwardMean));
}

gpu::RenderFrame HairInstance::frameBlock(const CameraMatrices& camera, VkExtent2D extent,
                                          const render::FrameLights& lights, const render::LookSettings& look) const {
  gpu::RenderFrame f = render::makeRenderFrame(camera, extent, lights, settings_.material, look, strands().layout(),
                                               renderer_.shadows().settings(), glm::vec3(marschner_->params().forwardMean));
  render::setSkinLight(f, headToWorld(), geometry_->opacity.headSphere(headToWorld()).centre, lights, look);
  return f;
}

std::uint32_t HairInstance::frameOffset(std::uint64_t frame, std::uint32_t view) const {
  const RendererSettings& rs = renderer_.settings();
  return static_cast<std::uint32_t>((frame % rs.framesInFlight) * rs.maxViewsPerFrame + view) * frameStride_;
}

gpu::RenderFrame* HairInstance::frameSlot(std::uint64_t frame, std::uint32_t view) const {
  return reinterpret_cast<gpu::RenderFrame*>(static_cast<std::byte*>(frames_.mapped()) + frameOffset(frame, view));
}

std::shared_ptr<render::StrandPass> HairInstance::makeStrandPass(const Geometry& geometry,
                                                                 const render::MarschnerTextures& marschner) const {
  if (renderer_.raster() == RasterMode::Compute) return nullptr;  // the raster target draws the strands
  return std::make_shared<render::StrandPass>(renderer_.context(), geometry.buffers, marschner, frames_,
                                              renderer_.shadows().inputs(), renderer_.settings().formats,
                                              &renderer_.pipelines());
}

void HairInstance::replaceStrandPass(std::shared_ptr<render::StrandPass> pass) {
  if (strandPass_) renderer_.retire(std::move(strandPass_));  // frames in flight may still draw with it
  strandPass_ = std::move(pass);
}

void HairInstance::setMotion(const HeadMotion& motion) {
  checkFinite(motion.from, "HeadMotion.from");
  checkFinite(motion.to, "HeadMotion.to");
  if (!std::isfinite(motion.time)) throw Error("HeadMotion.time must be finite");
  motion_ = motion;
}

void HairInstance::setHeadToWorld(const glm::mat4& headToWorld) {
  checkFinite(headToWorld, "headToWorld");
  motion_.to = headToWorld;
}

void HairInstance::setRootFrames(VkBuffer buffer, VkDeviceSize offset, VkDeviceSize bytes) {
  renderer_.retire(simulate_.setRootFrames(buffer, offset, bytes));
}

void HairInstance::setMaterial(const HairMaterial& material, LutMode mode) {
  material.validate();
  pending_.reset();  // a newer change replaces a pending one (skipped if the worker has not started it)
  materialError_.clear();
  if (material == settings_.material && mode == settings_.lutMode) return;
  std::shared_ptr<render::MarschnerTextures> cached = renderer_.cachedMarschner(material, mode);
  if (cached) return applyMaterial([&] { return cached; }, material, mode);
  if (!renderer_.inFrameLoop()) return applyMaterial([&] { return renderer_.marschner(material, mode); }, material, mode);
  // In the frame loop the tables (tens of ms of CPU) are built off the application's thread.
  pending_ = LutBuild::start(material, mode);
}

void HairInstance::applyReadyMaterial() {
  if (!pending_ || !pending_->done()) return;
  const std::shared_ptr<LutBuild> done = std::move(pending_);
  pending_.reset();
  try {
    if (!done->error().empty()) throw Error(done->error());
    applyMaterial([&] { return renderer_.marschnerFrom(done->lut(), &done->params()); }, done->material(), done->mode());
  } catch (const std::exception& e) {  // record calls do not throw: the old material stays, the reason is kept
    materialError_ = "the material change did not apply (the instance keeps its former material): " + std::string(e.what());
  }
}

void HairInstance::applyMaterial(const TexturesMaker& make, const HairMaterial& material, LutMode mode) {
  renderer_.withUploads("set material", [&] {
    std::shared_ptr<render::MarschnerTextures> textures = make();
    auto pass = makeStrandPass(*geometry_, *textures);  // everything that can throw happens before the swap
    // The old textures and strand pass stay alive until the frames that sample them are done.
    renderer_.retire(marschner_);
    marschner_ = std::move(textures);
    replaceStrandPass(std::move(pass));
    settings_.material = material;
    settings_.lutMode = mode;
  });
  renderer_.materialChanged(*this);  // a compute raster target rebinds the LUTs
}

void HairInstance::setLook(const render::LookSettings& look) {
  look.validate();
  settings_.look = look;  // read into the per-frame constants at record time
}

void HairInstance::setLod(const hairpipe::LodSettings& lod) {
  validate(lod);
  settings_.lod = lod;  // applied per view at record time
}

float HairInstance::lodFraction(const glm::vec3& eye) const {
  return hp::lodFraction(settings_.lod, glm::length(eye - glm::vec3(headToWorld()[3])));
}

std::uint32_t HairInstance::lodStrands(float fraction) const {
  return lodStrandCount(fraction, strands().layout().strandCount);
}

void HairInstance::checkFrameBlock(std::uint64_t frame, std::uint32_t index, const gpu::RenderFrame& block) const {
  const std::optional<BlockWrite>& written = blockWrites_.at(index);
  if (!written || written->epoch != renderer_.recordEpoch() || written->frame != frame) return;
  if (std::memcmp(frameSlot(frame, index), &block, sizeof(block)) != 0)
    throw Error("Renderer::recordDraw: View.index " + std::to_string(index) + " already drew another view in frame " +
                std::to_string(frame) + " (another camera, extent or jitter): each view of a frame needs its own " +
                "index, below RendererSettings::maxViewsPerFrame");
}

void HairInstance::writeFrameBlock(std::uint64_t frame, std::uint32_t index, const gpu::RenderFrame& block) {
  *frameSlot(frame, index) = block;
  blockWrites_.at(index) = BlockWrite{renderer_.recordEpoch(), frame};
}

void HairInstance::noteViewFraction(std::uint64_t frame, float fraction) {
  if (!viewsDrawn_ || frame != viewFrame_) largestViewFraction_ = 0.0f;
  viewsDrawn_ = true;
  viewFrame_ = frame;
  largestViewFraction_ = std::max(largestViewFraction_, fraction);
}

void HairInstance::setGroom(const GroomSettings& groom) {
  geometry_->interpolate.setGroom(groom);  // validates; push constants of the next recordUpdate
  settings_.groom = groom;
}

void HairInstance::setSimulation(const SimulationParams& params) {
  simulate_.setParams(params);
  settings_.simulation = params;
}

void HairInstance::setStrands(const InterpolationTopology& topology, const compute::StrandOptions& options) {
  renderer_.withUploads("set strands", [&] {
    InstanceSettings next = settings_;
    next.strands = options;
    auto geometry = std::make_shared<Geometry>(renderer_, simulate_, topology, headMesh_, occluderSphere_, next,
                                               bounceFrame_);
    auto pass = makeStrandPass(*geometry, *marschner_);
    renderer_.retire(geometry_);
    geometry_ = std::move(geometry);
    replaceStrandPass(std::move(pass));
    settings_ = next;
  });
  renderer_.instanceChanged(*this);  // a compute raster target reads the old strand buffers
}
}  // namespace hp

namespace hp {
void HairInstance::recordCharacterCopies(const vk::Context& ctx, VkCommandBuffer cmd) const {
  const CharacterPass* character = simulate_.character();
  if (!character || !simulate_.characterPosed() || !head_ || head_->empty()) return;
  const VkDeviceSize bytes = VkDeviceSize(character->vertexCount()) * sizeof(glm::vec4);
  const VkBufferCopy region{0, 0, bytes};
  // The last frame's head draws (the view, the shadow maps' head depth, the bounce map) read these buffers.
  vk::memoryBarrier(ctx, cmd, vk::BufferUse::GraphicsRead, vk::BufferUse::TransferDst);
  const auto& fn = ctx.fn();
  fn.vkCmdCopyBuffer(cmd, character->posedPositions().handle(), head_->positions().handle(), 1, &region);
  fn.vkCmdCopyBuffer(cmd, character->posedNormals().handle(), head_->normals().handle(), 1, &region);
  fn.vkCmdCopyBuffer(cmd, character->posedPositions().handle(), geometry_->opacity.headPositions().handle(), 1, &region);
  vk::memoryBarrier(ctx, cmd, vk::BufferUse::TransferDst, vk::BufferUse::GraphicsRead);
}
}  // namespace hp
