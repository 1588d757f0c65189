// Shared by GLSL and C++: the compute strand rasterizer (compute/raster/strand_raster_pass.h, shaders/raster_*.comp;
// docs/THEORY.md §7). One source of truth for bindings, tile and bin sizes, the per-frame state, the push
// constants and the coverage formula (plain arithmetic, compiled for both languages and tested on the CPU).
//
// Buffers (std430; V = S*Q render vertices, E = S*(Q-1) segments, K = tiles * RASTER_DEPTH_BINS keys):
//   screen     vec4[V]   x, y pixel position (origin top left, pixel centres at +0.5), z = NDC depth,
//                        w = projected width in pixels (< 0: the vertex is behind the camera)
//   colors     uvec2[V]  packHalf2x16(r, g), packHalf2x16(b, view depth): the shaded radiance
//   state      RasterState
//   counts     uint[K]   segments per (tile, depth bin); the scan turns them into scatter cursors
//   keys       uvec2[K]  x = offset of the key within its tile's list, y = entries kept (tile budget)
//   tiles      uvec2[T]  x = offset of the tile's list within its scan block, y = entries kept
//   blocks     uint[ceil(T / RASTER_SCAN_SIZE)]  offset of each scan block in the list
//   tileDepth  float[T]  the farthest head depth (NDC z) over each tile's pixels, 1 where no head
//   shadeFlags uint[V]   1 once the vertex is in the shade list (cleared every frame)
//   shadeList  uint[V]   per chunk, from its firstVertex: the global vertices of segments that touch a tile, or
//                        of their pairs' ends where a middle vertex takes its neighbours' mean (only they are
//                        shaded: off-screen and head-hidden segments are not)
//   shadeArgs  uvec4[chunks]  the indirect shade dispatch of each chunk (x, y, z groups) and w = its listed count
//   list       uvec2[capacity] per tile, depth bins near to far: x = the global index of the segment's first
//                              vertex (strand * Q + k), | RASTER_LAST_SEGMENT for the strand's last segment
//                              (no integer division in the fine loop: CPU SIMD has none); y = the blocks of
//                              the tile it may cover (bits 0-7, bit b: block b, RASTER_BLOCK_*), which the
//                              fine loop skips by, | RASTER_COLOR_A_MID or RASTER_COLOR_B_MID where an end's
//                              colour is the mean of its neighbours' (RasterParams::shadingSpacing)
// Key of tile t and bin b: t * RASTER_DEPTH_BINS + b. Tile t covers pixels [tx*8, tx*8+8) x [ty*8, ty*8+8).
#ifndef HP_SHARED_RASTER_H
#define HP_SHARED_RASTER_H
#include "common.h"

#ifdef __cplusplus
#include <cmath>

#include <glm/glm.hpp>
#define HP_RASTER_FN inline
namespace hp::gpu {  // the GLSL built-ins, as shared/marschner.h declares them
using glm::clamp;
using glm::max;
using glm::min;
using std::abs;
using std::ceil;
using std::floor;
}  // namespace hp::gpu
#else
#define HP_RASTER_FN
#endif

