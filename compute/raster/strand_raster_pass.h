#pragma once
// Contract: the compute strand rasterizer for the camera view (docs/THEORY.md §7; layouts and the coverage
// formula in shaders/shared/raster.h). Over the render strands of every chunk of every source (one source
// per hair instance: its strands and its shading resources; all share one set of tile lists, so hair of
// different heads interleaves correctly by depth) it
//   bin      per vertex: the projection to pixels, NDC depth and width; per tile: the farthest head depth;
//            per segment: count its (8x8 tile, depth bin) keys (a block mask of the tile it may cover),
//            leaving out tiles where the head hides it, and list the ends of kept segments for shading;
//            scan the tiles (tile budget: nearest bins kept first), scatter the segment ids into per-tile
//            lists ordered near to far by depth bin;
//   shade    per listed vertex (indirect dispatch): radiance by the graphics path's hairRadiance (opacity
//            maps looked up at the vertex: strand-space shading);
//   fine     per pixel: exact band coverage, hidden at or behind the head's depth, composited front to
//            back until T < 1/255, into output(): RGBA16F, premultiplied radiance, alpha = 1 - T. With a
//            multisampled head depth (headSamples > 1) also nearOutput() and nearMask(): the hair in front
//            of every head sample and the samples that take it (shaders/shared/raster.h, the two layers).
//            With settings.motion also motionOutput(): RG16F, the hair's coverage-weighted screen motion in
//            pixels (current unjittered minus previous; StrandChunk::previous and the frame block's
//            previousViewProj), 0 without hair.
// The pass owns every buffer and image it writes and the barriers between its own steps. The frame
// recorder guarantees before record(): strand buffers, the frame block, LightSpace and the opacity maps
// visible to compute reads (maps in ImageUse::ComputeSampled), the depth image given to setDepth() in
// ImageUse::ComputeSampled. After record(): output() in ImageUse::FragmentSampled, every own buffer's
// last use ComputeWrite. Each chunk has one descriptor set per frame slot (`frameSlots`: the frames the
// caller keeps in flight), so rebindShading() can point one slot's sets at new shading resources while
// frames recorded with the other slots still run: the caller rewrites a slot only once the last frame
// recorded with it is complete, and names the slot in record(). List overflow is never silent:
// readStats() reports entries dropped by the tile budget and for the list capacity (derived from the segment
// count and the frame size, or grown: RasterSettings::growLists); a full list cuts every tile's far bins alike.
#include "hairpipe_volk.h"

#include <array>
#include <functional>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "compute/raster/list_sizing.h"
#include "compute/raster/shade_variant.h"
#include "compute/strands/strand_buffers.h"
#include "engine/vk/buffer.h"
#include "engine/vk/buffer_view.h"
#include "engine/vk/descriptors.h"
#include "engine/vk/image.h"
#include "engine/vk/pipeline.h"
#include "engine/vk/profiler.h"
#include "shaders/shared/raster.h"

