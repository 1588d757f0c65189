#pragma once
// Contract: one-shot use of the strand passes outside the frame loop, for tools and tests:
// `hairpipe strands`, `hairpipe bench strands` and (later) `hairpipe render --dump-strands`.
// Every function waits for its own submission; none is meant for the per-frame path.
#include <string>
#include <vector>

#include "compute/strands/interpolate_pass.h"
#include "compute/strands/strand_buffers.h"
#include "compute/strands/tessellate_pass.h"
#include "engine/core/hair/guide_set.h"
#include "engine/core/hair/hair_asset.h"
#include "engine/core/hair/hair_file.h"
#include "engine/vk/profiler.h"

namespace hp::compute {
// The guides as the simulation outputs them (vec4 per particle, w = 0), left in BufferUse::ComputeRead.
vk::Buffer uploadGuideParticles(const vk::Context& ctx, const GuideSet& guides,
                                const std::string& name = "guide particles");

// Records tessellate, the ComputeWrite -> ComputeRead barrier on the smoothed guides, interpolate.
// Before: guide particles in ComputeRead. After: render strands in ComputeWrite.
void recordStrandPasses(const vk::Context& ctx, VkCommandBuffer cmd, const TessellatePass& tessellate, const InterpolatePass& interpolate,
                        vk::GpuProfiler* profiler = nullptr);

// The render strands now in `buffers` (last GPU use `before`) as .hair data: Q points per strand.
HairFileData renderStrandsToHairData(const vk::Context& ctx, const StrandBuffers& buffers, vk::BufferUse before,
                                     const std::string& info);

struct StrandRun {
  StrandLayout layout;
  HairFileData hair;
  std::vector<vk::ScopeTime> times;  // "tessellate", "interpolate" (empty without timestamps)
};
// The rest pose of `asset` through both passes, read back as .hair data.
StrandRun computeRenderStrands(const vk::Context& ctx, const HairAsset& asset, const StrandOptions& options,
                               const std::string& info, const GroomSettings& groom = {});
}  // namespace hp::compute
