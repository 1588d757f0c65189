#include "engine/frame_recorder.h"

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

void recordShadowPasses(const vk::Context& ctx, VkCommandBuffer cmd, const render::ShadowMaps& maps,
                        std::span<const ShadowCaster> casters,
                        const compute::ShadowLight& shadowLight, const compute::BoundsFraming& framing,
                        vk::GpuProfiler* profiler, const render::HeadShadowView& headView) {
  if (casters.empty()) return;
  const VkBuffer light = maps.lightSpace().handle();
  if (profiler) profiler->begin(cmd, "bounds");
  vk::memoryBarrier(ctx, cmd, vk::BufferUse::ComputeWrite, vk::BufferUse::ComputeRead);        // strand positions
  vk::bufferBarrier(ctx, cmd, light, vk::BufferUse::VertexRead, vk::BufferUse::ComputeWrite);  // last frame's readers
  for (const ShadowCaster& c : casters) {
    c.bounds->recordReduce(cmd, shadowLight);
    // Atomics of the next caster after these: order them like any two writers.
    vk::bufferBarrier(ctx, cmd, light, vk::BufferUse::ComputeWrite, vk::BufferUse::ComputeWrite);
  }
  casters.front().bounds->recordFinalize(cmd, shadowLight, framing);
  vk::bufferBarrier(ctx, cmd, light, vk::BufferUse::ComputeWrite, vk::BufferUse::VertexRead);
  if (profiler) profiler->end(cmd);

  const vk::Image& image = maps.image();
  if (profiler) profiler->begin(cmd, "opacity");
  vk::imageBarrier(ctx, cmd, image.handle(), VK_IMAGE_ASPECT_COLOR_BIT, vk::ImageUse::FragmentSampled,
                   vk::ImageUse::ColorAttachment, gpu::OPACITY_TARGETS);
  maps.beginRendering(cmd);
  for (const ShadowCaster& c : casters) c.opacity->recordDraws(cmd, c.headToWorld, c.strandWidth);
  maps.endRendering(cmd);
  vk::imageBarrier(ctx, cmd, image.handle(), VK_IMAGE_ASPECT_COLOR_BIT, vk::ImageUse::ColorAttachment,
                   vk::ImageUse::FragmentSampled, gpu::OPACITY_TARGETS);
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
