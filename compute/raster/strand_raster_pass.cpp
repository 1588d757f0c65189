#include "compute/raster/strand_raster_pass.h"

#include <algorithm>
#include <bit>
#include <cstddef>
#include <cstring>
#include <utility>
#include <string>

#include "engine/core/error.h"
#include "engine/core/shading/half_float.h"
#include "engine/vk/barriers.h"
#include "engine/vk/context.h"
#include "engine/vk/transfer.h"
#include "shaders/shared/raster.h"
#include "shaders/shared/render.h"

namespace hp::compute {
namespace {
// The raster's own bindings follow the shading bindings of shaders/shared/render.h in one set.
static_assert(gpu::RASTER_BINDING_SCREEN > gpu::RENDER_BINDING_HEAD_SHADOW, "raster bindings overlap render.h's");
static_assert(gpu::RASTER_BINDING_LIST_TEXELS > gpu::RENDER_BINDING_SCALP_TRIANGLES, "raster bindings overlap render.h's");
static_assert(gpu::RASTER_BINDING_SHADE_ARGS < gpu::RENDER_BINDING_BOUNCE_FLUX &&
                  gpu::RASTER_BINDING_MOTION_OUTPUT < gpu::RENDER_BINDING_BOUNCE_SAMPLES,
              "raster bindings overlap render.h's");
// No uniform buffers and no push constants: lavapipe would recompile each step per dispatch
// (docs/DESIGN.md, driver notes); the frame block, the Marschner block and the per-chunk parameters are
// read-only storage buffers.
const vk::Binding kStrandRasterBindings[] = {
    {gpu::RENDER_BINDING_FRAME, vk::kStorage, vk::kCompute},
    {gpu::RENDER_BINDING_MARSCHNER, vk::kStorage, vk::kCompute},
    {gpu::RENDER_BINDING_LUT_M, vk::kSampled, vk::kCompute},
    {gpu::RENDER_BINDING_LUT_N0, vk::kSampled, vk::kCompute},
    {gpu::RENDER_BINDING_LUT_N1, vk::kSampled, vk::kCompute},
    {gpu::RENDER_BINDING_OPACITY, vk::kSampled, vk::kCompute},
    {gpu::RENDER_BINDING_HEAD_SHADOW, vk::kSampled, vk::kCompute},
    {gpu::RENDER_BINDING_LIGHT, vk::kStorage, vk::kCompute},
    {gpu::RENDER_BINDING_POSITIONS, vk::kStorage, vk::kCompute},
    {gpu::RENDER_BINDING_TANGENTS, vk::kStorage, vk::kCompute},
    {gpu::RENDER_BINDING_ATTRIBUTES, vk::kStorage, vk::kCompute},
    {gpu::RASTER_BINDING_SCREEN, vk::kStorage, vk::kCompute},
    {gpu::RASTER_BINDING_COLORS, vk::kStorage, vk::kCompute},
    {gpu::RASTER_BINDING_STATE, vk::kStorage, vk::kCompute},
    {gpu::RASTER_BINDING_COUNTS, vk::kStorage, vk::kCompute},
    {gpu::RASTER_BINDING_KEYS, vk::kStorage, vk::kCompute},
    {gpu::RASTER_BINDING_TILES, vk::kStorage, vk::kCompute},
    {gpu::RASTER_BINDING_BLOCKS, vk::kStorage, vk::kCompute},
    {gpu::RASTER_BINDING_LIST, vk::kStorage, vk::kCompute},
    {gpu::RASTER_BINDING_DEPTH, vk::kSampled, vk::kCompute},
    {gpu::RASTER_BINDING_OUTPUT, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, vk::kCompute},
    {gpu::RASTER_BINDING_OUTPUT_NEAR, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, vk::kCompute},
    {gpu::RASTER_BINDING_NEAR_MASK, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, vk::kCompute},
    {gpu::RASTER_BINDING_PARAMS, vk::kStorage, vk::kCompute},
    {gpu::RASTER_BINDING_TILE_DEPTH, vk::kStorage, vk::kCompute},
    {gpu::RASTER_BINDING_SHADE_FLAGS, vk::kStorage, vk::kCompute},
    {gpu::RASTER_BINDING_SHADE_LIST, vk::kStorage, vk::kCompute},
    {gpu::RASTER_BINDING_SHADE_ARGS, vk::kStorage, vk::kCompute},
    {gpu::RENDER_BINDING_BOUNCE_SAMPLES, vk::kStorage, vk::kCompute},
    {gpu::RASTER_BINDING_PREVIOUS, vk::kStorage, vk::kCompute},
    {gpu::RASTER_BINDING_MOTION, vk::kStorage, vk::kCompute},
    {gpu::RASTER_BINDING_MOTION_OUTPUT, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, vk::kCompute},
    // The direct fine walk's texel views (written only where it runs; the staged walk never reads them).
    {gpu::RASTER_BINDING_LIST_TEXELS, vk::kTexels, vk::kCompute},
    {gpu::RASTER_BINDING_SCREEN_TEXELS, vk::kTexels, vk::kCompute},
    {gpu::RASTER_BINDING_COLOR_TEXELS, vk::kTexels, vk::kCompute},
};
constexpr VkBufferUsageFlags kStorageUsage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT;
// The buffers the direct fine walk also reads as texel buffers.
constexpr VkBufferUsageFlags kTexelUsage = kStorageUsage | VK_BUFFER_USAGE_UNIFORM_TEXEL_BUFFER_BIT;
constexpr VkBufferUsageFlags kArmedUsage =
    VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT | VK_BUFFER_USAGE_TRANSFER_SRC_BIT;

std::uint32_t divUp(std::uint32_t a, std::uint32_t b) { return (a + b - 1) / b; }

gpu::RasterState armedState() {
  gpu::RasterState s{};
  s.depthBits = glm::uvec4(0xFFFFFFFFu, 0u, 0u, 0u);  // min, max of non-negative float bits
  return s;
}

vk::Buffer rasterBuffer(const vk::Context& ctx, VkDeviceSize bytes, VkBufferUsageFlags usage, const std::string& name,
                        VkDeviceSize limit) {
  if (bytes > limit)
    throw Error("compute raster: the " + name + " buffer needs " + std::to_string(bytes) +
                " bytes, more than the device's maxStorageBufferRange (" + std::to_string(limit) +
                "); use fewer strands or --raster graphics");
  return vk::Buffer(ctx, std::max<VkDeviceSize>(bytes, 16), usage, vk::MemoryKind::DeviceLocal, "raster " + name);
}

constexpr VkImageUsageFlags kOutputUsage =
    VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT;

// An output image of the frame's size, or of 1 x 1 where it only fills a binding (the near layer and
// mask under a single-sample head depth, which the composite never reads).
vk::Image outputImage(const vk::Context& ctx, VkExtent2D extent, bool used, VkFormat format, const std::string& name) {
  return vk::Image(ctx, {used ? extent.width : 1u, used ? extent.height : 1u, 1, format, kOutputUsage,
                         VK_SAMPLE_COUNT_1_BIT, name});
}

gpu::RasterParams baseParams(std::uint32_t tilesX, std::uint32_t tilesY, const RasterSettings& settings,
                             std::uint32_t capacity, VkExtent2D extent) {
  gpu::RasterParams p{};
  p.tilesX = tilesX;
  p.tilesY = tilesY;
  p.tileBudget = settings.tileBudget;
  p.shadingSpacing = settings.shadingSpacing;
  p.reversedDepth = settings.reversedDepth ? 1u : 0u;
  p.capacity = capacity;
  p.width = extent.width;
  p.height = extent.height;
  return p;
}

std::size_t chunkCount(std::span<const RasterSource> sources) {
  std::size_t n = 0;
  for (const RasterSource& s : sources) n += s.strands->chunks().size();
  return n;
}

// The shade dispatch arguments re-armed every frame: (0, 1, 1) groups and nothing listed, per chunk.
std::vector<glm::uvec4> armedShadeArgs(std::size_t chunks) { return std::vector<glm::uvec4>(chunks, {0u, 1u, 1u, 0u}); }
}  // namespace

const char* fineWalkName(FineWalk walk) {
  return walk == FineWalk::Auto ? "auto" : walk == FineWalk::Staged ? "staged" : "direct";
}

bool chooseStagedWalk(FineWalk walk, bool cpuDevice, bool texelsFit) {
  if (walk == FineWalk::Direct && !texelsFit)
    throw Error("compute raster: the direct fine walk reads the tile lists and vertices as texel buffers, which "
                "exceed the device's maxTexelBufferElements here; use --fine-walk staged or fewer strands");
  return walk == FineWalk::Staged || (walk == FineWalk::Auto && (!cpuDevice || !texelsFit));
}

std::optional<FineWalk> parseFineWalk(const std::string& name) {
  for (FineWalk w : {FineWalk::Auto, FineWalk::Direct, FineWalk::Staged})
    if (name == fineWalkName(w)) return w;
  return std::nullopt;
}

void RasterSettings::validate() const {
  if (tileBudget == 0 || tileBudget > (1u << 24))
    throw Error("tileBudget must be in [1, 16777216], got " + std::to_string(tileBudget));
  if (!(shadingSpacing >= 0.0f && shadingSpacing <= kMaxShadingSpacing))
    throw Error("shadingSpacing must be in [0, " + std::to_string(int(kMaxShadingSpacing)) + "] pixels, got " +
                std::to_string(shadingSpacing));
  if (listStartPerSegment < 1 || listStartPerSegment > 8)
    throw Error("listStartPerSegment must be in [1, 8], got " + std::to_string(listStartPerSegment));
}

std::uint32_t rasterListCapacity(std::uint64_t segments, std::uint64_t tiles, std::uint64_t maxRangeBytes) {
  const std::uint64_t wanted = segments * 8 + tiles * 16;
  return std::uint32_t(std::clamp<std::uint64_t>(wanted, 1024, std::min<std::uint64_t>(maxRangeBytes / 8, 0xFFFFFFFFu)));
}

std::uint32_t listStartCapacity(std::uint64_t segments, std::uint64_t tiles, std::uint32_t perSegment,
                                std::uint32_t maxCapacity) {
  return std::uint32_t(
      std::min<std::uint64_t>(std::max<std::uint64_t>(segments * perSegment + tiles * 16, 1024), maxCapacity));
}

std::uint64_t listNeed(const gpu::RasterState& state) { return std::uint64_t(state.entries.w) + state.entries.z; }

StrandRasterPass::StrandRasterPass(const vk::Context& ctx, std::span<const RasterSource> sources, VkExtent2D extent,
                                   const RasterSettings& settings, std::uint32_t headSamples, VkPipelineCache cache,
                                   std::uint32_t frameSlots)
    : ctx_(ctx), extent_(extent), settings_(settings), headSamples_(headSamples), frameSlots_(frameSlots) {
  settings.validate();
  if (frameSlots == 0 || frameSlots > 16)
    throw Error("compute raster: the frame slots must be in [1, 16], got " + std::to_string(frameSlots));
  if (headSamples == 0 || headSamples > gpu::RASTER_MAX_HEAD_SAMPLES || (headSamples & (headSamples - 1)) != 0)
    throw Error("compute raster: the head depth's sample count must be a power of two in [1, " +
                std::to_string(gpu::RASTER_MAX_HEAD_SAMPLES) + "], got " + std::to_string(headSamples));
  if (extent.width == 0 || extent.height == 0) throw Error("compute raster: the extent must be non-zero");
  if (sources.empty()) throw Error("compute raster: no strand source");
  tilesX_ = divUp(extent.width, gpu::RASTER_TILE_SIZE);
  tilesY_ = divUp(extent.height, gpu::RASTER_TILE_SIZE);
  const VkDeviceSize limit = ctx.properties().limits.maxStorageBufferRange;
  std::uint64_t vertices = 0, segments = 0;
  for (const RasterSource& source : sources) {
    const StrandLayout& layout = source.strands->layout();
    vertices += layout.strandVertexCount();
    segments += std::uint64_t(layout.strandCount) * (layout.verticesPerStrand - 1);
    sourceVertices_.push_back(std::uint32_t(layout.strandVertexCount()));
  }
  const std::uint64_t tiles = std::uint64_t(tilesX_) * tilesY_;
  segments_ = segments;
  const std::size_t chunks = chunkCount(sources);
  maxCapacity_ = rasterListCapacity(segments, tiles, limit);
  screen_ = rasterBuffer(ctx, vertices * 16, kTexelUsage, "screen vertices", limit);
  colors_ = rasterBuffer(ctx, vertices * 8, kTexelUsage, "vertex colours", limit);
  shadeFlags_ = rasterBuffer(ctx, vertices * 4, kArmedUsage, "shade flags", limit);
  shadeList_ = rasterBuffer(ctx, vertices * 4, kStorageUsage, "shade list", limit);
  shadeArgs_ = rasterBuffer(ctx, chunks * 16, kArmedUsage | VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT, "shade dispatch", limit);
  motion_ = rasterBuffer(ctx, settings.motion ? vertices * 4 : 16, kStorageUsage, "vertex motion", limit);
  state_ = rasterBuffer(ctx, sizeof(gpu::RasterState), kArmedUsage, "state", limit);
  counts_ = rasterBuffer(ctx, tiles * gpu::RASTER_DEPTH_BINS * 4, kArmedUsage, "key counts", limit);
  keys_ = rasterBuffer(ctx, tiles * gpu::RASTER_DEPTH_BINS * 8, kStorageUsage, "keys", limit);
  tiles_ = rasterBuffer(ctx, tiles * 8, kStorageUsage, "tiles", limit);
  tileDepth_ = rasterBuffer(ctx, tiles * 4, kStorageUsage, "tile head depth", limit);
  blocks_ = rasterBuffer(ctx, divUp(std::uint32_t(tiles), gpu::RASTER_SCAN_SIZE) * 4, kStorageUsage, "blocks", limit);
  setUpFineWalk(settings.fineWalk, vertices);  // before bind(): the chunk sets take the walk's views
  list_ = makeList(settings.growLists ? listStartCapacity(segments, tiles, settings.listStartPerSegment, maxCapacity_)
                                      : maxCapacity_);
  if (settings.growLists)
    sizing_.emplace(listStartCapacity(segments, tiles, 1, maxCapacity_), maxCapacity_, settings.listShrinkFrames);
  output_ = outputImage(ctx, extent, true, VK_FORMAT_R16G16B16A16_SFLOAT, "raster hair image");
  nearOutput_ = outputImage(ctx, extent, multisampled(), VK_FORMAT_R16G16B16A16_SFLOAT, "raster hair image (near layer)");
  nearMask_ = outputImage(ctx, extent, multisampled(), VK_FORMAT_R32_UINT, "raster near-layer sample mask");
  motionOutput_ = outputImage(ctx, extent, settings.motion, VK_FORMAT_R16G16_SFLOAT, "raster hair motion");
  sampler_ = vk::Sampler(ctx, "raster depth sampler", VK_FILTER_NEAREST);  // D32 cannot filter
  const gpu::RasterState armed = armedState();
  vk::uploadBytes(ctx, state_, &armed, sizeof(armed), vk::BufferUse::ComputeWrite);
  bind(sources);
  const auto setLayout = chunks_.front().sets.front().layout();
  const auto pipeline = [&](const char* shader, std::uint32_t size, const char* name) {
    return vk::ComputePipeline(ctx, shader, size, {setLayout}, 0, name, {}, cache);
  };
  const std::vector<std::uint32_t> motion = {settings.motion ? 1u : 0u};  // constant_id 0: MOTION
  project_ = vk::ComputePipeline(ctx, "raster_project.comp", gpu::RASTER_WORKGROUP_SIZE, {setLayout}, 0,
                                 "raster project", motion, cache);
  // The shade pass reads the head's depth (the sky on the fibres' far side), of the head's sample count; the
  // run-time fibre's builds are made here, a fixed fibre's by prepareShading() (ShadePipelines).
  shade_.emplace(ctx, multisampled() ? "raster_shade_ms.comp" : "raster_shade.comp", setLayout, cache);
  tileDepthPipeline_ = pipeline(multisampled() ? "raster_tile_depth_ms.comp" : "raster_tile_depth.comp",
                                gpu::RASTER_WORKGROUP_SIZE, "raster tile depth");
  count_ = vk::ComputePipeline(ctx, "raster_bin.comp", gpu::RASTER_WORKGROUP_SIZE, {setLayout}, 0, "raster count",
                               {gpu::RASTER_MODE_COUNT}, cache);
  scatter_ = vk::ComputePipeline(ctx, "raster_bin.comp", gpu::RASTER_WORKGROUP_SIZE, {setLayout}, 0, "raster scatter",
                                 {gpu::RASTER_MODE_SCATTER}, cache);
  budgetTiles_ = pipeline("raster_budget_tiles.comp", gpu::RASTER_SCAN_SIZE, "raster budget tiles");
  scanTiles_ = pipeline("raster_scan_tiles.comp", gpu::RASTER_SCAN_SIZE, "raster scan tiles");
  scanBlocks_ = pipeline("raster_scan_blocks.comp", gpu::RASTER_SCAN_SIZE, "raster scan blocks");
  const bool staged = walk_ == FineWalk::Staged;
  const char* fineShader = staged ? (multisampled() ? "raster_fine_staged_ms.comp" : "raster_fine_staged.comp")
                                  : (multisampled() ? "raster_fine_ms.comp" : "raster_fine.comp");
  fine_ = vk::ComputePipeline(ctx, fineShader, gpu::RASTER_FINE_SIZE, {setLayout}, 0,
                              staged ? "raster fine (staged)" : "raster fine", motion, cache);
}

void StrandRasterPass::setUpFineWalk(FineWalk requested, std::uint64_t vertices) {
  const bool cpu = ctx_.properties().deviceType == VK_PHYSICAL_DEVICE_TYPE_CPU;
  // The largest lists the pass may make: every one of them fits as a texel view.
  const bool texelsFit = vk::texelBufferFits(ctx_, maxCapacity_) && vk::texelBufferFits(ctx_, vertices);
  walk_ = chooseStagedWalk(requested, cpu, texelsFit) ? FineWalk::Staged : FineWalk::Direct;
  if (walk_ == FineWalk::Staged) return;
  screenTexels_ = vk::BufferView(ctx_, screen_, VK_FORMAT_R32G32B32A32_SFLOAT, "raster screen vertices (texels)");
  colorTexels_ = vk::BufferView(ctx_, colors_, VK_FORMAT_R32G32_UINT, "raster vertex colours (texels)");
}

void StrandRasterPass::bind(std::span<const RasterSource> sources) {
  if (sources.size() != sourceVertices_.size())
    throw Error("compute raster: bind() needs the sources the pass was built for");
  const std::uint32_t chunkTotal = std::uint32_t(chunkCount(sources));
  std::vector<Chunk> chunks;
  std::uint32_t firstVertex = 0;
  for (std::size_t s = 0; s < sources.size(); ++s) {
    const StrandBuffers& strands = *sources[s].strands;
    const std::uint32_t q = strands.layout().verticesPerStrand;
    if (strands.layout().strandVertexCount() != sourceVertices_[s])
      throw Error("compute raster: bind() needs strand buffers of the size the pass was built for");
    for (const StrandChunk& c : strands.chunks()) {
      const std::string name = "raster [source " + std::to_string(s) + " chunk " + std::to_string(chunks.size()) + "]";
      gpu::RasterParams params = baseParams(tilesX_, tilesY_, settings_, list_->capacity, extent_);
      params.firstStrand = c.range.firstStrand;
      params.strandCount = c.range.strandCount;
      params.firstVertex = firstVertex;
      params.verticesPerStrand = q;
      params.chunkIndex = std::uint32_t(chunks.size());
      params.chunkCount = chunkTotal;
      params.maxGroupsX = ctx_.properties().limits.maxComputeWorkGroupCount[0];
      firstVertex += c.range.strandCount * q;
      Chunk chunk{{},
                  vk::Buffer(ctx_, sizeof(params), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                             vk::MemoryKind::DeviceLocal, name + " params"),
                  c.range, std::uint32_t(s), q};
      vk::uploadBytes(ctx_, chunk.params, &params, sizeof(params), vk::BufferUse::ComputeRead);
      for (std::uint32_t slot = 0; slot < frameSlots_; ++slot) {
        chunk.sets.emplace_back(ctx_, kStrandRasterBindings, name + " [slot " + std::to_string(slot) + "]");
        writeChunkSet(chunk.sets.back(), sources[s].shading, c, chunk.params, *list_);
      }
      chunks.push_back(std::move(chunk));
    }
  }
  chunks_ = std::move(chunks);
  slotLists_.assign(frameSlots_, list_);
}

std::shared_ptr<const StrandRasterPass::TileList> StrandRasterPass::makeList(std::uint32_t capacity) const {
  auto list = std::make_shared<TileList>();
  list->buffer = rasterBuffer(ctx_, VkDeviceSize(capacity) * 8, kTexelUsage,
                              "tile lists (" + std::to_string(capacity) + " entries)",
                              ctx_.properties().limits.maxStorageBufferRange);
  if (walk_ == FineWalk::Direct)
    list->texels = vk::BufferView(ctx_, list->buffer, VK_FORMAT_R32G32_UINT, "raster tile lists (texels)");
  list->capacity = capacity;
  return list;
}

void StrandRasterPass::useLists(std::uint32_t slot, std::uint64_t need) {
  if (slot >= frameSlots_)
    throw Error("compute raster: frame slot " + std::to_string(slot) + " of " + std::to_string(frameSlots_));
  const std::uint32_t capacity = sizing_ && !growthFailed_ ? sizing_->next(need, list_->capacity) : 0;
  if (capacity != 0) {
    try {
      list_ = makeList(capacity);
    } catch (const Error&) {
      growthFailed_ = true;  // out of device memory: the lists stay; their overflow is counted as before
    }
  }
  if (slotLists_[slot] == list_) return;
  for (const Chunk& c : chunks_) writeListBindings(c.sets[slot], *list_);
  slotLists_[slot] = list_;
}

std::uint32_t StrandRasterPass::listEntriesPerSegment() const {
  const std::uint64_t tileEntries = std::uint64_t(tilesX_) * tilesY_ * 16;
  const std::uint64_t beyond = list_->capacity > tileEntries ? list_->capacity - tileEntries : 0;
  const std::uint64_t perSegment = segments_ ? (beyond + segments_ - 1) / segments_ : 1;
  return std::uint32_t(std::clamp<std::uint64_t>(perSegment, 1, 8));
}

void StrandRasterPass::recordStateCopy(VkCommandBuffer cmd, const vk::Buffer& dst, VkDeviceSize offset) const {
  // The previous copy into `dst` was read by the host: chained after it (no write-after-write).
  vk::bufferBarrier(ctx_, cmd, dst.handle(), vk::BufferUse::HostRead, vk::BufferUse::TransferDst);
  vk::bufferBarrier(ctx_, cmd, state_.handle(), vk::BufferUse::ComputeWrite, vk::BufferUse::TransferSrc);
  const VkBufferCopy region{0, offset, sizeof(gpu::RasterState)};
  ctx_.fn().vkCmdCopyBuffer(cmd, state_.handle(), dst.handle(), 1, &region);
  vk::bufferBarrier(ctx_, cmd, dst.handle(), vk::BufferUse::TransferDst, vk::BufferUse::HostRead);
  vk::bufferBarrier(ctx_, cmd, state_.handle(), vk::BufferUse::TransferSrc, vk::BufferUse::ComputeWrite);
}

void StrandRasterPass::rebindShading(std::uint32_t source, std::uint32_t slot, const ShadingWriter& shading) {
  if (source >= sourceVertices_.size() || slot >= frameSlots_)
    throw Error("compute raster: rebindShading(" + std::to_string(source) + ", " + std::to_string(slot) +
                ") is past the pass's " + std::to_string(sourceVertices_.size()) + " sources and " +
                std::to_string(frameSlots_) + " slots");
  for (const Chunk& c : chunks_)
    if (c.source == source) shading(c.sets[slot]);
}

const vk::DescriptorSet& StrandRasterPass::setOf(const Chunk& c, std::uint32_t slot) const {
  if (slot >= frameSlots_)
    throw Error("compute raster: frame slot " + std::to_string(slot) + " of " + std::to_string(frameSlots_));
  return c.sets[slot];
}

void StrandRasterPass::writeListBindings(const vk::DescriptorSet& set, const TileList& list) const {
  set.writeStorageBuffer(gpu::RASTER_BINDING_LIST, list.buffer.handle());
  if (list.texels) set.writeTexelBuffer(gpu::RASTER_BINDING_LIST_TEXELS, list.texels.handle());
}

void StrandRasterPass::writeChunkSet(const vk::DescriptorSet& set, const ShadingWriter& shading, const StrandChunk& c,
                                     const vk::Buffer& params, const TileList& list) const {
  shading(set);
  set.writeStorageBuffer(gpu::RASTER_BINDING_PARAMS, params.handle());
  set.writeStorageBuffer(gpu::RENDER_BINDING_POSITIONS, c.positions.handle());
  set.writeStorageBuffer(gpu::RENDER_BINDING_TANGENTS, c.tangents.handle());
  set.writeStorageBuffer(gpu::RENDER_BINDING_ATTRIBUTES, c.attributes.handle());
  set.writeStorageBuffer(gpu::RENDER_BINDING_BOUNCE_SAMPLES, c.bounce.handle());
  // Without previous positions the current ones stand in (motion from the camera only).
  set.writeStorageBuffer(gpu::RASTER_BINDING_PREVIOUS, (c.previous ? c.previous : c.positions).handle());
  set.writeStorageBuffer(gpu::RASTER_BINDING_MOTION, motion_.handle());
  set.writeStorageImage(gpu::RASTER_BINDING_MOTION_OUTPUT, motionOutput_.view());
  for (const auto& [binding, buffer] :
       {std::pair{gpu::RASTER_BINDING_SCREEN, &screen_}, {gpu::RASTER_BINDING_COLORS, &colors_},
        {gpu::RASTER_BINDING_STATE, &state_}, {gpu::RASTER_BINDING_COUNTS, &counts_}, {gpu::RASTER_BINDING_KEYS, &keys_},
        {gpu::RASTER_BINDING_TILES, &tiles_}, {gpu::RASTER_BINDING_BLOCKS, &blocks_},
        {gpu::RASTER_BINDING_TILE_DEPTH, &tileDepth_}, {gpu::RASTER_BINDING_SHADE_FLAGS, &shadeFlags_},
        {gpu::RASTER_BINDING_SHADE_LIST, &shadeList_}, {gpu::RASTER_BINDING_SHADE_ARGS, &shadeArgs_}})
    set.writeStorageBuffer(binding, buffer->handle());
  writeListBindings(set, list);
  if (screenTexels_) {
    set.writeTexelBuffer(gpu::RASTER_BINDING_SCREEN_TEXELS, screenTexels_.handle());
    set.writeTexelBuffer(gpu::RASTER_BINDING_COLOR_TEXELS, colorTexels_.handle());
  }
  set.writeStorageImage(gpu::RASTER_BINDING_OUTPUT, output_.view());
  set.writeStorageImage(gpu::RASTER_BINDING_OUTPUT_NEAR, nearOutput_.view());
  set.writeStorageImage(gpu::RASTER_BINDING_NEAR_MASK, nearMask_.view());
  if (depth_ != VK_NULL_HANDLE) set.writeSampledImage(gpu::RASTER_BINDING_DEPTH, depth_, sampler_.handle());
}

void StrandRasterPass::setDepth(VkImageView depth) {
  depth_ = depth;
  for (const Chunk& c : chunks_)
    for (const vk::DescriptorSet& set : c.sets) set.writeSampledImage(gpu::RASTER_BINDING_DEPTH, depth_, sampler_.handle());
}

void StrandRasterPass::recordArm(VkCommandBuffer cmd) const {
  // The previous frame's steps (compute) finish reading and writing before the transfers re-arm.
  vk::memoryBarrier(ctx_, cmd, vk::BufferUse::ComputeWrite, vk::BufferUse::ComputeWrite);
  vk::bufferBarrier(ctx_, cmd, state_.handle(), vk::BufferUse::ComputeWrite, vk::BufferUse::TransferDst);
  vk::bufferBarrier(ctx_, cmd, counts_.handle(), vk::BufferUse::ComputeWrite, vk::BufferUse::TransferDst);
  vk::bufferBarrier(ctx_, cmd, shadeFlags_.handle(), vk::BufferUse::ComputeWrite, vk::BufferUse::TransferDst);
  // The shade dispatches read their arguments both as indirect commands and in the shader.
  vk::bufferBarrier(ctx_, cmd, shadeArgs_.handle(), vk::BufferUse::IndirectRead, vk::BufferUse::TransferDst);
  vk::bufferBarrier(ctx_, cmd, shadeArgs_.handle(), vk::BufferUse::ComputeWrite, vk::BufferUse::TransferDst);
  const gpu::RasterState armed = armedState();
  const std::vector<glm::uvec4> args = armedShadeArgs(chunks_.size());
  ctx_.fn().vkCmdUpdateBuffer(cmd, state_.handle(), 0, sizeof(armed), &armed);
  ctx_.fn().vkCmdUpdateBuffer(cmd, shadeArgs_.handle(), 0, args.size() * sizeof(glm::uvec4), args.data());
  ctx_.fn().vkCmdFillBuffer(cmd, counts_.handle(), 0, VK_WHOLE_SIZE, 0u);
  ctx_.fn().vkCmdFillBuffer(cmd, shadeFlags_.handle(), 0, VK_WHOLE_SIZE, 0u);
  for (const vk::Buffer* b : {&state_, &counts_, &shadeFlags_, &shadeArgs_})
    vk::bufferBarrier(ctx_, cmd, b->handle(), vk::BufferUse::TransferDst, vk::BufferUse::ComputeWrite);
  // The previous frame's composite sampled the outputs; their contents are rewritten in full.
  for (const vk::Image* image : outputs())
    vk::imageBarrier(ctx_, cmd, image->handle(), VK_IMAGE_ASPECT_COLOR_BIT, vk::ImageUse::FragmentSampledDiscard,
                     vk::ImageUse::ComputeStorageWrite);
}

std::uint32_t StrandRasterPass::drawnStrands(const Chunk& c, std::span<const std::uint32_t> strandLimits) const {
  return strandLimits.empty() ? c.range.strandCount : strandsWithin(c.range, strandLimits[c.source]);
}

// The shaders bound their work by each chunk's RasterParams::strandCount, not by the dispatch (whose groups
// round up): this frame's drawn count goes there, so no strand past the limit is read half-projected.
void StrandRasterPass::recordStrandCounts(VkCommandBuffer cmd, std::span<const std::uint32_t> strandLimits,
                                          std::uint32_t slot) const {
  for (const Chunk& c : chunks_) {
    const std::uint32_t drawn = drawnStrands(c, strandLimits);
    vk::bufferBarrier(ctx_, cmd, c.params.handle(), vk::BufferUse::ComputeRead, vk::BufferUse::TransferDst);
    ctx_.fn().vkCmdUpdateBuffer(cmd, c.params.handle(), offsetof(gpu::RasterParams, strandCount), sizeof(drawn), &drawn);
    if (settings_.growLists) {  // the lists this slot's sets bind (the params are shared by every slot)
      const std::uint32_t capacity = slotLists_[slot]->capacity;
      ctx_.fn().vkCmdUpdateBuffer(cmd, c.params.handle(), offsetof(gpu::RasterParams, capacity), sizeof(capacity),
                                  &capacity);
    }
    vk::bufferBarrier(ctx_, cmd, c.params.handle(), vk::BufferUse::TransferDst, vk::BufferUse::ComputeRead);
  }
}

void StrandRasterPass::recordPerChunk(VkCommandBuffer cmd, const vk::ComputePipeline& pipeline,
                                      std::uint32_t perStrandLess, std::span<const std::uint32_t> strandLimits,
                                      std::uint32_t slot) const {
  for (const Chunk& c : chunks_) {
    const std::uint32_t strands = drawnStrands(c, strandLimits);
    if (strands == 0) continue;
    pipeline.bind(cmd, setOf(c, slot).set());
    pipeline.dispatch(cmd, strands * (c.verticesPerStrand - perStrandLess));
  }
}

void StrandRasterPass::recordOnce(VkCommandBuffer cmd, const vk::ComputePipeline& pipeline,
                                  std::uint32_t threads, std::uint32_t slot) const {
  pipeline.bind(cmd, setOf(chunks_.front(), slot).set());
  pipeline.dispatch(cmd, threads);
}

namespace {
// Each step's writes visible to the next step's reads and writes (all buffers are the pass's own).
void chain(const vk::Context& ctx, VkCommandBuffer cmd) {
  vk::memoryBarrier(ctx, cmd, vk::BufferUse::ComputeWrite, vk::BufferUse::ComputeWrite);
}

void begin(VkCommandBuffer cmd, vk::GpuProfiler* profiler, const char* name) {
  if (profiler) profiler->begin(cmd, name);
}
void end(VkCommandBuffer cmd, vk::GpuProfiler* profiler) {
  if (profiler) profiler->end(cmd);
}
}  // namespace

void StrandRasterPass::recordBinning(VkCommandBuffer cmd, vk::GpuProfiler* profiler,
                                     std::span<const std::uint32_t> strandLimits, std::uint32_t slot) const {
  if (depth_ == VK_NULL_HANDLE) throw Error("compute raster: setDepth() was not called before record()");
  if (!strandLimits.empty() && strandLimits.size() != sourceVertices_.size())
    throw Error("compute raster: one strand limit per source, got " + std::to_string(strandLimits.size()));
  const std::uint32_t tiles = tilesX_ * tilesY_;
  begin(cmd, profiler, "raster project");
  recordStrandCounts(cmd, strandLimits, slot);
  recordArm(cmd);
  recordPerChunk(cmd, project_, 0, strandLimits, slot);
  end(cmd, profiler);
  begin(cmd, profiler, "raster bin");
  begin(cmd, profiler, "raster tile depth");
  recordOnce(cmd, tileDepthPipeline_, tiles, slot);
  chain(ctx_, cmd);
  end(cmd, profiler);
  begin(cmd, profiler, "raster count");
  recordPerChunk(cmd, count_, 1, strandLimits, slot);
  chain(ctx_, cmd);
  end(cmd, profiler);
  begin(cmd, profiler, "raster scan");
  recordOnce(cmd, budgetTiles_, divUp(tiles, gpu::RASTER_SCAN_SIZE) * gpu::RASTER_SCAN_SIZE, slot);
  chain(ctx_, cmd);
  recordOnce(cmd, scanTiles_, divUp(tiles, gpu::RASTER_SCAN_SIZE) * gpu::RASTER_SCAN_SIZE, slot);
  chain(ctx_, cmd);
  recordOnce(cmd, scanBlocks_, gpu::RASTER_SCAN_SIZE, slot);
  chain(ctx_, cmd);
  end(cmd, profiler);
  begin(cmd, profiler, "raster scatter");
  recordPerChunk(cmd, scatter_, 1, strandLimits, slot);
  end(cmd, profiler);
  end(cmd, profiler);
}

void StrandRasterPass::recordFine(VkCommandBuffer cmd, vk::GpuProfiler* profiler,
                                  std::span<const ShadeVariant> shading, std::uint32_t slot) const {
  if (!shading.empty() && shading.size() != sourceVertices_.size())
    throw Error("compute raster: one shade variant per source, got " + std::to_string(shading.size()));
  begin(cmd, profiler, "raster shade");
  // The scan wrote the shade dispatches (indirect arguments) and the count step the shade lists.
  vk::bufferBarrier(ctx_, cmd, shadeArgs_.handle(), vk::BufferUse::ComputeWrite, vk::BufferUse::IndirectRead);
  chain(ctx_, cmd);
  for (std::size_t i = 0; i < chunks_.size(); ++i) {
    const vk::ComputePipeline& shade = shade_->get(shading.empty() ? ShadeVariant{} : shading[chunks_[i].source]);
    shade.bind(cmd, setOf(chunks_[i], slot).set());
    shade.dispatchIndirect(cmd, shadeArgs_.handle(), i * sizeof(glm::uvec4));
  }
  end(cmd, profiler);
  begin(cmd, profiler, "raster fine");
  chain(ctx_, cmd);
  recordOnce(cmd, fine_, tilesX_ * tilesY_ * gpu::RASTER_FINE_SIZE, slot);
  for (const vk::Image* image : outputs())
    vk::imageBarrier(ctx_, cmd, image->handle(), VK_IMAGE_ASPECT_COLOR_BIT, vk::ImageUse::ComputeStorageWrite,
                     vk::ImageUse::FragmentSampled);
  end(cmd, profiler);
}

std::vector<float> StrandRasterPass::readCoverage() const {
  const std::size_t pixels = std::size_t(extent_.width) * extent_.height;
  const auto alphas = [&](const vk::Image& image) {
    const std::vector<std::byte> bytes = vk::readbackImage(ctx_, image, vk::ImageUse::FragmentSampled);
    std::vector<float> a(pixels);
    for (std::size_t i = 0; i < pixels; ++i) {
      std::uint16_t half;
      std::memcpy(&half, bytes.data() + (i * 4 + 3) * sizeof(half), sizeof(half));
      a[i] = shading::halfToFloat(half);
    }
    return a;
  };
  std::vector<float> coverage = alphas(output_);
  if (!multisampled()) return coverage;
  const std::vector<float> near = alphas(nearOutput_);
  const std::vector<std::byte> maskBytes = vk::readbackImage(ctx_, nearMask_, vk::ImageUse::FragmentSampled);
  for (std::size_t i = 0; i < pixels; ++i) {
    std::uint32_t mask;
    std::memcpy(&mask, maskBytes.data() + i * sizeof(mask), sizeof(mask));
    const float nearShare = float(std::popcount(mask)) / float(headSamples_);
    coverage[i] = nearShare * near[i] + (1.0f - nearShare) * coverage[i];
  }
  return coverage;
}

std::vector<glm::vec2> StrandRasterPass::readMotion() const {
  if (!settings_.motion) throw Error("compute raster: readMotion() needs RasterSettings::motion");
  const std::size_t pixels = std::size_t(extent_.width) * extent_.height;
  const std::vector<std::byte> bytes = vk::readbackImage(ctx_, motionOutput_, vk::ImageUse::FragmentSampled);
  std::vector<glm::vec2> motion(pixels);
  for (std::size_t i = 0; i < pixels; ++i) {
    std::uint16_t half[2];
    std::memcpy(half, bytes.data() + i * sizeof(half), sizeof(half));
    motion[i] = {shading::halfToFloat(half[0]), shading::halfToFloat(half[1])};
  }
  return motion;
}

RasterStats StrandRasterPass::readStats() const {
  const auto state = vk::readback<gpu::RasterState>(ctx_, state_, vk::BufferUse::ComputeWrite, 1);
  RasterStats s;
  s.requested = state[0].entries.x;
  s.droppedByTileBudget = state[0].entries.y;
  s.droppedByCapacity = state[0].entries.z;
  s.kept = state[0].entries.w;
  for (const glm::uvec4& chunk : vk::readback<glm::uvec4>(ctx_, shadeArgs_, vk::BufferUse::IndirectRead, chunks_.size()))
    s.shaded += chunk.w;
  s.walk = walk_;
  s.listCapacity = list_->capacity;
  return s;
}
}  // namespace hp::compute
