// Compute rasterizer, one invocation per 8x8 tile: the farthest head depth over the tile's pixels and
// samples (1 where no head was drawn). The bin step drops a segment from a tile when its nearer end is at
// or behind it: every fragment it could give there is hidden by the head (raster_fine.glsl's depth test),
// so the lists lose only entries that would composite nothing.
#include "shared/raster.h"
#include "common.glsl"

layout(local_size_x = RASTER_WORKGROUP_SIZE) in;
layout(std430, binding = RASTER_BINDING_PARAMS) readonly buffer Params { RasterParams params; };
layout(std430, binding = RASTER_BINDING_TILE_DEPTH) writeonly buffer TileDepth { float tileDepth[]; };
#include "raster_head_depth.glsl"

void main() {
  uint tile = hpThreadId(RASTER_WORKGROUP_SIZE);
  if (tile >= params.tilesX * params.tilesY) return;
  uvec2 origin = uvec2(tile % params.tilesX, tile / params.tilesX) * RASTER_TILE_SIZE;
  uvec2 last = min(origin + RASTER_TILE_SIZE, uvec2(params.width, params.height)) - 1u;
  float farthest = 0.0;
  for (uint y = origin.y; y <= last.y; ++y)
    for (uint x = origin.x; x <= last.x; ++x)
      for (uint s = 0u; s < headSamples(); ++s) farthest = max(farthest, headDepthAt(ivec2(x, y), s));
  tileDepth[tile] = farthest;
}
