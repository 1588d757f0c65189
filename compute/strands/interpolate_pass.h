#pragma once
// Contract: the interpolation pass (docs/THEORY.md §1.4, shaders/interpolate.glsl). Fills every scalp
// triangle with render strands K_j = X1 A_j + X2 B_j + X3 C_j from its three smoothed guides, with
// renormalised blended tangents and per-strand attributes (random, width and colour scales; see
// makeStrandAttributes in shaders/shared/strands.h), and the groom detail of GroomSettings (clumps, curl,
// frizz; engine/core/hair/groom.h) when any is set. In guides-only layouts (StrandOptions::guidesOnly)
// it copies the smoothed guides instead, one render strand per guide. Owns its pipelines (one per walk it
// may take) and one descriptor set per chunk; record() adds one dispatch per chunk (one invocation per strand, or per
// vertex: InterpolateWalk) and inserts no barriers. The frame recorder guarantees:
//   before record: smoothed guides in BufferUse::ComputeRead (after TessellatePass's ComputeWrite);
//                  triangles and bindings in ComputeRead (StrandBuffers leaves them there);
//                  render strand buffers no longer read by the previous frame (last use -> ComputeWrite).
//   after record:  chunk positions, tangents and attributes are in BufferUse::ComputeWrite; barrier
//                  them to VertexRead/GraphicsRead for the draw passes (or TransferSrc for readback).
#include "hairpipe_volk.h"

#include <optional>
#include <string>
#include <vector>

#include "compute/strands/strand_buffers.h"
#include "engine/core/hair/groom.h"
#include "engine/vk/descriptors.h"
#include "engine/vk/pipeline_library.h"
#include "engine/vk/profiler.h"
#include "shaders/shared/strands.h"

namespace hp::compute {
// How the invocations cover a chunk (shaders/interpolate.glsl). Per vertex makes a warp's stores
// contiguous (GPUs): one invocation per vertex for the plain blend, and for the groom detail (whose frame is
// carried along the strand) one per strand whose vertices are staged in shared memory and written out by
// the workgroup (where the device has the 26 KiB of shared memory it takes; per strand otherwise). Per
// strand reads each strand's binding once (CPU devices). Auto: per strand on CPU devices, per vertex
// elsewhere. Guides-only layouts always walk per strand. The walks run the same arithmetic: the per-vertex
// walk writes the per-strand walk's bits; the staged one, a shader of its own, may differ in the last bit
// where its compiler contracts the arithmetic differently.
enum class InterpolateWalk { Auto, PerStrand, PerVertex };
const char* interpolateWalkName(InterpolateWalk walk);                        // "auto", "strand", "vertex"
std::optional<InterpolateWalk> parseInterpolateWalk(const std::string& name);  // one of those names, or none

class InterpolatePass {
 public:
  InterpolatePass(const vk::Context& ctx, const StrandBuffers& buffers, vk::PipelineLibrary* library = nullptr,
                  const GroomSettings& groom = {}, InterpolateWalk walk = InterpolateWalk::Auto);

  // After StrandBuffers was re-allocated (density, Q, guides-only change); outside the frame loop only.
  void bind(const StrandBuffers& buffers);
  void record(VkCommandBuffer cmd, vk::GpuProfiler* profiler = nullptr) const;
  // The groom detail of the next record() (push constants: no GPU object changes). Validates it.
  void setGroom(const GroomSettings& groom);
  // Whether the next record() writes per vertex, plain or staged (the walk asked for, the device, the
  // groom and layout).
  bool walksPerVertex() const;
  // The walk the next record() takes: "strand", "vertex" (plain blend) or "staged" (groomed, per vertex).
  const char* walkTaken() const;

 private:
  struct Chunk {
    vk::DescriptorSet set;
    gpu::InterpolatePush push;
  };
  const vk::Context* ctx_;
  // The pipeline layout is made from this set's layout; chunk sets have identical layouts, so they
  // are compatible, and chunk sets can be rebuilt without touching the pipeline.
  vk::DescriptorSet layoutSet_;
  std::shared_ptr<const vk::ComputePipeline> perStrand_;
  std::shared_ptr<const vk::ComputePipeline> perVertex_;  // none where the walk never goes per vertex
  std::shared_ptr<const vk::ComputePipeline> staged_;     // likewise, or where its shared memory does not fit
  const vk::ComputePipeline& walkPipeline() const;  // the one the next record() binds

  std::vector<Chunk> chunks_;
  gpu::GroomParams groom_{};
  bool groomOn_ = false;
  bool guidesOnly_ = false;
};
}  // namespace hp::compute
