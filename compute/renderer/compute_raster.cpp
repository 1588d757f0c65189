#include "compute/renderer/compute_raster.h"

#include <algorithm>
#include <cstring>
#include <string>

#include "engine/core/error.h"
#include "compute/raster/raster_shading.h"
#include "compute/renderer/hair_instance.h"
#include "engine/vk/barriers.h"
#include "engine/vk/context.h"
#include "shaders/shared/raster.h"
#include "shaders/shared/render.h"

namespace hp {
namespace {
compute::RasterSettings rasterSettingsOf(const RendererSettings& settings, const ComputeRaster* previous) {
  compute::RasterSettings r = settings.rasterSettings;
  r.motion = settings.motionVectors;
  r.reversedDepth = settings.formats.reversedDepth;
  // A rebuilt target's growing lists start where its predecessor's had grown (no frames of full lists again).
  if (previous) r.listStartPerSegment = std::max(r.listStartPerSegment, previous->listEntriesPerSegment());
  return r;
}

// With growing lists, per frame slot: room for the RasterState of each view the slot's frame records.
std::vector<vk::Buffer> makeListStates(const vk::Context& ctx, const RendererSettings& settings) {
  std::vector<vk::Buffer> states;
  if (!settings.rasterSettings.growLists) return states;
  for (std::uint32_t slot = 0; slot < settings.framesInFlight; ++slot)
    states.emplace_back(ctx, sizeof(gpu::RasterState) * settings.maxViewsPerFrame, VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                        vk::MemoryKind::Readback, "raster list needs [slot " + std::to_string(slot) + "]");
  return states;
}
}  // namespace

std::vector<vk::Buffer> ComputeRaster::makeFrameBlocks(const vk::Context& ctx, std::size_t count) {
  std::vector<vk::Buffer> frames;
  for (std::size_t i = 0; i < count; ++i)
    frames.emplace_back(ctx, sizeof(gpu::RenderFrame), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                        vk::MemoryKind::DeviceLocal, "raster frame [instance " + std::to_string(i) + "]");
  return frames;
}

ComputeRaster::ComputeRaster(const vk::Context& ctx, const RendererSettings& settings,
                             const render::ShadowMaps& shadows, VkExtent2D extent, VkImageView depth,
                             std::span<HairInstance* const> instances, VkPipelineCache cache,
                             const ComputeRaster* previous)
    : ctx_(ctx),
      shadows_(shadows),
      instances_(instances.begin(), instances.end()),
      frames_(makeFrameBlocks(ctx, instances.size())),
      depth_(depth),
      pass_(ctx, sources(), extent, rasterSettingsOf(settings, previous), std::uint32_t(settings.formats.samples), cache,
            settings.framesInFlight),
      stale_(settings.framesInFlight, std::vector<bool>(instances.size(), false)),
      composite_(ctx, settings.formats, settings.velocityOutput, cache),
      listStates_(makeListStates(ctx, settings)),
      slotViews_(settings.framesInFlight, 0) {
  pass_.setDepth(depth);
  // Each instance's fibre compiled into the shade pass, with and without the light loop (a fibre changed later,
  // in the frame loop, shades with the run-time form: compute/raster/shade_variant.h).
  for (const HairInstance* instance : instances_) {
    const bool dual = instance->settings().look.scattering == render::Scattering::Dual;
    const std::uint32_t fibre = gpu::hairFibre(instance->marschner().params().control.x, dual);
    pass_.prepareShading({false, fibre});
    pass_.prepareShading({true, fibre});
  }
  composite_.setInput(pass_.output().view(), pass_.nearOutput().view(), pass_.nearMask().view(),
                     pass_.motionOutput().view());
}

std::vector<compute::RasterSource> ComputeRaster::sources() const {
  if (instances_.empty()) throw Error("Renderer: a raster target needs an instance to rasterize");
  std::vector<compute::RasterSource> sources;
  for (std::size_t i = 0; i < instances_.size(); ++i) sources.push_back({&instances_[i]->strands(), shadingWriter(i)});
  return sources;
}

compute::ShadingWriter ComputeRaster::shadingWriter(std::size_t source) const {
  const HairInstance* instance = instances_[source];
  const VkBuffer frame = frames_[source].handle();
  return [this, instance, frame](const vk::DescriptorSet& set) {
    compute::writeRasterShading(set, frame, instance->marschner(), shadows_.inputs());
  };
}

void ComputeRaster::shadingChanged(const HairInstance* instance) {
  const auto it = std::find(instances_.begin(), instances_.end(), instance);
  if (it == instances_.end()) throw Error("ComputeRaster::shadingChanged: the instance is not in the raster target");
  for (std::vector<bool>& slot : stale_) slot[std::size_t(it - instances_.begin())] = true;
}

void ComputeRaster::prepareSlot(FrameId frame, std::uint32_t slot) {
  if (lastFrame_ == frame) return;  // a later view of the same frame: its sets are bound already
  lastFrame_ = frame;
  for (std::size_t source = 0; source < instances_.size(); ++source) {
    if (!stale_[slot][source]) continue;
    pass_.rebindShading(std::uint32_t(source), slot, shadingWriter(source));
    stale_[slot][source] = false;
  }
  if (listStates_.empty()) return;
  // The slot's last frame is complete (the frame contract): the most any of its views asked of the lists.
  const vk::Buffer& states = listStates_[slot];
  states.invalidate();
  std::uint64_t need = 0;
  for (std::uint32_t view = 0; view < slotViews_[slot]; ++view) {
    gpu::RasterState state;
    std::memcpy(&state, static_cast<const std::byte*>(states.mapped()) + view * sizeof(state), sizeof(state));
    need = std::max(need, compute::listNeed(state));
  }
  slotViews_[slot] = 0;
  pass_.useLists(slot, need);
}

bool ComputeRaster::holds(const HairInstance* instance) const {
  return std::find(instances_.begin(), instances_.end(), instance) != instances_.end();
}

ComputeRaster::SourceFrames ComputeRaster::recordFrameBlocks(VkCommandBuffer cmd, const View& view,
                                                             const render::FrameLights& lights,
                                                             std::uint32_t slot) const {
  SourceFrames sources;
  for (std::size_t i = 0; i < instances_.size(); ++i) {
    const HairInstance& instance = *instances_[i];
    const float fraction = instance.lodFraction(view.camera.position);
    sources.strandLimits.push_back(instance.lodStrands(fraction));
    gpu::RenderFrame frame =
        instance.frameBlock(view.camera, view.extent, lights, lodLook(instance.settings().look, fraction));
    render::setViewMotion(frame, view.extent, view.jitter, view.previousViewProj);
    // A slot whose sets still bind the instance's previous material (changed after this frame's first view)
    // shades with the run-time fibre, which reads the model from the bound parameter block.
    compute::ShadeVariant variant = compute::shadeVariantOf(frame, instance.marschner().params());
    if (stale_[slot][i]) variant.fibre = gpu::HAIR_FIBRE_RUNTIME;
    sources.shading.push_back(variant);
    const VkBuffer block = frames_[i].handle();
    vk::bufferBarrier(ctx_, cmd, block, vk::BufferUse::ComputeRead, vk::BufferUse::TransferDst);
    ctx_.fn().vkCmdUpdateBuffer(cmd, block, 0, sizeof(frame), &frame);
    vk::bufferBarrier(ctx_, cmd, block, vk::BufferUse::TransferDst, vk::BufferUse::ComputeRead);
  }
  return sources;
}

void ComputeRaster::record(VkCommandBuffer cmd, FrameId frame, const View& view,
                           const render::FrameLights& lights, vk::GpuProfiler* profiler) {
  const auto slot = std::uint32_t(frame.frame % stale_.size());  // the frame slot: one per frame in flight
  prepareSlot(frame, slot);
  const SourceFrames sources = recordFrameBlocks(cmd, view, lights, slot);
  // The graphics readers' states (recordShadows) extended to compute for the pass, then back, so the
  // next frame's barriers (which wait on vertex/fragment readers) still cover these reads.
  const VkBuffer lightSpace = shadows_.lightSpace().handle();
  const VkImage maps = shadows_.image().handle();
  const VkImage head = shadows_.headImage().handle();
  const std::uint32_t mapLayers = shadows_.image().desc().layers, headLayers = shadows_.headImage().desc().layers;
  vk::memoryBarrier(ctx_, cmd, vk::BufferUse::ComputeWrite, vk::BufferUse::ComputeRead);  // strand buffers
  vk::imageBarrier(ctx_, cmd, head, VK_IMAGE_ASPECT_DEPTH_BIT, vk::ImageUse::FragmentSampled, vk::ImageUse::ComputeSampled,
                   headLayers);
  vk::bufferBarrier(ctx_, cmd, lightSpace, vk::BufferUse::GraphicsRead, vk::BufferUse::ComputeRead);
  vk::imageBarrier(ctx_, cmd, maps, VK_IMAGE_ASPECT_COLOR_BIT, vk::ImageUse::FragmentSampled,
                   vk::ImageUse::ComputeSampled, mapLayers);
  pass_.record(cmd, profiler, sources.strandLimits, sources.shading, slot);
  if (!listStates_.empty() && slotViews_[slot] * sizeof(gpu::RasterState) < listStates_[slot].size())
    pass_.recordStateCopy(cmd, listStates_[slot], slotViews_[slot]++ * sizeof(gpu::RasterState));
  vk::bufferBarrier(ctx_, cmd, lightSpace, vk::BufferUse::ComputeRead, vk::BufferUse::GraphicsRead);
  vk::imageBarrier(ctx_, cmd, maps, VK_IMAGE_ASPECT_COLOR_BIT, vk::ImageUse::ComputeSampled,
                   vk::ImageUse::FragmentSampled, mapLayers);
  vk::imageBarrier(ctx_, cmd, head, VK_IMAGE_ASPECT_DEPTH_BIT, vk::ImageUse::ComputeSampled, vk::ImageUse::FragmentSampled,
                   headLayers);
}

void ComputeRaster::recordComposite(VkCommandBuffer cmd, VkExtent2D extent, vk::GpuProfiler* profiler) const {
  if (profiler) profiler->beginInRendering(cmd, "composite");
  composite_.draw(cmd, extent);
  if (profiler) profiler->end(cmd);
}
}  // namespace hp
