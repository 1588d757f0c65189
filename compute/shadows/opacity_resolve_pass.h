#pragma once
// Contract: the end of the compute opacity pass (shaders/opacity_resolve.glsl, shared/opacity.h). Owns
// the bins every instance's OpacitySplatPass adds into (uint[resolution^2 x 16], fixed point; deep maps
// in one splat: OPACITY_DEEP_BINS per texel in whole groups of OPACITY_FINE_GROUP texels) and the
// first-hair buffer, and turns them into the opacity maps: per texel the prefix sum over its 16 slices,
// written as the 4 RGBA layers the graphics pass would have blended (RGBA32F or RGBA16F; storage usage
// required).
//
// Recording, barriers by the caller (the frame recorder): recordClear (transfer fills of the bins and, for
// deep maps, the first-hair buffer; before it the previous frame's reads are done: ComputeRead ->
// TransferDst), the splats
// (TransferDst -> ComputeWrite before them), then recordResolve (bins, and for DeepFine the first-hair
// buffer too, ComputeWrite -> ComputeRead; the maps in ImageUse::ComputeStorageWrite). Throws hp::Error if
// the bins exceed maxStorageBufferRange.
#include "hairpipe_volk.h"

#include <memory>
#include <span>
#include <vector>

#include "engine/vk/buffer.h"
#include "engine/vk/descriptors.h"
#include "engine/vk/pipeline_library.h"
#include "shaders/shared/opacity.h"

namespace hp::compute {
// What the bins hold, which the splats fill and the resolve reads (gpu::OPACITY_RESOLVE_*).
enum class OpacityBins : std::uint32_t {
  Global = gpu::OPACITY_RESOLVE_GLOBAL,      // 16 per texel, global slices: OPACITY_SPLAT_MODE_PLAIN
  DeepTwoSplats = gpu::OPACITY_RESOLVE_DEEP,  // 16 per texel, deep slices: _FIRST for every instance, then _DEEP
  DeepFine = gpu::OPACITY_RESOLVE_DEEP_FINE,  // OPACITY_DEEP_BINS per texel: _DEEP_FINE alone
};

// The splat modes (gpu::OPACITY_SPLAT_MODE_*) that fill bins of this layout, in the order they run: the mode
// that adds the fragments last, after _FIRST where the deep slices need every instance's first hair first.
std::span<const std::uint32_t> splatModes(OpacityBins bins);

class OpacityResolvePass {
 public:
  // The bins' size for a map resolution, and whether the device can bind them (maxStorageBufferRange).
  static VkDeviceSize binBytes(std::uint32_t resolution, OpacityBins bins = OpacityBins::Global);
  static bool fits(const vk::Context& ctx, std::uint32_t resolution, OpacityBins bins = OpacityBins::Global);
  // Deep maps: DeepFine where its bins fit the device, else DeepTwoSplats; otherwise Global.
  static OpacityBins binsFor(const vk::Context& ctx, std::uint32_t resolution, bool deep);

  // slotMaps: per shadow slot, a 2D-array view of its OPACITY_LAYERS layers in `format` (written as a
  // storage image; a view per slot, so a resolve touches its slot's layers only). Deep bins: the last
  // layer gets the first-hair buffer.
  OpacityResolvePass(const vk::Context& ctx, std::uint32_t resolution, VkFormat format,
                     const std::vector<VkImageView>& slotMaps, OpacityBins bins,
                     vk::PipelineLibrary* library = nullptr);
  OpacityResolvePass(const OpacityResolvePass&) = delete;
  OpacityResolvePass& operator=(const OpacityResolvePass&) = delete;

  const vk::Buffer& bins() const { return bins_; }
  const vk::Buffer& first() const { return first_; }  // uint[resolution^2]: each texel's first hair
  OpacityBins layout() const { return layout_; }
  bool deep() const { return layout_ != OpacityBins::Global; }
  void recordClear(VkCommandBuffer cmd) const;
  // The bins into shadow slot `slot`'s layers of the maps.
  void recordResolve(VkCommandBuffer cmd, std::uint32_t slot) const;

 private:
  const vk::Context* ctx_;
  std::uint32_t resolution_;
  OpacityBins layout_;
  vk::Buffer bins_;
  vk::Buffer first_;
  std::vector<vk::DescriptorSet> sets_;  // per slot
  std::shared_ptr<const vk::ComputePipeline> pipeline_;
};
}  // namespace hp::compute
