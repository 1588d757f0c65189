#version 460
// Compute rasterizer, one workgroup: exclusive scan of the block totals of raster_scan_tiles in place
// (each invocation sums a run of blocks, a shared scan of the runs, then each run is written out), and
// the list statistics: entries kept within the capacity (raster_scan_tiles already cut a full list's to fit;
// anything past it would be dropped by the scatter and is counted with the cut); and the
// indirect shade dispatch of every chunk from its listed vertices (2D past maxGroupsX, as dispatch()).
#include "shared/raster.h"

layout(local_size_x = RASTER_SCAN_SIZE) in;
layout(std430, binding = RASTER_BINDING_STATE) buffer State { RasterState state; };
layout(std430, binding = RASTER_BINDING_BLOCKS) buffer Blocks { uint blocks[]; };
layout(std430, binding = RASTER_BINDING_PARAMS) readonly buffer Params { RasterParams params; };
layout(std430, binding = RASTER_BINDING_SHADE_ARGS) buffer ShadeArgs { uvec4 shadeArgs[]; };

shared uint rows[2][RASTER_SCAN_SIZE];

void main() {
  uint lane = gl_LocalInvocationID.x;
  uint blockCount = (params.tilesX * params.tilesY + RASTER_SCAN_SIZE - 1u) / RASTER_SCAN_SIZE;
  uint run = (blockCount + RASTER_SCAN_SIZE - 1u) / RASTER_SCAN_SIZE;
  uint first = min(lane * run, blockCount);
  uint last = min(first + run, blockCount);
  uint sum = 0u;
  for (uint i = first; i < last; ++i) sum += blocks[i];
  rows[0][lane] = sum;
  barrier();
  uint src = 0u;
  for (uint offset = 1u; offset < RASTER_SCAN_SIZE; offset <<= 1u) {
    uint value = rows[src][lane];
    if (lane >= offset) value += rows[src][lane - offset];
    rows[1u - src][lane] = value;
    src = 1u - src;
    barrier();
  }
  uint offset = rows[src][lane] - sum;
  for (uint i = first; i < last; ++i) {
    uint total = blocks[i];
    blocks[i] = offset;
    offset += total;
  }
  if (lane == RASTER_SCAN_SIZE - 1u) {
    uint total = rows[src][lane];
    state.entries.z += total > params.capacity ? total - params.capacity : 0u;  // past the scan's share (none)
    state.entries.w = min(total, params.capacity);
  }
  for (uint c = lane; c < params.chunkCount; c += RASTER_SCAN_SIZE) {
    uint groups = (shadeArgs[c].w + RASTER_WORKGROUP_SIZE - 1u) / RASTER_WORKGROUP_SIZE;
    uint x = min(groups, params.maxGroupsX);
    shadeArgs[c].xyz = uvec3(x, x == 0u ? 0u : (groups + x - 1u) / x, 1u);
  }
}
