#version 460
// Compute rasterizer, per segment of a chunk: the (tile, depth bin) keys its footprint touches.
// RASTER_MODE_COUNT counts them; RASTER_MODE_SCATTER (after the tile scan) writes the segment's global
// id into each tile's list, keeping the first `keys.y` of each key (the tile budget, nearest bins first).
// The mode is a specialization constant (one pipeline each), not a uniform value lavapipe would inline.
#include "shared/raster.h"
#include "common.glsl"

layout(local_size_x = RASTER_WORKGROUP_SIZE) in;
layout(constant_id = 0) const uint MODE = RASTER_MODE_COUNT;
layout(std430, binding = RASTER_BINDING_SCREEN) readonly buffer Screen { vec4 screen[]; };
layout(std430, binding = RASTER_BINDING_STATE) readonly buffer State { RasterState state; };
layout(std430, binding = RASTER_BINDING_COUNTS) buffer Counts { uint counts[]; };
layout(std430, binding = RASTER_BINDING_KEYS) readonly buffer Keys { uvec2 keys[]; };
layout(std430, binding = RASTER_BINDING_TILES) readonly buffer Tiles { uvec2 tiles[]; };
layout(std430, binding = RASTER_BINDING_BLOCKS) readonly buffer Blocks { uint blocks[]; };
layout(std430, binding = RASTER_BINDING_LIST) writeonly buffer List { uint list[]; };
layout(std430, binding = RASTER_BINDING_TILE_DEPTH) readonly buffer TileDepth { float tileDepth[]; };
layout(std430, binding = RASTER_BINDING_PARAMS) readonly buffer Params { RasterParams params; };
#include "raster.glsl"

void main() {
  uint segments = params.verticesPerStrand - 1u;
  uint i = hpThreadId(RASTER_WORKGROUP_SIZE);
  if (i >= params.strandCount * segments) return;
  uint strand = params.firstStrand + i / segments;
  uint k = i % segments;
  Footprint f = segmentFootprint(strand, k);
  if (!f.visible) return;
  uint id = (strand * params.verticesPerStrand + k) | (k + 1u == segments ? RASTER_LAST_SEGMENT : 0u);
  for (uint ty = f.tileMin.y; ty <= f.tileMax.y; ++ty)
    for (uint tx = f.tileMin.x; tx <= f.tileMax.x; ++tx) {
      if (!footprintTouches(f, uvec2(tx, ty))) continue;
      uint tile = ty * params.tilesX + tx;
      uint key = tile * RASTER_DEPTH_BINS + f.bin;
      uint slot = atomicAdd(counts[key], 1u);
      if (MODE != RASTER_MODE_SCATTER || slot >= keys[key].y) continue;
      uint index = tileListStart(tile) + keys[key].x + slot;
      if (index < params.capacity) list[index] = id;
    }
}