namespace hp::compute {
// How the fine pass walks a tile's list (shaders/raster_fine.glsl): every pixel on its own (Direct), or in
// batches the tile's invocations load together into shared memory (Staged). The image is the same; the
// speed is not: Auto takes Direct on CPU devices (lavapipe) and Staged on GPUs, and Staged wherever the
// direct walk's texel views would not fit the device (chooseStagedWalk).
enum class FineWalk { Auto, Direct, Staged };
const char* fineWalkName(FineWalk walk);                        // "auto", "direct", "staged"
std::optional<FineWalk> parseFineWalk(const std::string& name);  // one of those names, or none
// Whether the pass takes the staged walk: the direct one reads the lists and vertices as texel buffers, so
// it needs them within maxTexelBufferElements (texelsFit); Auto falls back to Staged where they are not,
// an explicit Direct throws an Error.
bool chooseStagedWalk(FineWalk walk, bool cpuDevice, bool texelsFit);

// Shading spacing: where a strand's vertices 2j and 2j + 2 lie within this many pixels of each other on screen
// and the strand turns little there, vertex 2j + 1 is not shaded and takes their mean radiance (shared/raster.h RASTER_COLOR_A_MID; docs/DESIGN.md
// "Shading spacing"); 0 shades every vertex a tile lists.
inline constexpr float kMaxShadingSpacing = 4096.0f;

struct RasterSettings {
  std::uint32_t tileBudget = 16384;  // list entries kept per 8x8 tile, [1, 1<<24]
  float shadingSpacing = 24.0f;      // pixels, [0, kMaxShadingSpacing]; the public default
  bool motion = false;               // write motion vectors (motionOutput)
  bool reversedDepth = false;        // the head's depth and the view's projection are reversed-Z (near 1, far 0)
  FineWalk fineWalk = FineWalk::Auto;
  // The tile lists start at listStartCapacity (listStartPerSegment entries per segment plus 16 per tile) and
  // grow by useLists with the frames' need, up to rasterListCapacity, and shrink after listShrinkFrames frames
  // that needed under a quarter of them (ListSizing; 0: never); false: rasterListCapacity from the start.
  bool growLists = false;
  std::uint32_t listStartPerSegment = 2;  // [1, 8]
  std::uint32_t listShrinkFrames = 300;   // 5 s at 60 Hz
  void validate() const;
};

struct RasterStats {
  std::uint64_t requested = 0;           // (segment, tile) entries the segments asked for
  std::uint64_t droppedByTileBudget = 0;
  std::uint64_t droppedByCapacity = 0;
  std::uint64_t kept = 0;
  std::uint64_t shaded = 0;              // vertices the shade pass shaded
  std::uint32_t listCapacity = 0;        // entries of the newest lists (RasterSettings::growLists grows them)
  FineWalk walk = FineWalk::Auto;  // the walk the fine pass runs: Direct or Staged (Auto resolved)
  std::uint64_t overflow() const { return droppedByTileBudget + droppedByCapacity; }
};

// Writes the shading bindings of shaders/shared/render.h (frame block and Marschner parameters as STORAGE
// buffers, the LUTs, opacity maps, LightSpace, the head's depth shadow map) into a raster descriptor set:
// what hairRadiance reads (compute/raster/raster_shading.h writes them). The pass binds each chunk's skin
// bounce samples itself (StrandChunk::bounce).
using ShadingWriter = std::function<void(const vk::DescriptorSet&)>;

// One head's strands and the shading resources its segments are shaded with.
struct RasterSource {
  const StrandBuffers* strands = nullptr;
  ShadingWriter shading;
};

class StrandRasterPass {
 public:
  // headSamples: the sample count of the depth image setDepth() will get (1 to RASTER_MAX_HEAD_SAMPLES).
  // frameSlots: descriptor sets per chunk (1 to 16). Throws hp::Error for no source, a zero extent, bad
  // settings, sample count or slot count, or buffers past maxStorageBufferRange.
  StrandRasterPass(const vk::Context& ctx, std::span<const RasterSource> sources, VkExtent2D extent,
                   const RasterSettings& settings, std::uint32_t headSamples = 1, VkPipelineCache cache = VK_NULL_HANDLE,
                   std::uint32_t frameSlots = 1);
  StrandRasterPass(const vk::Context& ctx, const StrandBuffers& strands, const ShadingWriter& shading,
                   VkExtent2D extent, const RasterSettings& settings, std::uint32_t headSamples = 1)
      : StrandRasterPass(ctx, std::span<const RasterSource>(std::vector<RasterSource>{{&strands, shading}}), extent,
                         settings, headSamples) {}
  // Outside the frame loop: rewrite descriptors after the shading resources changed (same strand sizes).
  void bind(std::span<const RasterSource> sources);
  // settings.growLists, in the frame loop before the first record() of a frame with `slot`, when no pending
  // frame was recorded with that slot: `need` (the most list entries the slot's last frame asked for within
  // the tile budget, listNeed) goes to the lists' ListSizing (compute/raster/list_sizing.h), and new lists of
  // the size it answers become the newest: twice the need when over 3/4 of the newest lists (within
  // maxCapacity), or smaller after settings.listShrinkFrames frames under a quarter. The slot's sets are
  // pointed at the newest lists; older lists go when no slot binds them. A failed allocation keeps the lists
  // and stops their growth (their overflow stays in readStats()).
  void useLists(std::uint32_t slot, std::uint64_t need);
  // After record(): its RasterState copied into `dst` (host-visible) at `offset`, for listNeed once the
  // frame is complete.
  void recordStateCopy(VkCommandBuffer cmd, const vk::Buffer& dst, VkDeviceSize offset) const;
  // In the frame loop: the shading bindings of one source's chunks in one slot's sets rewritten, when no
  // pending frame was recorded with that slot (the strand and pass bindings stay).
  void rebindShading(std::uint32_t source, std::uint32_t slot, const ShadingWriter& shading);
  // The head's depth (D32, headSamples samples); 1.0 where nothing was drawn. Must be set before record().
  void setDepth(VkImageView depth);

