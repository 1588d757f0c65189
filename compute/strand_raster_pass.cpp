#include "compute/strand_raster_pass.h"

#include <algorithm>
#include <string>

#include "engine/error.h"
#include "engine/vk/barriers.h"
#include "engine/vk/context.h"
#include "engine/vk/transfer.h"
#include "shaders/shared/raster.h"
#include "shaders/shared/render.h"

namespace hp::compute {
namespace {
constexpr VkShaderStageFlags kCompute = VK_SHADER_STAGE_COMPUTE_BIT;
constexpr VkDescriptorType kStorage = VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
constexpr VkDescriptorType kSampled = VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
// The raster's own bindings follow the shading bindings of shaders/shared/render.h in one set.
static_assert(gpu::RASTER_BINDING_SCREEN > gpu::RENDER_BINDING_HEAD_SHADOW, "raster bindings overlap render.h's");
// No uniform buffers and no push constants: lavapipe would recompile each step per dispatch
// (docs/DESIGN.md, driver notes); the frame block, the Marschner block and the per-chunk parameters are
// read-only storage buffers.
const vk::Binding kBindings[] = {
    {gpu::RENDER_BINDING_FRAME, kStorage, kCompute},
    {gpu::RENDER_BINDING_MARSCHNER, kStorage, kCompute},
    {gpu::RENDER_BINDING_LUT_M, kSampled, kCompute},
    {gpu::RENDER_BINDING_LUT_N0, kSampled, kCompute},
    {gpu::RENDER_BINDING_LUT_N1, kSampled, kCompute},
    {gpu::RENDER_BINDING_OPACITY, kSampled, kCompute},
    {gpu::RENDER_BINDING_HEAD_SHADOW, kSampled, kCompute},
    {gpu::RENDER_BINDING_LIGHT, kStorage, kCompute},
    {gpu::RENDER_BINDING_POSITIONS, kStorage, kCompute},
    {gpu::RENDER_BINDING_TANGENTS, kStorage, kCompute},
    {gpu::RENDER_BINDING_ATTRIBUTES, kStorage, kCompute},
    {gpu::RASTER_BINDING_SCREEN, kStorage, kCompute},
    {gpu::RASTER_BINDING_COLORS, kStorage, kCompute},
    {gpu::RASTER_BINDING_STATE, kStorage, kCompute},
    {gpu::RASTER_BINDING_COUNTS, kStorage, kCompute},
    {gpu::RASTER_BINDING_KEYS, kStorage, kCompute},
    {gpu::RASTER_BINDING_TILES, kStorage, kCompute},
    {gpu::RASTER_BINDING_BLOCKS, kStorage, kCompute},
    {gpu::RASTER_BINDING_LIST, kStorage, kCompute},
    {gpu::RASTER_BINDING_DEPTH, kSampled, kCompute},
    {gpu::RASTER_BINDING_OUTPUT, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, kCompute},
    {gpu::RASTER_BINDING_PARAMS, kStorage, kCompute},
    {gpu::RASTER_BINDING_TILE_DEPTH, kStorage, kCompute},
};
constexpr VkBufferUsageFlags kStorageUsage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT;
constexpr VkBufferUsageFlags kArmedUsage =
    VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT | VK_BUFFER_USAGE_TRANSFER_SRC_BIT;

std::uint32_t divUp(std::uint32_t a, std::uint32_t b) { return (a + b - 1) / b; }

gpu::RasterState armedState() {
  gpu::RasterState s{};
  s.depthBits = glm::uvec4(0xFFFFFFFFu, 0u, 0u, 0u);  // min, max of non-negative float bits
  return s;
}

vk::Buffer deviceBuffer(const vk::Context& ctx, VkDeviceSize bytes, VkBufferUsageFlags usage, const std::string& name,
                        VkDeviceSize limit) {
  if (bytes > limit)
    throw Error("compute raster: the " + name + " buffer needs " + std::to_string(bytes) +
                " bytes, more than the device's maxStorageBufferRange (" + std::to_string(limit) +
                "); use fewer strands or --raster graphics");
  return vk::Buffer(ctx, std::max<VkDeviceSize>(bytes, 16), usage, vk::MemoryKind::DeviceLocal, "raster " + name);
}

gpu::RasterParams baseParams(std::uint32_t tilesX, std::uint32_t tilesY, std::uint32_t budget,
                             std::uint32_t capacity, VkExtent2D extent, std::uint32_t q) {
  gpu::RasterParams p{};
  p.tilesX = tilesX;
  p.tilesY = tilesY;
  p.tileBudget = budget;
  p.capacity = capacity;
  p.width = extent.width;
  p.height = extent.height;
  p.verticesPerStrand = q;
  return p;
}
}  // namespace

void RasterSettings::validate() const {
  if (tileBudget == 0 || tileBudget > (1u << 24))
    throw Error("RasterSettings.tileBudget must be in [1, 16777216], got " + std::to_string(tileBudget));
}

std::uint32_t rasterListCapacity(std::uint64_t segments, std::uint64_t tiles, std::uint64_t maxRangeBytes) {
  const std::uint64_t wanted = segments * 8 + tiles * 16;
  return std::uint32_t(std::clamp<std::uint64_t>(wanted, 1024, std::min<std::uint64_t>(maxRangeBytes / 4, 0xFFFFFFFFu)));
}

StrandRasterPass::StrandRasterPass(const vk::Context& ctx, const StrandBuffers& strands, const ShadingWriter& shading,
                                   VkExtent2D extent, const RasterSettings& settings)
    : ctx_(ctx), extent_(extent), settings_(settings) {
  settings.validate();
  if (extent.width == 0 || extent.height == 0) throw Error("compute raster: the extent must be non-zero");
  tilesX_ = divUp(extent.width, gpu::RASTER_TILE_SIZE);
  tilesY_ = divUp(extent.height, gpu::RASTER_TILE_SIZE);
  const StrandLayout& layout = strands.layout();
  q_ = layout.verticesPerStrand;
  const VkDeviceSize limit = ctx.properties().limits.maxStorageBufferRange;
  const std::uint64_t vertices = layout.strandVertexCount();
  const std::uint64_t tiles = std::uint64_t(tilesX_) * tilesY_;
  capacity_ = rasterListCapacity(std::uint64_t(layout.strandCount) * (q_ - 1), tiles, limit);
  screen_ = deviceBuffer(ctx, vertices * 16, kStorageUsage, "screen vertices", limit);
  colors_ = deviceBuffer(ctx, vertices * 8, kStorageUsage, "vertex colours", limit);
  state_ = deviceBuffer(ctx, sizeof(gpu::RasterState), kArmedUsage, "state", limit);
  counts_ = deviceBuffer(ctx, tiles * gpu::RASTER_DEPTH_BINS * 4, kArmedUsage, "key counts", limit);
  keys_ = deviceBuffer(ctx, tiles * gpu::RASTER_DEPTH_BINS * 8, kStorageUsage, "keys", limit);
  tiles_ = deviceBuffer(ctx, tiles * 8, kStorageUsage, "tiles", limit);
  tileDepth_ = deviceBuffer(ctx, tiles * 4, kStorageUsage, "tile head depth", limit);
  blocks_ = deviceBuffer(ctx, divUp(std::uint32_t(tiles), gpu::RASTER_SCAN_SIZE) * 4, kStorageUsage, "blocks", limit);
  list_ = deviceBuffer(ctx, VkDeviceSize(capacity_) * 4, kStorageUsage, "tile lists", limit);
  output_ = vk::Image(ctx, {extent.width, extent.height, 1, VK_FORMAT_R16G16B16A16_SFLOAT,
                            VK_IMAGE_USAGE_STORAGE_BIT | VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_TRANSFER_SRC_BIT,
                            VK_SAMPLE_COUNT_1_BIT, "raster hair image"});
  sampler_ = vk::Sampler(ctx, "raster depth sampler", VK_FILTER_NEAREST);  // D32 cannot filter
  const gpu::RasterState armed = armedState();
  vk::uploadBytes(ctx, state_, &armed, sizeof(armed), vk::BufferUse::ComputeWrite);
  bind(strands, shading);
  const auto setLayout = chunks_.front().set.layout();
  const auto pipeline = [&](const char* shader, std::uint32_t size, const char* name) {
    return vk::ComputePipeline(ctx, shader, size, {setLayout}, 0, name);
  };
  shade_ = pipeline("raster_shade.comp", gpu::RASTER_WORKGROUP_SIZE, "raster shade");
  tileDepthPipeline_ = pipeline("raster_tile_depth.comp", gpu::RASTER_WORKGROUP_SIZE, "raster tile depth");
  count_ = vk::ComputePipeline(ctx, "raster_bin.comp", gpu::RASTER_WORKGROUP_SIZE, {setLayout}, 0, "raster count",
                               {gpu::RASTER_MODE_COUNT});
  scatter_ = vk::ComputePipeline(ctx, "raster_bin.comp", gpu::RASTER_WORKGROUP_SIZE, {setLayout}, 0, "raster scatter",
                                 {gpu::RASTER_MODE_SCATTER});
  scanTiles_ = pipeline("raster_scan_tiles.comp", gpu::RASTER_SCAN_SIZE, "raster scan tiles");
  scanBlocks_ = pipeline("raster_scan_blocks.comp", gpu::RASTER_SCAN_SIZE, "raster scan blocks");
  fine_ = pipeline("raster_fine.comp", gpu::RASTER_FINE_SIZE, "raster fine");
}

void StrandRasterPass::bind(const StrandBuffers& strands, const ShadingWriter& shading) {
  if (strands.layout().verticesPerStrand != q_ || strands.layout().strandVertexCount() * 16 > screen_.size())
    throw Error("compute raster: bind() needs strand buffers of the size the pass was built for");
  std::vector<Chunk> chunks;
  for (const StrandChunk& c : strands.chunks()) {
    const std::string name = "raster [chunk " + std::to_string(chunks.size()) + "]";
    gpu::RasterParams params = baseParams(tilesX_, tilesY_, settings_.tileBudget, capacity_, extent_, q_);
    params.firstStrand = c.range.firstStrand;
    params.strandCount = c.range.strandCount;
    Chunk chunk{vk::DescriptorSet(ctx_, kBindings, name),
                vk::Buffer(ctx_, sizeof(params), VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT,
                           vk::MemoryKind::DeviceLocal, name + " params"),
                c.range.strandCount};
    vk::uploadBytes(ctx_, chunk.params, &params, sizeof(params), vk::BufferUse::ComputeRead);
    const vk::DescriptorSet& set = chunk.set;
    shading(set);
    set.writeStorageBuffer(gpu::RASTER_BINDING_PARAMS, chunk.params.handle());
    set.writeStorageBuffer(gpu::RENDER_BINDING_POSITIONS, c.positions.handle());
    set.writeStorageBuffer(gpu::RENDER_BINDING_TANGENTS, c.tangents.handle());
    set.writeStorageBuffer(gpu::RENDER_BINDING_ATTRIBUTES, c.attributes.handle());
    set.writeStorageBuffer(gpu::RASTER_BINDING_SCREEN, screen_.handle());
    set.writeStorageBuffer(gpu::RASTER_BINDING_COLORS, colors_.handle());
    set.writeStorageBuffer(gpu::RASTER_BINDING_STATE, state_.handle());
    set.writeStorageBuffer(gpu::RASTER_BINDING_COUNTS, counts_.handle());
    set.writeStorageBuffer(gpu::RASTER_BINDING_KEYS, keys_.handle());
    set.writeStorageBuffer(gpu::RASTER_BINDING_TILES, tiles_.handle());
    set.writeStorageBuffer(gpu::RASTER_BINDING_BLOCKS, blocks_.handle());
    set.writeStorageBuffer(gpu::RASTER_BINDING_LIST, list_.handle());
    set.writeStorageBuffer(gpu::RASTER_BINDING_TILE_DEPTH, tileDepth_.handle());
    set.writeStorageImage(gpu::RASTER_BINDING_OUTPUT, output_.view());
    if (depth_ != VK_NULL_HANDLE) set.writeSampledImage(gpu::RASTER_BINDING_DEPTH, depth_, sampler_.handle());
    chunks.push_back(std::move(chunk));
  }
  chunks_ = std::move(chunks);
}

void StrandRasterPass::setDepth(VkImageView depth) {
  depth_ = depth;
  for (const Chunk& c : chunks_) c.set.writeSampledImage(gpu::RASTER_BINDING_DEPTH, depth_, sampler_.handle());
}

void StrandRasterPass::recordArm(VkCommandBuffer cmd) const {
  // The previous frame's steps (compute) finish reading and writing before the transfers re-arm.
  vk::memoryBarrier(ctx_, cmd, vk::BufferUse::ComputeWrite, vk::BufferUse::ComputeWrite);
  vk::bufferBarrier(ctx_, cmd, state_.handle(), vk::BufferUse::ComputeWrite, vk::BufferUse::TransferDst);
  vk::bufferBarrier(ctx_, cmd, counts_.handle(), vk::BufferUse::ComputeWrite, vk::BufferUse::TransferDst);
  const gpu::RasterState armed = armedState();
  ctx_.fn().vkCmdUpdateBuffer(cmd, state_.handle(), 0, sizeof(armed), &armed);
  ctx_.fn().vkCmdFillBuffer(cmd, counts_.handle(), 0, VK_WHOLE_SIZE, 0u);
  vk::bufferBarrier(ctx_, cmd, state_.handle(), vk::BufferUse::TransferDst, vk::BufferUse::ComputeWrite);
  vk::bufferBarrier(ctx_, cmd, counts_.handle(), vk::BufferUse::TransferDst, vk::BufferUse::ComputeWrite);
  // The previous frame's composite sampled the output; its contents are rewritten in full.
  vk::imageBarrier(ctx_, cmd, output_.handle(), VK_IMAGE_ASPECT_COLOR_BIT, vk::ImageUse::FragmentSampledDiscard,
                   vk::ImageUse::ComputeStorageWrite);
}

void StrandRasterPass::recordPerChunk(VkCommandBuffer cmd, const vk::ComputePipeline& pipeline,
                                      std::uint32_t perStrand) const {
  for (const Chunk& c : chunks_) {
    pipeline.bind(cmd, c.set.set());
    pipeline.dispatch(cmd, c.strandCount * perStrand);
  }
}

void StrandRasterPass::recordOnce(VkCommandBuffer cmd, const vk::ComputePipeline& pipeline,
                                  std::uint32_t threads) const {
  pipeline.bind(cmd, chunks_.front().set.set());
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

void StrandRasterPass::recordBinning(VkCommandBuffer cmd, vk::GpuProfiler* profiler) const {
  if (depth_ == VK_NULL_HANDLE) throw Error("compute raster: setDepth() was not called before record()");
  const std::uint32_t tiles = tilesX_ * tilesY_;
  begin(cmd, profiler, "raster shade");
  recordArm(cmd);
  recordPerChunk(cmd, shade_, q_);
  end(cmd, profiler);
  begin(cmd, profiler, "raster bin");
  recordOnce(cmd, tileDepthPipeline_, tiles);
  chain(ctx_, cmd);
  recordPerChunk(cmd, count_, q_ - 1);
  chain(ctx_, cmd);
  recordOnce(cmd, scanTiles_, divUp(tiles, gpu::RASTER_SCAN_SIZE) * gpu::RASTER_SCAN_SIZE);
  chain(ctx_, cmd);
  recordOnce(cmd, scanBlocks_, gpu::RASTER_SCAN_SIZE);
  chain(ctx_, cmd);
  recordPerChunk(cmd, scatter_, q_ - 1);
  end(cmd, profiler);
}

void StrandRasterPass::recordFine(VkCommandBuffer cmd, vk::GpuProfiler* profiler) const {
  begin(cmd, profiler, "raster fine");
  chain(ctx_, cmd);
  recordOnce(cmd, fine_, tilesX_ * tilesY_ * gpu::RASTER_FINE_SIZE);
  vk::imageBarrier(ctx_, cmd, output_.handle(), VK_IMAGE_ASPECT_COLOR_BIT, vk::ImageUse::ComputeStorageWrite,
                   vk::ImageUse::FragmentSampled);
  end(cmd, profiler);
}

RasterStats StrandRasterPass::readStats() const {
  const auto state = vk::readback<gpu::RasterState>(ctx_, state_, vk::BufferUse::ComputeWrite, 1);
  RasterStats s;
  s.requested = state[0].entries.x;
  s.droppedByTileBudget = state[0].entries.y;
  s.droppedByCapacity = state[0].entries.z;
  s.kept = state[0].entries.w;
  return s;
}
}  // namespace hp::compute