HP_BEGIN
HP_CONST(uint, RASTER_TILE_SIZE, 8)             // pixels per tile side; one fine workgroup per tile
HP_CONST(uint, RASTER_FINE_SIZE, 64)            // = RASTER_TILE_SIZE^2 invocations, one per pixel
// A tile's 8 blocks of RASTER_BLOCK_WIDTH x RASTER_BLOCK_HEIGHT pixels, each 8 consecutive invocations of the
// fine pass (one SIMD vector on lavapipe): block b = columns 2 (b % 4) .. + 1, rows 4 (b / 4) .. + 3. Tall
// blocks suit hair that falls (docs/DESIGN.md "Block masks in the lists": the shapes measured).
HP_CONST(uint, RASTER_BLOCK_WIDTH, 2)
HP_CONST(uint, RASTER_BLOCK_HEIGHT, 4)
HP_CONST(uint, RASTER_DEPTH_BINS, 32)           // depth bins per tile across the hair's view-depth range
HP_CONST(uint, RASTER_WORKGROUP_SIZE, 64)       // vertex and segment passes
HP_CONST(uint, RASTER_SCAN_SIZE, 256)           // tiles per scan block; the block scan is one workgroup
HP_CONST(float, RASTER_OPAQUE_T, 1.0f / 255.0f) // a pixel stops compositing below this transmittance
HP_CONST(uint, RASTER_MASK_SIDE, 8)             // samples per side of a pixel's overlap mask (8 x 8: 2 words)
HP_CONST(uint, RASTER_LAST_SEGMENT, 0x80000000u) // list entry flag: the segment ends at the strand's tip
// Shading at half the rate along a strand (RasterParams::shadingSpacing; docs/DESIGN.md "Shading spacing"):
// segments 2j and 2j + 1 of a strand share vertex 2j + 1; where vertices 2j and 2j + 2 lie within the spacing
// of each other on screen and the pair turns little (raster_bin.comp pairInterpolated), only they are shaded and vertex 2j + 1 takes their mean radiance. The list entry
// (y) says which end of a segment is such a mean: its first (odd k: of vertices v - 1 and v + 1) or its second
// (even k: of v and v + 2).
HP_CONST(uint, RASTER_COLOR_A_MID, 0x100u)
HP_CONST(uint, RASTER_COLOR_B_MID, 0x200u)

// Set 0 of every raster pipeline; 0-10 are the strand shading bindings (shared/render.h), same numbers.
HP_CONST(uint, RASTER_BINDING_SCREEN, 11)
HP_CONST(uint, RASTER_BINDING_COLORS, 12)
HP_CONST(uint, RASTER_BINDING_STATE, 13)
HP_CONST(uint, RASTER_BINDING_COUNTS, 14)
HP_CONST(uint, RASTER_BINDING_KEYS, 15)
HP_CONST(uint, RASTER_BINDING_TILES, 16)
HP_CONST(uint, RASTER_BINDING_BLOCKS, 17)
HP_CONST(uint, RASTER_BINDING_LIST, 18)
HP_CONST(uint, RASTER_BINDING_DEPTH, 19)   // sampler2D(MS): the head's depth, 1 = nothing (raster_head_depth.glsl)
HP_CONST(uint, RASTER_BINDING_OUTPUT, 20)  // storage image rgba16f: premultiplied hair radiance, a = 1 - T
HP_CONST(uint, RASTER_BINDING_PARAMS, 21)  // RasterParams of the set's chunk (read-only storage buffer)
HP_CONST(uint, RASTER_BINDING_TILE_DEPTH, 22)  // float[tiles]: the farthest head depth in each tile
HP_CONST(uint, RASTER_BINDING_SHADE_FLAGS, 23) // uint[V]: 1 once a vertex is listed for shading
HP_CONST(uint, RASTER_BINDING_SHADE_LIST, 24)  // uint[V]: per chunk from its firstVertex, the vertices to shade
HP_CONST(uint, RASTER_BINDING_SHADE_ARGS, 25)  // uvec4[chunks]: x, y, z = the shade dispatch, w = listed
// 26, 27: shared/render.h's bounce map (not bound here); 33 its samples along the strands. A multisampled head depth splits a pixel's samples in two layers:
// the far layer (OUTPUT) is the hair in front of the farthest head sample; the samples of NEAR_MASK, where
// the head hides hair the far samples see, take the near layer: the hair in front of every head sample.
HP_CONST(uint, RASTER_BINDING_OUTPUT_NEAR, 28)  // storage image rgba16f: the near layer, as OUTPUT
HP_CONST(uint, RASTER_BINDING_NEAR_MASK, 29)    // storage image r32ui: the samples that take the near layer
// Motion vectors (RendererSettings::motionVectors; the passes' specialization constant 0 turns them on):
// the project pass writes each vertex's screen motion, current unjittered pixel position minus its previous
// one (previous positions through RenderFrame::previousViewProj), and the fine raster composites it like the
// radiance: the hair's coverage-weighted motion per pixel, in pixels (x right, y down), 0 without hair.
HP_CONST(uint, RASTER_BINDING_PREVIOUS, 30)     // vec4[chunk strands * Q]: the render strands' previous positions
HP_CONST(uint, RASTER_BINDING_MOTION, 31)       // uint[V]: packHalf2x16 of each vertex's screen motion
HP_CONST(uint, RASTER_BINDING_MOTION_OUTPUT, 32)  // storage image rg16f: the pixel's hair motion
// The direct fine walk (CPU devices) reads the list, the screen vertices and their colours as uniform texel
// buffers over the same buffers (R32G32_UINT, R32G32B32A32_SFLOAT, R32G32_UINT): lavapipe fetches a texel
// for all 8 lanes at once where it loads a storage buffer lane by lane (docs/DESIGN.md, driver notes).
HP_CONST(uint, RASTER_BINDING_LIST_TEXELS, 37)
HP_CONST(uint, RASTER_BINDING_SCREEN_TEXELS, 38)
HP_CONST(uint, RASTER_BINDING_COLOR_TEXELS, 39)
HP_CONST(uint, RASTER_MAX_HEAD_SAMPLES, 16)     // head depth samples per pixel the raster reads

