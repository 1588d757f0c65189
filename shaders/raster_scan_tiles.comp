#version 460
// Compute rasterizer, one invocation per tile: walks the tile's depth bins near to far, keeps at most
// `tileBudget` entries (the farthest bins lose theirs first, counted in RasterState.entries.y) and, where the
// frame's budgeted entries (raster_budget_tiles.comp) exceed the lists' capacity, that share of them scaled by
// capacity / budgeted (again the farthest bins first, counted in entries.z), writes each key's offset within
// the tile and re-arms its counter as the scatter cursor; then an exclusive scan of the kept totals within
// each block of RASTER_SCAN_SIZE tiles (block totals to `blocks`).
#include "shared/raster.h"
#include "common.glsl"

layout(local_size_x = RASTER_SCAN_SIZE) in;
layout(std430, binding = RASTER_BINDING_STATE) buffer State { RasterState state; };
layout(std430, binding = RASTER_BINDING_COUNTS) buffer Counts { uint counts[]; };
layout(std430, binding = RASTER_BINDING_KEYS) writeonly buffer Keys { uvec2 keys[]; };
layout(std430, binding = RASTER_BINDING_TILES) writeonly buffer Tiles { uvec2 tiles[]; };
layout(std430, binding = RASTER_BINDING_BLOCKS) writeonly buffer Blocks { uint blocks[]; };
layout(std430, binding = RASTER_BINDING_PARAMS) readonly buffer Params { RasterParams params; };

// Hillis-Steele with ping-pong rows, one barrier per round (as the prefix-sum self test).
shared uint rows[2][RASTER_SCAN_SIZE];

void main() {
  uint t = hpThreadId(RASTER_SCAN_SIZE);
  uint lane = gl_LocalInvocationID.x;
  uint kept = 0u;
  if (t < params.tilesX * params.tilesY) {
    uint requested = 0u;
    for (uint b = 0u; b < RASTER_DEPTH_BINS; ++b) requested += counts[t * RASTER_DEPTH_BINS + b];
    uint budgeted = min(requested, params.tileBudget);
    // Over the capacity: each asking tile keeps its nearest entry and a share of the rest (a sparse tile's only
    // hair, often a silhouette's, is not cut).
    uint limit = rasterTileShare(budgeted, state.budgeted.x, state.budgeted.y, params.capacity);
    for (uint b = 0u; b < RASTER_DEPTH_BINS; ++b) {
      uint key = t * RASTER_DEPTH_BINS + b;
      uint k = min(counts[key], limit - kept);
      keys[key] = uvec2(kept, k);
      counts[key] = 0u;
      kept += k;
    }
    if (requested > budgeted) atomicAdd(state.entries.y, requested - budgeted);
    if (budgeted > kept) atomicAdd(state.entries.z, budgeted - kept);
  }
  rows[0][lane] = kept;
  barrier();
  uint src = 0u;
  for (uint offset = 1u; offset < RASTER_SCAN_SIZE; offset <<= 1u) {
    uint value = rows[src][lane];
    if (lane >= offset) value += rows[src][lane - offset];
    rows[1u - src][lane] = value;
    src = 1u - src;
    barrier();
  }
  if (t < params.tilesX * params.tilesY) tiles[t] = uvec2(rows[src][lane] - kept, kept);
  if (lane == RASTER_SCAN_SIZE - 1u) blocks[t / RASTER_SCAN_SIZE] = rows[src][lane];
}
