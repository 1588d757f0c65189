#version 460
// Compute rasterizer, per segment of a chunk: the (tile, depth bin) keys its footprint touches.
// RASTER_MODE_COUNT counts them and lists the ends of every segment that touches a tile for shading; RASTER_MODE_SCATTER (after the tile scan) writes the segment's global
// id and the blocks of the tile it may cover into each tile's list, keeping the first `keys.y` of each key (the tile budget, nearest bins first).
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
layout(std430, binding = RASTER_BINDING_LIST) writeonly buffer List { uvec2 list[]; };
layout(std430, binding = RASTER_BINDING_TILE_DEPTH) readonly buffer TileDepth { float tileDepth[]; };
layout(std430, binding = RASTER_BINDING_PARAMS) readonly buffer Params { RasterParams params; };
layout(std430, binding = RASTER_BINDING_SHADE_FLAGS) buffer ShadeFlags { uint shadeFlags[]; };
layout(std430, binding = RASTER_BINDING_SHADE_LIST) writeonly buffer ShadeList { uint shadeList[]; };
layout(std430, binding = RASTER_BINDING_SHADE_ARGS) buffer ShadeArgs { uvec4 shadeArgs[]; };
#include "raster.glsl"

// Count mode: the vertices this workgroup lists for raster_shade.comp, and where they go in the chunk's
// shade list. One global atomic per workgroup instead of one per listed vertex on a single counter (which
// serialises on GPUs), and a workgroup's vertices land next to each other, as the shade pass reads them.
shared uint groupListed;
shared uint groupBase;

// Bins segment i of the chunk (its key counts, and in scatter mode its list entries); returns whether
// some tile lists it.
bool binSegment(uint i, uint v, uint k, uint segments) {
  Footprint f = segmentFootprint(v);
  if (!f.visible) return false;
  uint id = v | (k + 1u == segments ? RASTER_LAST_SEGMENT : 0u);
  bool listed = false;
  for (uint ty = f.tileMin.y; ty <= f.tileMax.y; ++ty)
    for (uint tx = f.tileMin.x; tx <= f.tileMax.x; ++tx) {
      vec2 span;
      if (!tileTouched(f, uvec2(tx, ty), span)) continue;
      listed = true;
      uint tile = ty * params.tilesX + tx;
      uint key = tile * RASTER_DEPTH_BINS + f.bin;
      uint slot = atomicAdd(counts[key], 1u);
      if (MODE != RASTER_MODE_SCATTER || slot >= keys[key].y) continue;
      uint index = tileListStart(tile) + keys[key].x + slot;
      if (index < params.capacity) list[index] = uvec2(id, footprintBlocks(f, uvec2(tx, ty), span));
    }
  return listed;
}

// Whether this invocation is the one that lists vertex v for shading (the segments on either side of it
// may both ask). A flag only goes from 0 to 1 in a frame: one already read as set needs no atomic.
bool claimForShading(uint v) { return shadeFlags[v] == 0u && atomicExchange(shadeFlags[v], 1u) == 0u; }

void main() {
  uint segments = params.verticesPerStrand - 1u;
  uint i = hpThreadId(RASTER_WORKGROUP_SIZE);
  bool inRange = i < params.strandCount * segments;
  uint k = i % segments;
  uint v = params.firstVertex + (i / segments) * params.verticesPerStrand + k;
  if (MODE != RASTER_MODE_COUNT) {  // a specialization constant: uniform, no barrier below is skipped unevenly
    if (inRange) binSegment(i, v, k, segments);
    return;
  }
  if (gl_LocalInvocationIndex == 0u) groupListed = 0u;
  barrier();
  // Count mode: both ends of a segment in some tile's list get shaded; the others never composite.
  bool listed = inRange && binSegment(i, v, k, segments);
  bool first = listed && claimForShading(v);
  bool second = listed && claimForShading(v + 1u);
  uint mine = uint(first) + uint(second);
  uint local = mine > 0u ? atomicAdd(groupListed, mine) : 0u;
  barrier();
  if (gl_LocalInvocationIndex == 0u && groupListed > 0u)
    groupBase = atomicAdd(shadeArgs[params.chunkIndex].w, groupListed);
  barrier();
  uint slot = params.firstVertex + groupBase + local;
  if (first) shadeList[slot++] = v;
  if (second) shadeList[slot] = v + 1u;
}
