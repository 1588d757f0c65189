#pragma once
// Contract: one hair instance's part of the compute opacity pass (shaders/opacity_splat.comp,
// shaders/shared/opacity.h). One dispatch per chunk of render strands rasterizes every segment from the
// light by the graphics pass's rule and adds each fragment's opacity, in fixed point, to the bin of its
// first slice in a bins buffer it is given (render::ShadowMaps owns it; every instance's splats add into
// the same one, and OpacityResolvePass turns the bins into the maps). Owns one descriptor set per chunk.
//
// record(): the caller guarantees the strand positions and LightSpace visible to BufferUse::ComputeRead and
// the bins cleared and visible to ComputeWrite. Between its own chunks the pass orders the atomics with
// ComputeWrite -> ComputeWrite barriers (atomics are writes to synchronization validation); after it the
// bins' last use is ComputeWrite.
#include "hairpipe_volk.h"

#include <glm/glm.hpp>

#include <memory>
#include <utility>
#include <vector>

#include "compute/shadows/opacity_resolve_pass.h"
#include "compute/strands/strand_buffers.h"
#include "engine/vk/buffer.h"
#include "engine/vk/descriptors.h"
#include "engine/vk/pipeline_library.h"

namespace hp::compute {
// What one instance's strands add per fragment (shaders/opacity_footprint.glsl).
struct SplatFootprint {
  bool footprint = true;       // width / texel size per fragment; false: `opacity` per fragment
  float opacity = 0.04f;       // constant mode's opacity per fragment
  glm::vec2 strandWidth{0.0f}; // x = root width (scene units), y = tip / root
  std::uint32_t slot = 0;      // the light's shadow slot (its LightSpace; the bins hold one slot at a time)
};

class OpacitySplatPass {
 public:
  // lightSpace: gpu::LightSpace per slot; bins: OpacityResolvePass::binBytes of `layout`; first:
  // uint[resolution^2] (deep maps); all with storage usage, all outliving the pass. Builds a pipeline for each
  // of the layout's splatModes().
  OpacitySplatPass(const vk::Context& ctx, const StrandBuffers& strands, const vk::Buffer& lightSpace,
                   const vk::Buffer& bins, const vk::Buffer& first, std::uint32_t resolution, OpacityBins layout,
                   vk::PipelineLibrary* library = nullptr);
  OpacitySplatPass(const OpacitySplatPass&) = delete;
  OpacitySplatPass& operator=(const OpacitySplatPass&) = delete;

  // mode: one of splatModes(layout), gpu::OPACITY_SPLAT_MODE_* (deep maps: _DEEP_FINE; where the fine bins do
  // not fit, _FIRST for every instance, a barrier, then _DEEP); another throws hp::Error.
  // strandLimit: the level of detail's prefix of the strands splatted (strandsWithin).
  void record(VkCommandBuffer cmd, const SplatFootprint& footprint, std::uint32_t mode,
              std::uint32_t strandLimit = kAllStrands) const;

 private:
  struct Chunk {
    vk::DescriptorSet set;
    ChunkRange range;
  };

  const vk::Context* ctx_;
  std::uint32_t resolution_;
  std::uint32_t verticesPerStrand_;
  std::vector<Chunk> chunks_;
  const vk::ComputePipeline& pipeline(std::uint32_t mode) const;

  std::vector<std::pair<std::uint32_t, std::shared_ptr<const vk::ComputePipeline>>> pipelines_;  // per mode
};
}  // namespace hp::compute
