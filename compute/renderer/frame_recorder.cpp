#include "compute/renderer/frame_recorder.h"

#include <algorithm>
#include <span>

#include "engine/vk/barriers.h"
#include "shaders/shared/opacity.h"

namespace hp {
namespace {
// The positions into the previous positions of the work items whose `primed` is `before`, with the barriers
// around the copies: the positions' last compute write and the previous positions' last read (the last
// frame's compute raster) before them, their read of the positions before interpolate overwrites them.
void recordKeepPrevious(const vk::Context& ctx, VkCommandBuffer cmd, std::span<const UpdateWork> work, bool before) {
  const auto copies = [&](const UpdateWork& w) { return w.strands && w.strands->keepsPrevious() && w.primed == before; };
  if (std::none_of(work.begin(), work.end(), copies)) return;
  vk::memoryBarrier(ctx, cmd, vk::BufferUse::ComputeWrite, vk::BufferUse::TransferSrc);
  vk::memoryBarrier(ctx, cmd, vk::BufferUse::ComputeRead, vk::BufferUse::TransferDst);
  for (const UpdateWork& w : work)
    if (copies(w)) w.strands->recordKeepPrevious(ctx, cmd);
  vk::memoryBarrier(ctx, cmd, vk::BufferUse::TransferSrc, vk::BufferUse::ComputeWrite);
}
}  // namespace

void recordUpdatePasses(const vk::Context& ctx, VkCommandBuffer cmd, std::span<const UpdateWork> work,
                        vk::GpuProfiler* profiler) {
  // The previous frame drew the strands and chained compute passes over the same buffers.
  vk::memoryBarrier(ctx, cmd, vk::BufferUse::VertexRead, vk::BufferUse::ComputeWrite);
  vk::memoryBarrier(ctx, cmd, vk::BufferUse::ComputeWrite, vk::BufferUse::ComputeWrite);
  for (const UpdateWork& w : work) w.simulate->record(cmd, w.motion, profiler);
  vk::memoryBarrier(ctx, cmd, vk::BufferUse::ComputeWrite, vk::BufferUse::ComputeRead);
  for (const UpdateWork& w : work) w.tessellate->record(cmd, profiler);
  recordKeepPrevious(ctx, cmd, work, true);  // the last frame's positions become the previous ones
  vk::memoryBarrier(ctx, cmd, vk::BufferUse::ComputeWrite, vk::BufferUse::ComputeRead);
  for (const UpdateWork& w : work) w.interpolate->record(cmd, profiler);
  recordKeepPrevious(ctx, cmd, work, false);  // a first frame: no motion
  vk::memoryBarrier(ctx, cmd, vk::BufferUse::TransferDst, vk::BufferUse::ComputeRead);  // the raster reads them
}

void makeStrandsDrawable(const vk::Context& ctx, VkCommandBuffer cmd) {
  vk::memoryBarrier(ctx, cmd, vk::BufferUse::ComputeWrite, vk::BufferUse::VertexRead);
}

compute::ShadowLight shadowLightOf(const LightSpec& light) {
  const glm::vec3 toward = glm::normalize(light.direction);
  if (light.type == LightSpec::Type::Directional) return compute::ShadowLight(toward);
  return compute::ShadowLight::makeSpot(light.position, toward, glm::radians(light.coneDeg));
}

namespace {
// A transition of one shadow slot's layers of the opacity maps.
void slotBarrier(const vk::Context& ctx, VkCommandBuffer cmd, const render::ShadowMaps& maps, std::uint32_t slot,
                 vk::ImageUse from, vk::ImageUse to) {
  vk::imageBarrier(ctx, cmd, maps.image().handle(), VK_IMAGE_ASPECT_COLOR_BIT, from, to, gpu::OPACITY_LAYERS,
                   slot * gpu::OPACITY_LAYERS);
}

void recordGraphicsOpacity(const vk::Context& ctx, VkCommandBuffer cmd, const render::ShadowMaps& maps,
                           std::span<const ShadowCaster> casters, std::uint32_t slot) {
  slotBarrier(ctx, cmd, maps, slot, vk::ImageUse::FragmentSampled, vk::ImageUse::ColorAttachment);
  maps.beginRendering(cmd, slot);
  for (const ShadowCaster& c : casters)
    c.opacity->recordDraws(cmd, slot, c.headToWorld, c.strandWidth, c.strandLimit);
  maps.endRendering(cmd);
  slotBarrier(ctx, cmd, maps, slot, vk::ImageUse::ColorAttachment, vk::ImageUse::FragmentSampled);
}

// Clear the bins, every caster's splats (atomics: ordered like any two writers), the resolve into the
// maps, then the heads that go into the slices, drawn over the resolved maps. The bins serve one slot
// after another. The splats and the resolve are scopes of their own within the profiler's "opacity".
void recordComputeOpacity(const vk::Context& ctx, VkCommandBuffer cmd, const render::ShadowMaps& maps,
                          std::span<const ShadowCaster> casters, std::uint32_t slot, vk::GpuProfiler* profiler) {
  auto begin = [&](const char* scope) { if (profiler) profiler->begin(cmd, scope); };
  auto end = [&] { if (profiler) profiler->end(cmd); };
  const compute::OpacityResolvePass& resolve = *maps.resolvePass();
  const VkBuffer bins = resolve.bins().handle(), first = resolve.first().handle();
  // What recordClear fills: the bins, and the first-hair buffer for deep maps only.
  const VkBuffer both[] = {bins, first};
  const std::span<const VkBuffer> cleared(both, resolve.deep() ? 2 : 1);
  auto barriers = [&](std::span<const VkBuffer> buffers, vk::BufferUse from, vk::BufferUse to) {
    for (VkBuffer b : buffers) vk::bufferBarrier(ctx, cmd, b, from, to);
  };
  // The last resolve and deep splats (last frame's, or another slot's) read them.
  barriers(cleared, vk::BufferUse::ComputeRead, vk::BufferUse::TransferDst);
  resolve.recordClear(cmd);
  barriers(cleared, vk::BufferUse::TransferDst, vk::BufferUse::ComputeWrite);
  auto splatAll = [&](std::uint32_t mode, std::span<const VkBuffer> targets) {
    for (std::size_t i = 0; i < casters.size(); ++i) {
      if (i > 0) barriers(targets, vk::BufferUse::ComputeWrite, vk::BufferUse::ComputeWrite);
      casters[i].opacity->recordSplats(cmd, slot, casters[i].strandWidth, mode, casters[i].strandLimit);
    }
  };
  using compute::OpacityBins;
  const std::span<const std::uint32_t> modes = compute::splatModes(resolve.layout());
  if (resolve.layout() == OpacityBins::DeepTwoSplats) {  // every instance's first hair per texel before any
    begin("opacity first");                             // deep slice is measured from it
    splatAll(modes.front(), std::span<const VkBuffer>(&first, 1));
    end();
    vk::bufferBarrier(ctx, cmd, first, vk::BufferUse::ComputeWrite, vk::BufferUse::ComputeRead);
  }
  const std::uint32_t mode = modes.back();
  // The fine splat writes the first hair too; the two-splat one only reads it (made visible above).
  const std::span<const VkBuffer> written(both, resolve.layout() == OpacityBins::DeepFine ? 2 : 1);
  begin("opacity splat");
  splatAll(mode, written);
  end();
  barriers(written, vk::BufferUse::ComputeWrite, vk::BufferUse::ComputeRead);
  slotBarrier(ctx, cmd, maps, slot, vk::ImageUse::FragmentSampledDiscard, vk::ImageUse::ComputeStorageWrite);
  begin("opacity resolve");
  resolve.recordResolve(cmd, slot);
  end();
  // Heads in the slices (headOpacity > 0) are drawn at global slice coordinates: not into deep maps.
  const bool heads = !resolve.deep() && std::any_of(casters.begin(), casters.end(),
                                                    [](const ShadowCaster& c) { return c.opacity->drawsHead(); });
  if (!heads) {
    slotBarrier(ctx, cmd, maps, slot, vk::ImageUse::ComputeStorageWrite, vk::ImageUse::FragmentSampled);
    return;
  }
  slotBarrier(ctx, cmd, maps, slot, vk::ImageUse::ComputeStorageWrite, vk::ImageUse::ColorAttachment);
  maps.beginRendering(cmd, slot, /*keep=*/true);
  for (const ShadowCaster& c : casters) c.opacity->recordHeadDraw(cmd, slot, c.headToWorld);
  maps.endRendering(cmd);
  slotBarrier(ctx, cmd, maps, slot, vk::ImageUse::ColorAttachment, vk::ImageUse::FragmentSampled);
}
}  // namespace

void recordShadowPasses(const vk::Context& ctx, VkCommandBuffer cmd, const render::ShadowMaps& maps,
                        std::span<const ShadowCaster> casters,
                        const compute::ShadowLight& shadowLight, const compute::BoundsFraming& framing,
                        vk::GpuProfiler* profiler, const render::HeadShadowView& headView) {
  if (casters.empty()) return;
  // Barriers on the whole buffer of every slot's LightSpace: the readers' descriptors bind all of it.
  const VkBuffer light = maps.lightSpace().handle();
  auto lightBarrier = [&](vk::BufferUse from, vk::BufferUse to) { vk::bufferBarrier(ctx, cmd, light, from, to); };
  if (profiler) profiler->begin(cmd, "bounds");
  vk::memoryBarrier(ctx, cmd, vk::BufferUse::ComputeWrite, vk::BufferUse::ComputeRead);  // strand positions
  lightBarrier(vk::BufferUse::GraphicsRead, vk::BufferUse::ComputeWrite);  // last frame's readers: draws,
  lightBarrier(vk::BufferUse::ComputeRead, vk::BufferUse::ComputeWrite);   // splats and the compute raster
  for (const ShadowCaster& c : casters) {
    c.bounds->recordReduce(cmd, shadowLight);
    // Atomics of the next caster after these: order them like any two writers.
    lightBarrier(vk::BufferUse::ComputeWrite, vk::BufferUse::ComputeWrite);
  }
  casters.front().bounds->recordFinalize(cmd, shadowLight, framing);
  lightBarrier(vk::BufferUse::ComputeWrite, vk::BufferUse::GraphicsRead);
  lightBarrier(vk::BufferUse::ComputeWrite, vk::BufferUse::ComputeRead);  // splats, the compute raster
  if (profiler) profiler->end(cmd);

  if (profiler) profiler->begin(cmd, "opacity");
  if (maps.resolvePass())
    recordComputeOpacity(ctx, cmd, maps, casters, shadowLight.slot, profiler);
  else
    recordGraphicsOpacity(ctx, cmd, maps, casters, shadowLight.slot);
  if (profiler) profiler->end(cmd);

  if (headView.params.x == 0.0f) return;
  const VkImage head = maps.headImage().handle();
  if (profiler) profiler->begin(cmd, "head shadow");
  const std::uint32_t slot = shadowLight.slot;
  vk::imageBarrier(ctx, cmd, head, VK_IMAGE_ASPECT_DEPTH_BIT, vk::ImageUse::FragmentSampled, vk::ImageUse::DepthAttachment,
                   1, slot);
  maps.beginHeadRendering(cmd, slot);
  for (const ShadowCaster& c : casters) c.opacity->recordHeadDepth(cmd, headView.viewProj * c.headToWorld);
  maps.endRendering(cmd);
  vk::imageBarrier(ctx, cmd, head, VK_IMAGE_ASPECT_DEPTH_BIT, vk::ImageUse::DepthAttachment, vk::ImageUse::FragmentSampled,
                   1, slot);
  if (profiler) profiler->end(cmd);
}

void recordStrandBounce(const vk::Context& ctx, VkCommandBuffer cmd, const render::ShadowMaps& maps,
                        std::span<const render::StrandBouncePass* const> passes) {
  if (passes.empty()) return;
  const VkImage opacity = maps.image().handle();
  const std::uint32_t layers = maps.image().desc().layers;
  const render::HeadBounceMap& bounce = maps.bounceMap();
  // The samples' last readers (the last frame's shading) before they are rewritten; the positions' writes.
  vk::memoryBarrier(ctx, cmd, vk::BufferUse::ComputeRead, vk::BufferUse::ComputeWrite);
  vk::memoryBarrier(ctx, cmd, vk::BufferUse::VertexRead, vk::BufferUse::ComputeWrite);
  vk::memoryBarrier(ctx, cmd, vk::BufferUse::ComputeWrite, vk::BufferUse::ComputeRead);
  vk::imageBarrier(ctx, cmd, opacity, VK_IMAGE_ASPECT_COLOR_BIT, vk::ImageUse::FragmentSampled,
                   vk::ImageUse::ComputeSampled, layers);
  bounce.transition(cmd, vk::ImageUse::FragmentSampled, vk::ImageUse::ComputeSampled);
  for (const render::StrandBouncePass* pass : passes) pass->record(cmd);
  bounce.transition(cmd, vk::ImageUse::ComputeSampled, vk::ImageUse::FragmentSampled);
  vk::imageBarrier(ctx, cmd, opacity, VK_IMAGE_ASPECT_COLOR_BIT, vk::ImageUse::ComputeSampled,
                   vk::ImageUse::FragmentSampled, layers);
  vk::memoryBarrier(ctx, cmd, vk::BufferUse::ComputeWrite, vk::BufferUse::ComputeRead);
  vk::memoryBarrier(ctx, cmd, vk::BufferUse::ComputeWrite, vk::BufferUse::VertexRead);
}
}  // namespace hp
