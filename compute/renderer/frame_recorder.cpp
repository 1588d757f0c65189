#include "compute/renderer/frame_recorder.h"

#include <algorithm>
#include <span>

#include "engine/vk/barriers.h"
#include "shaders/shared/opacity.h"

namespace hp {
void recordUpdatePasses(const vk::Context& ctx, VkCommandBuffer cmd, std::span<const UpdateWork> work,
                        vk::GpuProfiler* profiler) {
  // The previous frame drew the strands and chained compute passes over the same buffers.
  vk::memoryBarrier(ctx, cmd, vk::BufferUse::VertexRead, vk::BufferUse::ComputeWrite);
  vk::memoryBarrier(ctx, cmd, vk::BufferUse::ComputeWrite, vk::BufferUse::ComputeWrite);
  for (const UpdateWork& w : work) w.simulate->record(cmd, w.motion, profiler);
  vk::memoryBarrier(ctx, cmd, vk::BufferUse::ComputeWrite, vk::BufferUse::ComputeRead);
  for (const UpdateWork& w : work) w.tessellate->record(cmd, profiler);
  vk::memoryBarrier(ctx, cmd, vk::BufferUse::ComputeWrite, vk::BufferUse::ComputeRead);
  for (const UpdateWork& w : work) w.interpolate->record(cmd, profiler);
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
void recordGraphicsOpacity(const vk::Context& ctx, VkCommandBuffer cmd, const render::ShadowMaps& maps,
                           std::span<const ShadowCaster> casters) {
  const VkImage image = maps.image().handle();
  vk::imageBarrier(ctx, cmd, image, VK_IMAGE_ASPECT_COLOR_BIT, vk::ImageUse::FragmentSampled,
                   vk::ImageUse::ColorAttachment, gpu::OPACITY_LAYERS);
  maps.beginRendering(cmd);
  for (const ShadowCaster& c : casters) c.opacity->recordDraws(cmd, c.headToWorld, c.strandWidth, c.strandLimit);
  maps.endRendering(cmd);
  vk::imageBarrier(ctx, cmd, image, VK_IMAGE_ASPECT_COLOR_BIT, vk::ImageUse::ColorAttachment,
                   vk::ImageUse::FragmentSampled, gpu::OPACITY_LAYERS);
}

// Clear the bins, every caster's splats (atomics: ordered like any two writers), the resolve into the
// maps, then the heads that go into the slices, drawn over the resolved maps.
void recordComputeOpacity(const vk::Context& ctx, VkCommandBuffer cmd, const render::ShadowMaps& maps,
                          std::span<const ShadowCaster> casters) {
  const compute::OpacityResolvePass& resolve = *maps.resolvePass();
  const VkBuffer bins = resolve.bins().handle(), first = resolve.first().handle();
  const VkImage image = maps.image().handle();
  // What recordClear fills: the bins, and the first-hair buffer for deep maps only.
  const VkBuffer fills[] = {bins, first};
  const std::span<const VkBuffer> cleared(fills, resolve.deep() ? 2 : 1);
  for (VkBuffer b : cleared)  // last frame's resolve and deep splats read them
    vk::bufferBarrier(ctx, cmd, b, vk::BufferUse::ComputeRead, vk::BufferUse::TransferDst);
  resolve.recordClear(cmd);
  for (VkBuffer b : cleared) vk::bufferBarrier(ctx, cmd, b, vk::BufferUse::TransferDst, vk::BufferUse::ComputeWrite);
  auto splatAll = [&](std::uint32_t mode, VkBuffer target) {
    for (std::size_t i = 0; i < casters.size(); ++i) {
      if (i > 0) vk::bufferBarrier(ctx, cmd, target, vk::BufferUse::ComputeWrite, vk::BufferUse::ComputeWrite);
      casters[i].opacity->recordSplats(cmd, casters[i].strandWidth, mode, casters[i].strandLimit);
    }
  };
  if (resolve.deep()) {  // every instance's first hair per texel before any deep slice is measured from it
    splatAll(gpu::OPACITY_SPLAT_MODE_FIRST, first);
    vk::bufferBarrier(ctx, cmd, first, vk::BufferUse::ComputeWrite, vk::BufferUse::ComputeRead);
  }
  splatAll(resolve.deep() ? gpu::OPACITY_SPLAT_MODE_DEEP : gpu::OPACITY_SPLAT_MODE_PLAIN, bins);
  vk::bufferBarrier(ctx, cmd, bins, vk::BufferUse::ComputeWrite, vk::BufferUse::ComputeRead);
  vk::imageBarrier(ctx, cmd, image, VK_IMAGE_ASPECT_COLOR_BIT, vk::ImageUse::FragmentSampledDiscard,
                   vk::ImageUse::ComputeStorageWrite, gpu::OPACITY_LAYERS);
  resolve.recordResolve(cmd);
  // Heads in the slices (headOpacity > 0) are drawn at global slice coordinates: not into deep maps.
  const bool heads = !resolve.deep() && std::any_of(casters.begin(), casters.end(),
                                                    [](const ShadowCaster& c) { return c.opacity->drawsHead(); });
  if (!heads) {
    vk::imageBarrier(ctx, cmd, image, VK_IMAGE_ASPECT_COLOR_BIT, vk::ImageUse::ComputeStorageWrite,
                     vk::ImageUse::FragmentSampled, gpu::OPACITY_LAYERS);
    return;
  }
  vk::imageBarrier(ctx, cmd, image, VK_IMAGE_ASPECT_COLOR_BIT, vk::ImageUse::ComputeStorageWrite,
                   vk::ImageUse::ColorAttachment, gpu::OPACITY_LAYERS);
  maps.beginRendering(cmd, /*keep=*/true);
  for (const ShadowCaster& c : casters) c.opacity->recordHeadDraw(cmd, c.headToWorld);
  maps.endRendering(cmd);
  vk::imageBarrier(ctx, cmd, image, VK_IMAGE_ASPECT_COLOR_BIT, vk::ImageUse::ColorAttachment,
                   vk::ImageUse::FragmentSampled, gpu::OPACITY_LAYERS);
}
}  // namespace

void recordShadowPasses(const vk::Context& ctx, VkCommandBuffer cmd, const render::ShadowMaps& maps,
                        std::span<const ShadowCaster> casters,
                        const compute::ShadowLight& shadowLight, const compute::BoundsFraming& framing,
                        vk::GpuProfiler* profiler, const render::HeadShadowView& headView) {
  if (casters.empty()) return;
  const VkBuffer light = maps.lightSpace().handle();
  if (profiler) profiler->begin(cmd, "bounds");
  vk::memoryBarrier(ctx, cmd, vk::BufferUse::ComputeWrite, vk::BufferUse::ComputeRead);        // strand positions
  vk::bufferBarrier(ctx, cmd, light, vk::BufferUse::GraphicsRead, vk::BufferUse::ComputeWrite);  // last frame's readers
  for (const ShadowCaster& c : casters) {
    c.bounds->recordReduce(cmd, shadowLight);
    // Atomics of the next caster after these: order them like any two writers.
    vk::bufferBarrier(ctx, cmd, light, vk::BufferUse::ComputeWrite, vk::BufferUse::ComputeWrite);
  }
  casters.front().bounds->recordFinalize(cmd, shadowLight, framing);
  vk::bufferBarrier(ctx, cmd, light, vk::BufferUse::ComputeWrite, vk::BufferUse::GraphicsRead);
  if (maps.resolvePass()) vk::bufferBarrier(ctx, cmd, light, vk::BufferUse::ComputeWrite, vk::BufferUse::ComputeRead);
  if (profiler) profiler->end(cmd);

  if (profiler) profiler->begin(cmd, "opacity");
  if (maps.resolvePass())
    recordComputeOpacity(ctx, cmd, maps, casters);
  else
    recordGraphicsOpacity(ctx, cmd, maps, casters);
  if (profiler) profiler->end(cmd);

  if (headView.params.x == 0.0f) return;
  const VkImage head = maps.headImage().handle();
  if (profiler) profiler->begin(cmd, "head shadow");
  vk::imageBarrier(ctx, cmd, head, VK_IMAGE_ASPECT_DEPTH_BIT, vk::ImageUse::FragmentSampled, vk::ImageUse::DepthAttachment);
  maps.beginHeadRendering(cmd);
  for (const ShadowCaster& c : casters) c.opacity->recordHeadDepth(cmd, headView.viewProj * c.headToWorld);
  maps.endRendering(cmd);
  vk::imageBarrier(ctx, cmd, head, VK_IMAGE_ASPECT_DEPTH_BIT, vk::ImageUse::DepthAttachment, vk::ImageUse::FragmentSampled);
  if (profiler) profiler->end(cmd);
}
}  // namespace hp