// The composite pass (composite.frag) samples the output images; its push constant picks the layer.
HP_CONST(uint, COMPOSITE_BINDING_HAIR, 0)
HP_CONST(uint, COMPOSITE_BINDING_NEAR, 1)
HP_CONST(uint, COMPOSITE_BINDING_NEAR_MASK, 2)
HP_CONST(uint, COMPOSITE_EVERY_SAMPLE, 0)  // the far layer into every sample (single-sample head depth)
HP_CONST(uint, COMPOSITE_FAR_SAMPLES, 1)   // the far layer into the samples outside the near mask
HP_CONST(uint, COMPOSITE_NEAR_SAMPLES, 2)  // the near layer into the near mask's samples
// The velocity write (composite_velocity.glsl) also samples the motion image.
HP_CONST(uint, COMPOSITE_BINDING_MOTION, 3)

// raster_bin.comp's specialization constant 0.
HP_CONST(uint, RASTER_MODE_COUNT, 1)    // per segment: count into (tile, bin) keys
HP_CONST(uint, RASTER_MODE_SCATTER, 2)  // per segment: write ids into the tile lists

// composite_velocity.glsl's push constants (hairpipe::VelocityOutput): motion * scale + offset where the hair's
// coverage exceeds minCoverage; samples: the attachments' sample count (above 1 the coverage is the mean over
// the pixel's samples of the two layers the composite draws).
struct CompositeVelocityPush {
  vec2 scale;
  vec2 offset;
  float minCoverage;
  uint samples;
};

// Written by the passes each frame; the frame recorder re-arms it with vkCmdUpdateBuffer.
struct RasterState {
  uvec4 depthBits;  // x, y = orderedFromFloat of the min / max view depth of the visible vertices
  uvec4 entries;    // x = (segment, tile) entries requested, y = dropped by the tile budget,
                    // z = dropped for the list capacity, w = entries kept
  uvec4 budgeted;   // x = entries within the tile budgets, which the capacity may cut; y = tiles with any
                    // (raster_budget_tiles.comp)
};

