#include "engine/hair_system.h"

#include <cmath>

#include "engine/error.h"

#include "engine/vk/barriers.h"
#include "engine/vk/transfer.h"
#include "engine/vk/context.h"

namespace hp {
namespace {
vk::Buffer makeFrameBlock(const vk::Context& ctx) {
  return vk::Buffer(ctx, sizeof(gpu::RenderFrame), VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                    vk::MemoryKind::DeviceLocal, "render frame");
}

const HairSystemSettings& validated(const HairSystemSettings& s) {
  s.simulation.validate();
  s.material.validate();
  s.look.validate();
  s.opacity.validate();
  // The strand shader builds its coverage sample mask in 32 bits (and gl_SampleMask[0] holds 32).
  if (s.formats.samples > VK_SAMPLE_COUNT_16_BIT) throw Error("HairSystemSettings.formats.samples must be at most 16");
  return s;
}

// The opacity map's strand footprint is the width the strands are drawn with (one source: LookSettings).
render::OpacitySettings opacityFor(const HairSystemSettings& s) {
  render::OpacitySettings o = s.opacity;
  o.strandWidth = s.look.strandWidth;
  o.tipWidthFraction = s.look.tipWidthFraction;
  return o;
}

// The embedding path has no CLI in front of it: a bad view must fail here, not as NaN on the device.
void validateView(const DrawView& view) {
  view.light.validate();
  if (view.extent.width == 0 || view.extent.height == 0) throw Error("DrawView.extent must be non-zero");
  for (const glm::mat4* m : {&view.camera.view, &view.camera.proj, &view.headToWorld})
    for (int c = 0; c < 4; ++c)
      for (int r = 0; r < 4; ++r)
        if (!std::isfinite((*m)[c][r])) throw Error("DrawView matrices must be finite");
}
}  // namespace

HairSystem::HairSystem(const vk::Context& ctx, const HairAsset& asset, const HairSystemSettings& settings,
                       const glm::mat4& initialHead)
    : ctx_(ctx),
      settings_(validated(settings)),
      simulate_(ctx, asset, settings.simulation, initialHead),
      strands_(ctx, asset.guides.guideCount(), asset.guides.particlesPerGuide, asset.topology, settings.strands),
      tessellate_(ctx, simulate_.positions(), strands_),
      interpolate_(ctx, strands_),
      marschner_(ctx, settings.material, settings.lutMode),
      frameBlock_(makeFrameBlock(ctx)),
      bounds_(ctx, strands_),
      opacity_(ctx, strands_, asset.head, bounds_.lightSpace(), opacityFor(settings)),
      head_(ctx, asset.head, frameBlock_, opacity_.shadowInputs(), settings.formats),
      strandPass_(ctx, strands_, marschner_, frameBlock_, opacity_.shadowInputs(), settings.formats) {
  // A valid frame block from the start, so a draw recorded before the first recordPrepareDraw reads
  // sane values (vertex count, matrices) instead of uninitialised memory.
  const gpu::RenderFrame initial =
      render::makeRenderFrame(CameraMatrices{}, {1, 1}, LightSpec{}, settings_.material, settings_.look,
                              strands_.layout().verticesPerStrand, settings_.opacity);
  vk::upload<gpu::RenderFrame>(ctx, frameBlock_, std::span(&initial, 1), vk::BufferUse::GraphicsRead);
}

void HairSystem::recordUpdate(VkCommandBuffer cmd, const HeadMotion& motion, vk::GpuProfiler* profiler) {
  // The previous frame drew the strands and chained compute passes over the same buffers.
  vk::memoryBarrier(cmd, vk::BufferUse::VertexRead, vk::BufferUse::ComputeWrite);
  vk::memoryBarrier(cmd, vk::BufferUse::ComputeWrite, vk::BufferUse::ComputeWrite);
  simulate_.record(cmd, motion, profiler);
  vk::memoryBarrier(cmd, vk::BufferUse::ComputeWrite, vk::BufferUse::ComputeRead);
  tessellate_.record(cmd, profiler);
  vk::memoryBarrier(cmd, vk::BufferUse::ComputeWrite, vk::BufferUse::ComputeRead);
  interpolate_.record(cmd, profiler);
}

void HairSystem::recordPrepareDraw(VkCommandBuffer cmd, const DrawView& view, vk::GpuProfiler* profiler) {
  validateView(view);
  gpu::RenderFrame frame = render::makeRenderFrame(view.camera, view.extent, view.light, settings_.material,
                                                   settings_.look, strands_.layout().verticesPerStrand,
                                                   settings_.opacity);
  vk::bufferBarrier(cmd, frameBlock_.handle(), vk::BufferUse::GraphicsRead, vk::BufferUse::TransferDst);
  vkCmdUpdateBuffer(cmd, frameBlock_.handle(), 0, sizeof(frame), &frame);
  vk::bufferBarrier(cmd, frameBlock_.handle(), vk::BufferUse::TransferDst, vk::BufferUse::GraphicsRead);
  vk::memoryBarrier(cmd, vk::BufferUse::ComputeWrite, vk::BufferUse::VertexRead);
  if (!settings_.opacity.enabled) return;
  compute::BoundsFraming framing;
  framing.resolution = settings_.opacity.resolution;
  framing.marginWorld = 0.5f * settings_.look.strandWidth * gpu::WIDTH_SCALE_MAX;
  recordShadowPasses(cmd, bounds_, opacity_, shadowLightOf(view.light), framing, view.headToWorld, profiler);
}

compute::ShadowLight shadowLightOf(const LightSpec& light) {
  const glm::vec3 toward = glm::normalize(light.direction);
  if (light.type == LightSpec::Type::Directional) return compute::ShadowLight(toward);
  return compute::ShadowLight::makeSpot(light.position, toward, glm::radians(light.coneDeg));
}

void recordShadowPasses(VkCommandBuffer cmd, const compute::BoundsPass& bounds, const render::OpacityPass& opacity,
                        const compute::ShadowLight& shadowLight, const compute::BoundsFraming& framing,
                        const glm::mat4& headToWorld, vk::GpuProfiler* profiler) {
  const VkBuffer light = bounds.lightSpace().handle();
  if (profiler) profiler->begin(cmd, "bounds");
  vk::memoryBarrier(cmd, vk::BufferUse::ComputeWrite, vk::BufferUse::ComputeRead);        // strand positions
  vk::bufferBarrier(cmd, light, vk::BufferUse::VertexRead, vk::BufferUse::ComputeWrite);  // last frame's readers
  bounds.recordReduce(cmd, shadowLight);
  vk::bufferBarrier(cmd, light, vk::BufferUse::ComputeWrite, vk::BufferUse::ComputeWrite);
  bounds.recordFinalize(cmd, shadowLight, framing);
  vk::bufferBarrier(cmd, light, vk::BufferUse::ComputeWrite, vk::BufferUse::VertexRead);
  if (profiler) profiler->end(cmd);

  const vk::Image& maps = opacity.image();
  if (profiler) profiler->begin(cmd, "opacity");
  vk::imageBarrier(cmd, maps.handle(), VK_IMAGE_ASPECT_COLOR_BIT, vk::ImageUse::FragmentSampled,
                   vk::ImageUse::ColorAttachment, gpu::OPACITY_TARGETS);
  opacity.record(cmd, headToWorld);
  vk::imageBarrier(cmd, maps.handle(), VK_IMAGE_ASPECT_COLOR_BIT, vk::ImageUse::ColorAttachment,
                   vk::ImageUse::FragmentSampled, gpu::OPACITY_TARGETS);
  if (profiler) profiler->end(cmd);
}

void HairSystem::recordDraw(VkCommandBuffer cmd, const DrawView& view, vk::GpuProfiler* profiler) const {
  if (profiler) profiler->begin(cmd, "head");
  head_.draw(cmd, view.extent, view.headToWorld);
  if (profiler) profiler->end(cmd);
  if (profiler) profiler->begin(cmd, "shade");
  strandPass_.draw(cmd, view.extent, view.lines);
  if (profiler) profiler->end(cmd);
}

void HairSystem::setMaterial(const HairMaterial& material, LutMode mode) {
  try {
    if (!marschner_.rebuild(material, mode)) return;
  } catch (...) {
    // A rebuild that failed part-way (out of memory) may have replaced some images: rebind so the
    // strand pass never keeps descriptors to destroyed views, then report the failure.
    strandPass_.bind(strands_, marschner_, frameBlock_, opacity_.shadowInputs());
    throw;
  }
  settings_.material = material;
  settings_.lutMode = mode;
  strandPass_.bind(strands_, marschner_, frameBlock_, opacity_.shadowInputs());
}
}  // namespace hp
