#include "compute/strands/strand_buffers.h"

#include <algorithm>
#include <bit>
#include <string>

#include "engine/core/error.h"
#include "engine/core/hair/hairline_distance.h"
#include "engine/vk/context.h"
#include "engine/vk/transfer.h"

namespace hp::compute {
namespace {
constexpr VkBufferUsageFlags kStrandBuffersUsage =
    VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_SRC_BIT | VK_BUFFER_USAGE_TRANSFER_DST_BIT;
constexpr VkDeviceSize kVec4 = 16;
constexpr VkDeviceSize kBounceSample = 8;  // uvec2: rgb as half floats

void refuseOversized(const char* what, std::uint64_t bytes, VkDeviceSize limit) {
  if (bytes > limit)
    throw Error(std::string(what) + ": " + std::to_string(bytes) + " bytes exceed the device's maxStorageBufferRange (" +
                std::to_string(limit) + " bytes)");
}

std::vector<ChunkRange> splitIntoChunks(std::uint32_t strands, std::uint32_t perChunk) {
  std::vector<ChunkRange> chunks;
  for (std::uint32_t first = 0; first < strands; first += perChunk)
    chunks.push_back({first, std::min(perChunk, strands - first)});
  return chunks;
}

vk::Buffer strandBuffer(const vk::Context& ctx, VkDeviceSize bytes, const std::string& name) {
  return vk::Buffer(ctx, std::max<VkDeviceSize>(bytes, kVec4), kStrandBuffersUsage, vk::MemoryKind::DeviceLocal, name);
}

std::vector<gpu::StrandBindingGpu> packBindings(const InterpolationTopology& topology, ChunkRange range) {
  std::vector<gpu::StrandBindingGpu> out(range.strandCount);
  for (std::uint32_t k = 0; k < range.strandCount; ++k) {
    const StrandBinding& b = topology.strands[range.firstStrand + k];
    out[k] = {b.barycentric.x, b.barycentric.y, b.random, b.triangle};
  }
  return out;
}

// xyz: the guides; w: the bits of the triangle's hairline distance (kNoHairline where the topology has none).
std::vector<glm::uvec4> packTriangles(const InterpolationTopology& topology) {
  std::vector<glm::uvec4> out(topology.triangles.size());
  const bool distances = topology.hairlineDistance.size() == out.size();
  for (std::size_t t = 0; t < out.size(); ++t)
    out[t] = glm::uvec4(topology.triangles[t], std::bit_cast<std::uint32_t>(distances ? topology.hairlineDistance[t] : kNoHairline));
  return out;
}

template <class T>
void appendReadback(const vk::Context& ctx, const vk::Buffer& buffer, vk::BufferUse before, std::size_t count,
                    std::vector<T>& out) {
  if (count == 0) return;
  std::vector<T> part = vk::readback<T>(ctx, buffer, before, count);
  out.insert(out.end(), part.begin(), part.end());
}
}  // namespace

void validateVerticesPerStrand(std::uint32_t q, std::uint32_t p) {
  if (q < p || q > gpu::MAX_VERTICES_PER_STRAND)
    throw Error("verticesPerStrand (Q) must be in [particlesPerGuide = " + std::to_string(p) + ", " +
                std::to_string(gpu::MAX_VERTICES_PER_STRAND) + "], got " + std::to_string(q) +
                (q < p ? ": a render strand needs a vertex for each of its guide's particles; give the guides at most " +
                             std::to_string(q) + " particles (a scene's growth.particles, a model kept as is "
                             "with fewer points per strand) or more vertices (strands --vertices)"
                       : ""));
}

void validateBounceSamples(std::uint32_t samples, const char* field) {
  if (samples < 2 || samples > gpu::MAX_VERTICES_PER_STRAND)
    throw Error(std::string(field) + " must be in [2, " + std::to_string(gpu::MAX_VERTICES_PER_STRAND) + "], got " +
                std::to_string(samples));
}

StrandLayout planStrandLayout(std::uint32_t guideCount, std::uint32_t particlesPerGuide, std::uint32_t triangleCount,
                              std::uint32_t strandCount, const StrandOptions& options,
                              VkDeviceSize maxStorageBufferRange) {
  validateVerticesPerStrand(options.verticesPerStrand, particlesPerGuide);
  if (particlesPerGuide < 2) throw Error("strand layout: particlesPerGuide must be at least 2");
  if (guideCount == 0) throw Error("strand layout: no guides");
  validateBounceSamples(options.bounceSamples, "strand layout: bounceSamples");
  StrandLayout l;
  l.guideCount = guideCount;
  l.particlesPerGuide = particlesPerGuide;
  l.verticesPerStrand = options.verticesPerStrand;
  l.bounceSamples = std::min(options.bounceSamples, options.verticesPerStrand);
  l.bounceAtGuides = options.bounceAtGuides && !options.guidesOnly;
  l.guidesOnly = options.guidesOnly;
  l.triangleCount = options.guidesOnly ? 0 : triangleCount;
  l.strandCount = options.guidesOnly ? guideCount : strandCount;
  if (l.strandCount == 0) throw Error("strand layout: no render strands");

  VkDeviceSize limit = maxStorageBufferRange;
  if (options.maxChunkBytes) limit = std::min(limit, options.maxChunkBytes);
  const std::uint64_t strandBytes = std::uint64_t(l.verticesPerStrand) * kVec4;
  refuseOversized("guide particles (G x P x 16)", std::uint64_t(guideCount) * particlesPerGuide * kVec4,
                  maxStorageBufferRange);
  refuseOversized("smoothed guides (G x Q x 16)", std::uint64_t(guideCount) * strandBytes, maxStorageBufferRange);
  refuseOversized("triangles (T x 16)", std::uint64_t(l.triangleCount) * kVec4, maxStorageBufferRange);
  refuseOversized("one render strand (Q x 16)", strandBytes, limit);
  const std::uint64_t perChunk = std::min<std::uint64_t>(limit / strandBytes, l.strandCount);
  l.chunks = splitIntoChunks(l.strandCount, static_cast<std::uint32_t>(perChunk));
  return l;
}

void checkStrandMemory(const StrandLayout& layout, VkDeviceSize heapBytes) {
  // Per strand: positions and tangents (Q vec4 each), binding, attributes and the bounce samples (8 bytes
  // each); plus the smoothed guides and their bounce samples.
  const double perStrand =
      double(layout.verticesPerStrand) * 2.0 * kVec4 + 2.0 * kVec4 + double(layout.bounceSamples) * kBounceSample;
  const double perGuide = layout.verticesPerStrand * 2.0 * kVec4 +
                          (layout.bounceAtGuides ? double(layout.bounceSamples) * kBounceSample : 0.0);
  const double bytes = double(layout.strandCount) * perStrand + double(layout.guideCount) * perGuide;
  if (bytes > double(heapBytes))
    throw Error("strand buffers: " + std::to_string(layout.strandCount) + " strands x " +
                std::to_string(layout.verticesPerStrand) + " vertices need " +
                std::to_string(std::uint64_t(bytes / (1 << 20))) + " MiB, more than this device's " +
                std::to_string(heapBytes >> 20) + " MiB device-local heap");
}

StrandBuffers::StrandBuffers(const vk::Context& ctx, std::uint32_t guideCount, std::uint32_t particlesPerGuide,
                             const InterpolationTopology& topology, const StrandOptions& options)
    : layout_(planStrandLayout(guideCount, particlesPerGuide, static_cast<std::uint32_t>(topology.triangles.size()),
                               static_cast<std::uint32_t>(topology.strands.size()), options,
                               ctx.properties().limits.maxStorageBufferRange)) {
  checkStrandMemory(layout_, ctx.deviceLocalHeapBytes());
  const VkDeviceSize guideBytes = VkDeviceSize(guideCount) * layout_.verticesPerStrand * kVec4;
  guidePositions_ = strandBuffer(ctx, guideBytes, "smoothed guide positions");
  guideTangents_ = strandBuffer(ctx, guideBytes, "smoothed guide tangents");
  triangles_ = strandBuffer(ctx, VkDeviceSize(layout_.triangleCount) * kVec4, "strand triangles");
  // A placeholder where the bounce is gathered along the render strands themselves.
  guideBounce_ = strandBuffer(ctx, layout_.bounceAtGuides ? VkDeviceSize(guideCount) * layout_.bounceSamples * kBounceSample : 0,
                              "guide bounce samples");
  for (std::size_t c = 0; c < layout_.chunks.size(); ++c) {
    const ChunkRange range = layout_.chunks[c];
    const std::string tag = " [chunk " + std::to_string(c) + "]";
    const VkDeviceSize vertexBytes = VkDeviceSize(range.strandCount) * layout_.verticesPerStrand * kVec4;
    const VkDeviceSize strandBytes = layout_.guidesOnly ? 0 : VkDeviceSize(range.strandCount) * kVec4;
    chunks_.push_back({range, strandBuffer(ctx, strandBytes, "strand bindings" + tag),
                       strandBuffer(ctx, vertexBytes, "strand positions" + tag),
                       strandBuffer(ctx, vertexBytes, "strand tangents" + tag),
                       strandBuffer(ctx, VkDeviceSize(range.strandCount) * kVec4, "strand attributes" + tag),
                       options.previousPositions ? strandBuffer(ctx, vertexBytes, "strand previous positions" + tag)
                                                 : vk::Buffer(),
                       strandBuffer(ctx, VkDeviceSize(range.strandCount) * layout_.bounceSamples * kBounceSample,
                                    "strand bounce samples" + tag)});
  }
  keepsPrevious_ = options.previousPositions;
  if (!layout_.guidesOnly) uploadTopology(ctx, topology);
}

void StrandBuffers::recordKeepPrevious(const vk::Context& ctx, VkCommandBuffer cmd) const {
  if (!keepsPrevious_) return;
  for (const StrandChunk& c : chunks_) {
    const VkBufferCopy region{0, 0, c.positions.size()};
    ctx.fn().vkCmdCopyBuffer(cmd, c.positions.handle(), c.previous.handle(), 1, &region);
  }
}

void StrandBuffers::uploadTopology(const vk::Context& ctx, const InterpolationTopology& topology) {
  for (std::size_t t = 0; t < topology.triangles.size(); ++t)
    if (glm::any(glm::greaterThanEqual(topology.triangles[t], glm::uvec3(layout_.guideCount))))
      throw Error("strand buffers: triangle " + std::to_string(t) + " names a guide beyond " +
                  std::to_string(layout_.guideCount));
  for (const StrandBinding& s : topology.strands)
    if (s.triangle >= layout_.triangleCount)
      throw Error("strand buffers: a strand names triangle " + std::to_string(s.triangle) + " of " +
                  std::to_string(layout_.triangleCount));
  vk::upload<glm::uvec4>(ctx, triangles_, packTriangles(topology), vk::BufferUse::ComputeRead);
  for (const StrandChunk& chunk : chunks_)
    vk::upload<gpu::StrandBindingGpu>(ctx, chunk.bindings, packBindings(topology, chunk.range),
                                      vk::BufferUse::ComputeRead);
}

StrandData readRenderStrands(const vk::Context& ctx, const StrandBuffers& buffers, vk::BufferUse before) {
  StrandData d;
  const std::size_t q = buffers.layout().verticesPerStrand;
  for (const StrandChunk& chunk : buffers.chunks()) {
    appendReadback(ctx, chunk.positions, before, chunk.range.strandCount * q, d.positions);
    appendReadback(ctx, chunk.tangents, before, chunk.range.strandCount * q, d.tangents);
    appendReadback(ctx, chunk.attributes, before, chunk.range.strandCount, d.attributes);
  }
  return d;
}

StrandData readSmoothedGuides(const vk::Context& ctx, const StrandBuffers& buffers, vk::BufferUse before) {
  StrandData d;
  const std::size_t n = std::size_t(buffers.layout().guideCount) * buffers.layout().verticesPerStrand;
  appendReadback(ctx, buffers.guidePositions(), before, n, d.positions);
  appendReadback(ctx, buffers.guideTangents(), before, n, d.tangents);
  return d;
}
}  // namespace hp::compute
