#include "engine/compute_raster.h"

#include <algorithm>

#include "engine/error.h"
#include "engine/hair_instance.h"
#include "engine/vk/barriers.h"
#include "engine/vk/context.h"
#include "shaders/shared/raster.h"
#include "shaders/shared/render.h"

namespace hp {
std::vector<vk::Buffer> ComputeRaster::makeFrameBlocks(const vk::Context& ctx, std::size_t count) {
  std::vector<vk::Buffer> frames;
  for (std::size_t i = 0; i < count; ++i)
    frames.emplace_back(ctx, sizeof(gpu::RenderFrame), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                        vk::MemoryKind::DeviceLocal, "raster frame [instance " + std::to_string(i) + "]");
  return frames;
}

ComputeRaster::ComputeRaster(const vk::Context& ctx, const RendererSettings& settings,
                             const render::ShadowMaps& shadows, VkExtent2D extent, VkImageView depth,
                             std::span<HairInstance* const> instances, vk::PipelineLibrary* library)
    : ctx_(ctx),
      shadows_(shadows),
      instances_(instances.begin(), instances.end()),
      frames_(makeFrameBlocks(ctx, instances.size())),
      depth_(depth),
      bounceMap_(ctx),
      pass_(ctx, sources(), extent, settings.rasterSettings),
      bounce_(makeBouncePasses(library)),
      composite_(ctx, settings.formats) {
  pass_.setDepth(depth);
  composite_.setInput(pass_.output().view());
}

std::vector<compute::RasterSource> ComputeRaster::sources() const {
  if (instances_.empty()) throw Error("Renderer::setRasterTarget: no instance to rasterize");
  std::vector<compute::RasterSource> sources;
  for (std::size_t i = 0; i < instances_.size(); ++i) {
    const HairInstance* instance = instances_[i];
    const VkBuffer frame = frames_[i].handle();
    sources.push_back({&instance->strands(), [this, instance, frame](const vk::DescriptorSet& set) {
                         // Storage buffers: the raster shaders read no uniform blocks (compute/strand_raster_pass.cpp).
                         set.writeStorageBuffer(gpu::RENDER_BINDING_FRAME, frame);
                         instance->marschner().writeDescriptors(set, gpu::RENDER_BINDING_MARSCHNER,
                                                                gpu::RENDER_BINDING_LUT_M, gpu::RENDER_BINDING_LUT_N0,
                                                                gpu::RENDER_BINDING_LUT_N1,
                                                                VK_DESCRIPTOR_TYPE_STORAGE_BUFFER);
                         const render::ShadowInputs in = shadows_.inputs();
                         set.writeSampledImage(gpu::RENDER_BINDING_OPACITY, in.opacityView, in.sampler);
                         set.writeStorageBuffer(gpu::RENDER_BINDING_LIGHT, in.lightSpace);
                         set.writeSampledImage(gpu::RENDER_BINDING_HEAD_SHADOW, in.headShadowView, in.headShadowSampler);
                         set.writeSampledImage(gpu::RASTER_BINDING_BOUNCE_FLUX, bounceMap_.fluxView(), bounceMap_.sampler());
                         set.writeSampledImage(gpu::RASTER_BINDING_BOUNCE_POSITION, bounceMap_.positionView(),
                                               bounceMap_.sampler());
                       }});
  }
  return sources;
}

std::vector<render::HeadBouncePass> ComputeRaster::makeBouncePasses(vk::PipelineLibrary* library) const {
  std::vector<render::HeadBouncePass> passes;
  passes.reserve(instances_.size());
  for (std::size_t i = 0; i < instances_.size(); ++i)
    passes.emplace_back(ctx_, instances_[i]->headPass(), frames_[i].handle(), shadows_.inputs(), library);
  return passes;
}

bool ComputeRaster::wantsBounce(const render::HeadShadowView& headShadow) const {
  if (headShadow.params.x == 0.0f) return false;  // no head (or shadows off): nothing to bounce from
  return std::any_of(instances_.begin(), instances_.end(),
                     [](const HairInstance* i) { return i->settings().look.skinBounce; });
}

bool ComputeRaster::holds(const HairInstance* instance) const {
  return std::find(instances_.begin(), instances_.end(), instance) != instances_.end();
}

// The frame blocks are read by the raster (compute) and the bounce map's draw (vertex and fragment).
void ComputeRaster::recordFrameBlocks(VkCommandBuffer cmd, const View& view, const LightSpec& light,
                                      const render::HeadShadowView& headShadow, bool bounce) const {
  for (std::size_t i = 0; i < instances_.size(); ++i) {
    const HairInstance& instance = *instances_[i];
    gpu::RenderFrame frame = render::makeRenderFrame(view.camera, view.extent, light, instance.settings().material,
                                                     instance.settings().look,
                                                     instance.strands().layout().verticesPerStrand, shadows_.settings());
    frame.headShadowViewProj = headShadow.viewProj;
    frame.headShadow = headShadow.params;
    frame.headBounce = glm::vec4(bounce && instance.settings().look.skinBounce ? 1.0f : 0.0f,
                                 headShadow.extentWorld / float(gpu::RENDER_BOUNCE_RESOLUTION), 0.0f, 0.0f);
    const VkBuffer block = frames_[i].handle();
    vk::bufferBarrier(ctx_, cmd, block, vk::BufferUse::ComputeRead, vk::BufferUse::TransferDst);
    vk::bufferBarrier(ctx_, cmd, block, vk::BufferUse::GraphicsRead, vk::BufferUse::TransferDst);
    ctx_.fn().vkCmdUpdateBuffer(cmd, block, 0, sizeof(frame), &frame);
    vk::bufferBarrier(ctx_, cmd, block, vk::BufferUse::TransferDst, vk::BufferUse::ComputeRead);
    vk::bufferBarrier(ctx_, cmd, block, vk::BufferUse::TransferDst, vk::BufferUse::GraphicsRead);
  }
}

// Inputs as recordShadows left them: opacity maps FragmentSampled, LightSpace VertexRead.
void ComputeRaster::recordBounce(VkCommandBuffer cmd, vk::GpuProfiler* profiler) const {
  if (profiler) profiler->begin(cmd, "head bounce");
  bounceMap_.begin(cmd);
  for (std::size_t i = 0; i < instances_.size(); ++i) bounce_[i].draw(cmd, instances_[i]->headToWorld());
  bounceMap_.end(cmd);
  if (profiler) profiler->end(cmd);
}

void ComputeRaster::record(VkCommandBuffer cmd, const View& view, const LightSpec& light,
                           const render::HeadShadowView& headShadow, vk::GpuProfiler* profiler) const {
  const bool bounce = wantsBounce(headShadow);
  recordFrameBlocks(cmd, view, light, headShadow, bounce);
  if (bounce) recordBounce(cmd, profiler);
  // The graphics readers' states (recordShadows) extended to compute for the pass, then back, so the
  // next frame's barriers (which wait on vertex/fragment readers) still cover these reads.
  const VkBuffer lightSpace = shadows_.lightSpace().handle();
  const VkImage maps = shadows_.image().handle();
  const VkImage head = shadows_.headImage().handle();
  vk::memoryBarrier(ctx_, cmd, vk::BufferUse::ComputeWrite, vk::BufferUse::ComputeRead);  // strand buffers
  vk::imageBarrier(ctx_, cmd, head, VK_IMAGE_ASPECT_DEPTH_BIT, vk::ImageUse::FragmentSampled, vk::ImageUse::ComputeSampled);
  vk::bufferBarrier(ctx_, cmd, lightSpace, vk::BufferUse::VertexRead, vk::BufferUse::ComputeRead);
  vk::imageBarrier(ctx_, cmd, maps, VK_IMAGE_ASPECT_COLOR_BIT, vk::ImageUse::FragmentSampled,
                   vk::ImageUse::ComputeSampled, gpu::OPACITY_LAYERS);
  pass_.record(cmd, profiler);
  vk::bufferBarrier(ctx_, cmd, lightSpace, vk::BufferUse::ComputeRead, vk::BufferUse::VertexRead);
  vk::imageBarrier(ctx_, cmd, maps, VK_IMAGE_ASPECT_COLOR_BIT, vk::ImageUse::ComputeSampled,
                   vk::ImageUse::FragmentSampled, gpu::OPACITY_LAYERS);
  vk::imageBarrier(ctx_, cmd, head, VK_IMAGE_ASPECT_DEPTH_BIT, vk::ImageUse::ComputeSampled, vk::ImageUse::FragmentSampled);
}

void ComputeRaster::recordComposite(VkCommandBuffer cmd, VkExtent2D extent, vk::GpuProfiler* profiler) const {
  if (profiler) profiler->begin(cmd, "composite");
  composite_.draw(cmd, extent);
  if (profiler) profiler->end(cmd);
}
}  // namespace hp