  // strandLimits: per source, the level of detail's prefix of its strands drawn (compute::strandsWithin);
  // empty: all of them. shading: per source, the shade pass's variant for its frame block and fibre
  // (shadeVariantOf: the light loop left out for one light, the fibre compiled in; twice and ~1.4x as fast on
  // lavapipe); empty: the run-time fibre with the light loop for every source. A fibre not prepared takes the
  // run-time form (ShadePipelines). slot: the frame slot whose descriptor sets the frame binds.
  void record(VkCommandBuffer cmd, vk::GpuProfiler* profiler = nullptr,
              std::span<const std::uint32_t> strandLimits = {}, std::span<const ShadeVariant> shading = {},
              std::uint32_t slot = 0) const {
    recordBinning(cmd, profiler, strandLimits, slot);
    recordFine(cmd, profiler, shading, slot);
  }
  // record() in two halves: project + bin (readStats() is complete after it), then shade + fine raster.
  void recordBinning(VkCommandBuffer cmd, vk::GpuProfiler* profiler = nullptr,
                     std::span<const std::uint32_t> strandLimits = {}, std::uint32_t slot = 0) const;
  void recordFine(VkCommandBuffer cmd, vk::GpuProfiler* profiler = nullptr, std::span<const ShadeVariant> shading = {},
                  std::uint32_t slot = 0) const;
  // Builds a shade pass variant for the frames that will take it (outside the frame loop).
  void prepareShading(const ShadeVariant& variant) { shade_->prepare(variant); }
  bool shadingPrepared(const ShadeVariant& variant) const { return shade_->prepared(variant); }

  const vk::Image& output() const { return output_; }
  // The near layer and its sample mask (R32_UINT); 1 x 1 and never written for a single-sample head depth.
  const vk::Image& nearOutput() const { return nearOutput_; }
  const vk::Image& nearMask() const { return nearMask_; }
  // 1 x 1 and never written without settings.motion.
  const vk::Image& motionOutput() const { return motionOutput_; }
  bool multisampled() const { return headSamples_ > 1; }
  VkExtent2D extent() const { return extent_; }
  std::uint32_t capacity() const { return list_->capacity; }  // of the newest lists
  std::uint32_t maxCapacity() const { return maxCapacity_; }
  // The newest lists' entries per segment beyond their 16 per tile, rounded up, in [1, 8]: where a rebuilt
  // pass (new strands, another extent) starts its growing lists (RasterSettings::listStartPerSegment).
  std::uint32_t listEntriesPerSegment() const;
  // Blocking readback of the last recorded frame's statistics (outside the frame loop).
  RasterStats readStats() const;
  // Blocking readback of the last frame's hair coverage per pixel (rows top to bottom), averaged over the
  // head's samples: the alpha of the layer each sample takes. Outside the frame loop, after record().
  std::vector<float> readCoverage() const;
  // Blocking readback of the last frame's motion (x, y per pixel, rows top to bottom); settings.motion only.
  std::vector<glm::vec2> readMotion() const;

