#version 460
// Compute rasterizer, one invocation per tile, before raster_scan_tiles.comp: the entries the tile asks for and
// those within its tileBudget (nearest bins first) summed over the frame, into RasterState.entries.x and
// budgeted.x, and the tiles that ask for any into budgeted.y. The scan then knows before it keeps anything whether the lists can hold the budgeted total, and
// where they cannot, every tile gives up its farthest bins in proportion (not the last tiles their all).
#include "shared/raster.h"
#include "common.glsl"

layout(local_size_x = RASTER_SCAN_SIZE) in;
layout(std430, binding = RASTER_BINDING_STATE) buffer State { RasterState state; };
layout(std430, binding = RASTER_BINDING_COUNTS) readonly buffer Counts { uint counts[]; };
layout(std430, binding = RASTER_BINDING_PARAMS) readonly buffer Params { RasterParams params; };

void main() {
  uint t = hpThreadId(RASTER_SCAN_SIZE);
  if (t >= params.tilesX * params.tilesY) return;
  uint requested = 0u;
  for (uint b = 0u; b < RASTER_DEPTH_BINS; ++b) requested += counts[t * RASTER_DEPTH_BINS + b];
  if (requested == 0u) return;
  atomicAdd(state.entries.x, requested);
  atomicAdd(state.budgeted.x, min(requested, params.tileBudget));
  atomicAdd(state.budgeted.y, 1u);
}