// Per chunk, fixed for the pass's life: a read-only storage buffer, not push constants (lavapipe in
// Mesa 22.3 recompiles a shader on every dispatch whose push constants steer its loops; docs/DESIGN.md).
struct RasterParams {
  uint firstStrand;   // global index of the chunk's first strand
  uint strandCount;   // strands in the chunk
  uint firstVertex;   // global index of the chunk's first vertex in the screen, colour and shade buffers
  uint tilesX;
  uint tilesY;
  uint tileBudget;    // entries kept per tile (the nearest bins first)
  uint capacity;      // list entries
  uint width;         // output pixels
  uint height;
  uint verticesPerStrand;  // Q
  uint chunkIndex;    // this chunk's shadeArgs entry
  uint chunkCount;    // chunks of every source together
  uint maxGroupsX;    // the device's maxComputeWorkGroupCount[0] (the shade dispatch goes 2D past it)
  float shadingSpacing;  // pixels: a strand's odd vertices take their neighbours' mean within it (0: none)
  uint reversedDepth;  // 1: the head's depth and the view's projection are reversed-Z (near 1): read as 1 - z
  uint pad2;
};
HP_END

// The entries a tile keeps of its `budgeted` (those within its tile budget) when the frame's budgeted `total`,
// over `tilesAsking` tiles, may exceed the lists' `capacity` (raster_scan_tiles.comp): all of them where the
// total fits; else its nearest entry and a share of the capacity left after one per tile. Summed over the
// tiles: at most tilesAsking + (capacity - tilesAsking) = capacity; the factor absorbs the float ratio's
// rounding (GLSL's division may be off by 2.5 ulp). The capacity holds 16 entries per tile, so it exceeds
// tilesAsking.
HP_BEGIN
HP_RASTER_FN uint rasterTileShare(uint budgeted, uint total, uint tilesAsking, uint capacity) {
  if (total <= capacity || budgeted == 0u) return budgeted;
  return min(budgeted, 1u + uint(float(budgeted) * (float(capacity - tilesAsking) / float(total)) * 0.99999f));
}
HP_END

// Coverage of a pixel (unit square centred on its centre) by a straight band of width w (pixels) whose
// centre line passes at signed distance d (pixels) from the centre, with unit normal n: the exact area
// of the intersection. The square's projection onto n is the sum of two uniform variables of
// half-widths a = |n.x|/2 and b = |n.y|/2; its CDF is (R(x+a+b) - R(x+a-b) - R(x-a+b) + R(x-a-b)) / 4ab
// with R(x) = max(x, 0)^2 / 2 (linear when the band is axis-aligned), and the band covers
// CDF(d + w/2) - CDF(d - w/2). The 1D box estimate of docs/THEORY.md §7.1 is the axis-aligned case.
HP_BEGIN
HP_RASTER_FN float rasterRamp(float x) {
  float m = max(x, 0.0f);
  return 0.5f * m * m;
}

HP_RASTER_FN float rasterSquareCdf(float x, float a, float b) {
  float hi = max(a, b);
  float lo = min(a, b);
  if (lo < 1.0e-3f) return clamp((x + hi) / (2.0f * hi), 0.0f, 1.0f);
  float s = rasterRamp(x + hi + lo) - rasterRamp(x + hi - lo) - rasterRamp(x - hi + lo) + rasterRamp(x - hi - lo);
  return clamp(s / (4.0f * hi * lo), 0.0f, 1.0f);
}

HP_RASTER_FN float rasterBandCoverage(float d, float w, float nx, float ny) {
  float a = 0.5f * abs(nx);
  float b = 0.5f * abs(ny);
  return max(rasterSquareCdf(d + 0.5f * w, a, b) - rasterSquareCdf(d - 0.5f * w, a, b), 0.0f);
}