 private:
  struct Chunk {
    std::vector<vk::DescriptorSet> sets;  // one per frame slot
    vk::Buffer params;  // gpu::RasterParams of the chunk (a storage buffer: no push constants, see .cpp)
    ChunkRange range;   // within its source's strands
    std::uint32_t source;
    std::uint32_t verticesPerStrand;
  };
  // One set of tile lists (entries of 8 bytes) and, for the direct walk, its texel view.
  struct TileList {
    vk::Buffer buffer;
    vk::BufferView texels;  // after the buffer: destroyed first
    std::uint32_t capacity = 0;
  };
  std::shared_ptr<const TileList> makeList(std::uint32_t capacity) const;
  std::array<const vk::Image*, 4> outputs() const { return {&output_, &nearOutput_, &nearMask_, &motionOutput_}; }
  void recordArm(VkCommandBuffer cmd) const;
  // Resolves the fine walk (chooseStagedWalk) into walk_ and, for the direct one, makes its texel views of
  // the list, screen and colour buffers (`vertices`: the screen and colour buffers' length).
  void setUpFineWalk(FineWalk requested, std::uint64_t vertices);
  void writeChunkSet(const vk::DescriptorSet& set, const ShadingWriter& shading, const StrandChunk& c,
                     const vk::Buffer& params, const TileList& list) const;
  void writeListBindings(const vk::DescriptorSet& set, const TileList& list) const;
  // One dispatch per chunk of strands * (verticesPerStrand - perStrandLess) invocations, strands those of
  // the chunk within its source's limit (all without limits).
  void recordPerChunk(VkCommandBuffer cmd, const vk::ComputePipeline& pipeline, std::uint32_t perStrandLess,
                      std::span<const std::uint32_t> strandLimits, std::uint32_t slot) const;
  const vk::DescriptorSet& setOf(const Chunk& c, std::uint32_t slot) const;
  std::uint32_t drawnStrands(const Chunk& c, std::span<const std::uint32_t> strandLimits) const;
  // Each chunk's drawn strands and (growLists) the capacity of the lists `slot` binds, into its params.
  void recordStrandCounts(VkCommandBuffer cmd, std::span<const std::uint32_t> strandLimits, std::uint32_t slot) const;
  void recordOnce(VkCommandBuffer cmd, const vk::ComputePipeline& pipeline, std::uint32_t threads,
                  std::uint32_t slot) const;

  const vk::Context& ctx_;
  VkExtent2D extent_;
  RasterSettings settings_;
  std::uint32_t headSamples_;
  std::uint32_t frameSlots_;
  std::uint32_t tilesX_, tilesY_, maxCapacity_ = 0;
  std::uint64_t segments_ = 0;  // of every source
  FineWalk walk_ = FineWalk::Direct;  // Auto resolved
  std::vector<std::uint32_t> sourceVertices_;  // render vertices of each source (bind() must match)
  vk::Buffer screen_, colors_, state_, counts_, keys_, tiles_, blocks_, tileDepth_;
  // The direct fine walk's views of screen_ and colors_ (none for the staged): declared after the buffers,
  // so destroyed before them.
  vk::BufferView screenTexels_, colorTexels_;
  std::shared_ptr<const TileList> list_;                  // the newest lists
  std::vector<std::shared_ptr<const TileList>> slotLists_;  // per frame slot: the lists its sets bind
  std::optional<ListSizing> sizing_;                      // growLists only
  bool growthFailed_ = false;                             // an allocation failed: no further attempt
  vk::Buffer shadeFlags_, shadeList_, shadeArgs_, motion_;
  vk::Image output_, nearOutput_, nearMask_, motionOutput_;
  vk::Sampler sampler_;
  VkImageView depth_ = VK_NULL_HANDLE;
  std::vector<Chunk> chunks_;
  vk::ComputePipeline project_, tileDepthPipeline_, count_, scatter_, budgetTiles_, scanTiles_, scanBlocks_, fine_;
  std::optional<ShadePipelines> shade_;
};

// List entries reserved for a frame: every segment in 8 tiles plus 16 per tile (the default head at
// 3840x2160 asks for 4.3M of 7.7M), within the device's
// storage buffer range (pure arithmetic, for tests and the docs). With growLists, the most the lists grow to.
std::uint32_t rasterListCapacity(std::uint64_t segments, std::uint64_t tiles, std::uint64_t maxRangeBytes);
// With growLists, the lists' first capacity: every segment in `perSegment` tiles plus 16 per tile, at most
// `maxCapacity`.
std::uint32_t listStartCapacity(std::uint64_t segments, std::uint64_t tiles, std::uint32_t perSegment,
                                std::uint32_t maxCapacity);
// The list entries a frame's view asked for within the tile budget (kept and dropped past the capacity).
std::uint64_t listNeed(const gpu::RasterState& state);
}  // namespace hp::compute
