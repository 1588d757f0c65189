#pragma once
// Contract: a Renderer's compute strand rasterizer for one camera target and a set of its instances: one
// compute::StrandRasterPass over every instance's strands (all in the same tile lists, so the hair of
// different heads is depth-ordered per pixel; each instance shaded with its own material, look and LUTs
// through its own frame block), and the composite of the hair image over the application's colour.
// Built by Renderer::setRasterTarget or createRasterTarget (one per view of a frame: hp::RasterTarget holds it),
// and rebuilt by the Renderer (the old one retired after its frames) when an instance in it changes its
// strands or is destroyed. A material change
// keeps the target: the instance's shading bindings are rewritten in each frame slot's descriptor sets as
// the first frame recorded with that slot after the change begins (the frame framesInFlight earlier, the
// last to use those sets, is complete by then: the Renderer's frame contract).
//   record(cmd, frame, view, lights)      outside rendering, after the heads were drawn into the depth
//                                         image (in ImageUse::ComputeSampled): per-instance frame blocks,
//                                         then the rasterizer (the skin's bounce from the strands' samples,
//                                         recordShadows's); leaves image() in ImageUse::FragmentSampled
//   recordComposite(cmd, extent)          inside a rendering of the application's attachments
#include <memory>
#include <optional>
#include <span>
#include <vector>

#include "compute/raster/strand_raster_pass.h"
#include "compute/raster/composite_pass.h"
#include "compute/shadows/head_shadow_view.h"
#include "compute/shadows/shadow_maps.h"
#include "compute/renderer/renderer_settings.h"
#include "engine/vk/buffer.h"

namespace hp {
class HairInstance;

class ComputeRaster {
 public:
  // `cache`: the Renderer's pipeline cache, which the target's own pipelines are built through. `previous`:
  // the raster this one replaces (its growing lists' size per segment is where this one's start), or null.
  ComputeRaster(const vk::Context& ctx, const RendererSettings& settings, const render::ShadowMaps& shadows,
                VkExtent2D extent, VkImageView depth, std::span<HairInstance* const> instances,
                VkPipelineCache cache = VK_NULL_HANDLE, const ComputeRaster* previous = nullptr);

  // A frame: its number within a numbering epoch (Renderer::recordEpoch: the numbers may start again after
  // releaseRetired, when nothing is in flight).
  struct FrameId {
    std::uint64_t epoch = 0, frame = 0;
    bool operator==(const FrameId&) const = default;
  };
  // The frame record() last drew (none before the first).
  std::optional<FrameId> drawnFrame() const { return lastFrame_; }
  void record(VkCommandBuffer cmd, FrameId frame, const View& view, const render::FrameLights& lights,
              vk::GpuProfiler* profiler);
  // `instance` (held) shades with new resources (its material's LUTs) from its next frame on.
  void shadingChanged(const HairInstance* instance);
  void recordComposite(VkCommandBuffer cmd, VkExtent2D extent, vk::GpuProfiler* profiler) const;

  bool holds(const HairInstance* instance) const;
  const std::vector<HairInstance*>& instances() const { return instances_; }
  VkExtent2D extent() const { return pass_.extent(); }
  VkImageView depth() const { return depth_; }
  const vk::Image& image() const { return pass_.output(); }
  const vk::Image& motionImage() const { return pass_.motionOutput(); }
  std::vector<glm::vec2> readMotion() const { return pass_.readMotion(); }
  compute::RasterStats readStats() const { return pass_.readStats(); }
  std::uint32_t listEntriesPerSegment() const { return pass_.listEntriesPerSegment(); }
  std::vector<float> readCoverage() const { return pass_.readCoverage(); }

 private:
  static std::vector<vk::Buffer> makeFrameBlocks(const vk::Context& ctx, std::size_t count);
  std::vector<compute::RasterSource> sources() const;
  compute::ShadingWriter shadingWriter(std::size_t source) const;
  // The first view of `frame`: the stale shading bindings of its slot rewritten and, with growing lists, the
  // lists the slot binds sized by its last frame's views (StrandRasterPass::useLists).
  void prepareSlot(FrameId frame, std::uint32_t slot);
  // What each instance draws in a view: its strands (the level of detail's prefix) and its shade variant.
  struct SourceFrames {
    std::vector<std::uint32_t> strandLimits;
    std::vector<compute::ShadeVariant> shading;
  };
  // Each instance's frame block for the view (strands widened by its level of detail); `slot`: the frame slot
  // whose descriptor sets the view binds.
  SourceFrames recordFrameBlocks(VkCommandBuffer cmd, const View& view, const render::FrameLights& lights,
                                 std::uint32_t slot) const;

  const vk::Context& ctx_;
  const render::ShadowMaps& shadows_;
  std::vector<HairInstance*> instances_;
  std::vector<vk::Buffer> frames_;  // per instance: its gpu::RenderFrame, written with vkCmdUpdateBuffer per view
  VkImageView depth_;
  compute::StrandRasterPass pass_;
  std::vector<std::vector<bool>> stale_;   // [frame slot][instance]: its shading bindings name old resources
  std::optional<FrameId> lastFrame_;  // the frame of the views most recently recorded
  render::CompositePass composite_;
  // Growing lists (RasterSettings::growLists): per frame slot, each view's RasterState copied after its
  // binning, and how many views the slot's latest frame recorded; empty when the lists do not grow.
  std::vector<vk::Buffer> listStates_;
  std::vector<std::uint32_t> slotViews_;
};
}  // namespace hp