// Which strands overlap in a pixel. Alpha compositing, T *= 1 - a, treats the strands in a pixel as
// independent; strands interpolated between the same guides lie in sheets and, seen edge-on, cover the
// same part of a pixel far more often (docs/SHADING.md "silhouette pixels"). So each fragment also marks
// the samples of an 8 x 8 grid in the pixel (sample (i, j) at ((i + 0.5) / 8 - 0.5, (j + 0.5) / 8 - 0.5)
// from the centre) that its band covers, and the share of it still visible is measured against the
// samples covered in front of it. The band's mask: row r in bits 8 (r % 4) .. + 7 of word r / 4, bit i of a
// row = sample (i, r) is inside. One reciprocal for the 8 rows (a division per row cost lavapipe's fine
// pass ~10%).
HP_RASTER_FN uvec2 rasterBandMask(float d, float w, float nx, float ny) {
  uvec2 mask = uvec2(0u);
  bool upright = abs(nx) < 1.0e-6f;  // the band runs along the rows: each row is all in or all out
  float invNx = upright ? 0.0f : 1.0f / nx;
  for (uint row = 0u; row < RASTER_MASK_SIDE; ++row) {
    float c = d + ((float(row) + 0.5f) / float(RASTER_MASK_SIDE) - 0.5f) * ny;  // at the row's centre
    uint bits;
    if (upright) {
      bits = abs(c) < 0.5f * w ? 0xFFu : 0u;
    } else {
      // |c + sx nx| < w / 2 for sx = (i + 0.5) / 8 - 0.5: i strictly between 8 lo + 3.5 and 8 hi + 3.5.
      float lo = (-0.5f * w - c) * invNx;
      float hi = (0.5f * w - c) * invNx;
      float first = min(lo, hi) * float(RASTER_MASK_SIDE) + 0.5f * float(RASTER_MASK_SIDE) - 0.5f;
      float last = max(lo, hi) * float(RASTER_MASK_SIDE) + 0.5f * float(RASTER_MASK_SIDE) - 0.5f;
      float i0 = max(floor(first) + 1.0f, 0.0f);
      float i1 = min(ceil(last) - 1.0f, float(RASTER_MASK_SIDE - 1u));
      bits = i0 > i1 ? 0u : ((2u << uint(i1)) - 1u) & ~((1u << uint(i0)) - 1u);
    }
    mask[row >> 2u] |= bits << ((row & 3u) * 8u);
  }
  return mask;
}

// The share of a fragment still visible: 1 - U for a strand independent of those in front (U = the
// pixel's alpha so far), scaled by how much more (or less) its samples overlap the covered ones than
// independence predicts: rho = (overlap / samples) / (covered / all samples). Coincident strands get
// 0, disjoint ones 1, and crossing ones (a band across the pixel meets every row or column alike) stay
// at 1 - U. Without samples on either side: independence.
HP_RASTER_FN float rasterVisibleShare(uint bandSamples, uint coveredSamples, uint overlapSamples, float alpha) {
  if (bandSamples == 0u || coveredSamples == 0u) return 1.0f - alpha;
  float rho = float(overlapSamples) * float(RASTER_MASK_SIDE * RASTER_MASK_SIDE) /
              (float(bandSamples) * float(coveredSamples));
  return 1.0f - min(alpha * rho, 1.0f);
}
HP_END

#ifdef __cplusplus
static_assert(sizeof(hp::gpu::RasterState) == 48);
static_assert(sizeof(hp::gpu::RasterParams) == 64);
static_assert(hp::gpu::RASTER_FINE_SIZE == hp::gpu::RASTER_TILE_SIZE * hp::gpu::RASTER_TILE_SIZE);
#endif
#ifdef __cplusplus
// raster.glsl's footprintBlocks works out a tile's blocks as 2 bands of rows of 4 blocks each.
static_assert(hp::gpu::RASTER_TILE_SIZE / hp::gpu::RASTER_BLOCK_HEIGHT == 2 && hp::gpu::RASTER_TILE_SIZE / hp::gpu::RASTER_BLOCK_WIDTH == 4);
static_assert(hp::gpu::RASTER_BLOCK_WIDTH * hp::gpu::RASTER_BLOCK_HEIGHT * 8 == hp::gpu::RASTER_FINE_SIZE);
#endif
#endif
