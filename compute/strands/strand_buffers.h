#pragma once
// Contract: owns the device buffers between the simulation and the draw passes: the smoothed guides
// (tessellate output, G x Q), the interpolation topology (triangles, per-strand bindings) and the
// render strands (positions, tangents, per-strand attributes), laid out as shaders/shared/strands.h
// documents. Everything is sized once at construction; a density, vertex-count or guides-only change
// builds a new StrandBuffers outside the frame loop (the GPU must be done with the old one).
//
// Per-strand arrays are split into chunks of whole strands so that no descriptor range exceeds the
// device's maxStorageBufferRange (lavapipe: 128 MiB, i.e. 233,016 strands of 36 vertices), so 1M
// strands work as 5 chunks. Each chunk is its own set of buffers; later passes draw chunk by chunk.
// Buffers that cannot be chunked (smoothed guides, triangles) are refused with hp::Error naming the
// limit when they would exceed it.
//
// The topology is uploaded at construction and left in BufferUse::ComputeRead. The smoothed guide
// and render strand buffers start with undefined contents (first use: BufferUse::None).
#include <cstdint>
#include <span>
#include <vector>

#include <glm/glm.hpp>

#include "engine/core/hair/strand_topology.h"
#include "engine/vk/barriers.h"
#include "engine/vk/buffer.h"
#include "shaders/shared/render.h"
#include "shaders/shared/strands.h"

namespace hp::vk {
class Context;
}

namespace hp::compute {
inline constexpr std::uint32_t kDefaultVerticesPerStrand = 36;

struct StrandOptions {
  std::uint32_t verticesPerStrand = kDefaultVerticesPerStrand;  // Q, in [particlesPerGuide, 256]
  bool guidesOnly = false;       // debug: the render strands are the smoothed guides, one per guide
  VkDeviceSize maxChunkBytes = 0;  // 0: maxStorageBufferRange; smaller forces more chunks (tests)
  // Keep each chunk's previous render positions (StrandChunk::previous, copied by keepPrevious): the
  // compute raster's motion vectors read them.
  bool previousPositions = false;
  // Points per strand where the skin's bounce is gathered (shaders/bounce_samples.glsl), at most Q: the
  // shading interpolates between them. At least 2; Q (or more) gathers at every vertex.
  std::uint32_t bounceSamples = gpu::RENDER_BOUNCE_STRAND_SAMPLES;
  // Where the skin's bounce is gathered: along the smoothed guides, each render strand's samples blended
  // from its guides' (true), or along every render strand (false). Guides-only layouts gather along their
  // strands either way.
  bool bounceAtGuides = true;
};

struct ChunkRange {
  std::uint32_t firstStrand = 0;
  std::uint32_t strandCount = 0;
};

// Level of detail: the render strands are in LOD order (strand_topology.h), so a fraction of them is the
// prefix of the first `limit` strands. How many strands of `range` lie in that prefix.
inline std::uint32_t strandsWithin(const ChunkRange& range, std::uint32_t limit) {
  return limit <= range.firstStrand ? 0u : std::min(range.strandCount, limit - range.firstStrand);
}
inline constexpr std::uint32_t kAllStrands = ~0u;

// Counts and chunking: pure arithmetic, no device.
struct StrandLayout {
  std::uint32_t guideCount = 0;
  std::uint32_t particlesPerGuide = 0;  // P
  std::uint32_t verticesPerStrand = 0;  // Q
  std::uint32_t triangleCount = 0;
  std::uint32_t strandCount = 0;        // S (guides only: G)
  std::uint32_t bounceSamples = 0;      // the skin bounce's samples per strand: min(StrandOptions's, Q)
  bool bounceAtGuides = false;          // StrandOptions's, and not guides only
  bool guidesOnly = false;
  std::vector<ChunkRange> chunks;

  std::uint64_t strandVertexCount() const { return std::uint64_t(strandCount) * verticesPerStrand; }
};

// Throws hp::Error naming verticesPerStrand unless particlesPerGuide <= Q <= 256.
void validateVerticesPerStrand(std::uint32_t verticesPerStrand, std::uint32_t particlesPerGuide);
// Throws hp::Error "<field> must be in [2, 256], got N" unless the skin bounce's points per strand are there.
void validateBounceSamples(std::uint32_t bounceSamples, const char* field);

// Throws hp::Error naming the buffer and maxStorageBufferRange when a buffer that cannot be chunked
// would exceed it (or one strand alone would).
StrandLayout planStrandLayout(std::uint32_t guideCount, std::uint32_t particlesPerGuide,
                              std::uint32_t triangleCount, std::uint32_t strandCount, const StrandOptions& options,
                              VkDeviceSize maxStorageBufferRange);

// Chunking keeps every descriptor range legal; the total must still fit the device. Throws hp::Error
// naming the strand count and the heap when the strand buffers would exceed heapBytes.
void checkStrandMemory(const StrandLayout& layout, VkDeviceSize heapBytes);

struct StrandChunk {
  ChunkRange range;
  vk::Buffer bindings;    // StrandBindingGpu[count] (guides only: a 16-byte placeholder)
  vk::Buffer positions;   // vec4[count * Q]
  vk::Buffer tangents;    // vec4[count * Q]
  vk::Buffer attributes;  // StrandAttributes[count]
  vk::Buffer previous;    // vec4[count * Q]: the positions of the frame before (StrandOptions::previousPositions;
                          // empty otherwise)
  vk::Buffer bounce;      // uvec2[count * bounceSamples]: the skin's bounce along each strand (half floats)
};

class StrandBuffers {
 public:
  StrandBuffers(const vk::Context& ctx, std::uint32_t guideCount, std::uint32_t particlesPerGuide,
                const InterpolationTopology& topology, const StrandOptions& options = {});

  const StrandLayout& layout() const { return layout_; }
  const vk::Buffer& guidePositions() const { return guidePositions_; }  // vec4[G * Q]
  const vk::Buffer& guideTangents() const { return guideTangents_; }    // vec4[G * Q]
  const vk::Buffer& triangles() const { return triangles_; }            // uvec4[T] (guides only: placeholder)
  // uvec2[G * bounceSamples]: the skin's bounce along the smoothed guides (render/StrandBouncePass blends
  // the render strands' samples from them); a 16-byte placeholder unless StrandLayout::bounceAtGuides.
  const vk::Buffer& guideBounce() const { return guideBounce_; }
  std::span<const StrandChunk> chunks() const { return chunks_; }
  bool keepsPrevious() const { return keepsPrevious_; }
  // With previousPositions: copies the positions into `previous` (vkCmdCopyBuffer per chunk). The caller
  // records it before this frame's interpolate (the last frame's positions become the previous ones), or on
  // the buffers' first frame after it (no motion yet), with the barriers: the positions' last write before
  // TransferSrc, the previous positions' last read before TransferDst.
  void recordKeepPrevious(const vk::Context& ctx, VkCommandBuffer cmd) const;

 private:
  void uploadTopology(const vk::Context& ctx, const InterpolationTopology& topology);

  StrandLayout layout_;
  vk::Buffer guidePositions_;
  vk::Buffer guideBounce_;
  vk::Buffer guideTangents_;
  vk::Buffer triangles_;
  std::vector<StrandChunk> chunks_;
  bool keepsPrevious_ = false;
};

// Host copies, for tests and tools outside the frame loop. `before` is the buffers' last GPU use.
struct StrandData {
  std::vector<glm::vec4> positions;  // S * Q (all chunks, in strand order)
  std::vector<glm::vec4> tangents;
  std::vector<gpu::StrandAttributes> attributes;  // S
};
StrandData readRenderStrands(const vk::Context& ctx, const StrandBuffers& buffers, vk::BufferUse before);
StrandData readSmoothedGuides(const vk::Context& ctx, const StrandBuffers& buffers, vk::BufferUse before);
}  // namespace hp::compute
