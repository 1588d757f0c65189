// GLSL only: what the compute rasterizer's segment passes share (compute/raster/strand_raster_pass.h,
// shared/raster.h). The includer declares `params` (RasterParams), `screen` (vec4[]) and `state` (RasterState).
#ifndef HP_RASTER_GLSL
#define HP_RASTER_GLSL

// The screen-space footprint of the segment from global vertex v to v + 1: the tiles it may touch and its
// depth bin.
struct Footprint {
  bool visible;
  uvec2 tileMin;
  uvec2 tileMax;
  uint bin;
  vec4 a;  // screen records of the two ends (shared/raster.h)
  vec4 b;
};

Footprint segmentFootprint(uint v) {
  Footprint f;
  f.a = screen[v];
  f.b = screen[v + 1u];
  f.visible = false;
  if (f.a.w < 0.0 || f.b.w < 0.0) return f;  // an end behind the camera
  // Reach past the centre line: half the width plus a pixel's half-diagonal.
  float reach = 0.5 * max(f.a.w, f.b.w) + 0.75;
  vec2 lo = max(min(f.a.xy, f.b.xy) - reach, vec2(0.0));
  vec2 hi = min(max(f.a.xy, f.b.xy) + reach, vec2(params.width, params.height) - 1e-3);
  if (any(greaterThan(lo, hi))) return f;
  f.visible = true;
  f.tileMin = uvec2(lo) / RASTER_TILE_SIZE;
  f.tileMax = uvec2(hi) / RASTER_TILE_SIZE;
  float zMin = uintBitsToFloat(state.depthBits.x);
  float zMax = uintBitsToFloat(state.depthBits.y);
  float z = min(f.a.z, f.b.z);
  float bin = (z - zMin) / max(zMax - zMin, 1e-20) * float(RASTER_DEPTH_BINS);
  f.bin = uint(clamp(bin, 0.0, float(RASTER_DEPTH_BINS - 1u)));
  return f;
}

// The rows of a tile that can hold a pixel the segment covers and the head does not hide: bit r set when
// row r may (0: the segment stays out of the tile's list). raster_fine.glsl composites a pixel centre c
// only when its foot point s on the segment (t in [0, 1]) is within half the width + 0.75 px (`reach`)
// of c; with c in the tile's columns, s lies on the part of the segment within `reach` of those columns in
// x, and c within `reach` of that part's y range: one clip gives a conservative run of rows (the same in
// the count and scatter modes). A segment whose nearer end is at or behind the farthest head depth in the
// tile (raster_tile_depth.glsl) is out: every fragment it could give there fails raster_fine's depth test.
uint footprintRows(Footprint f, uvec2 tile) {
  if (min(f.a.z, f.b.z) >= tileDepth[tile.y * params.tilesX + tile.x]) return 0u;
  float reach = 0.5 * max(f.a.w, f.b.w) + 0.75 + 1e-3;
  vec2 ab = f.b.xy - f.a.xy;
  vec2 origin = vec2(tile * RASTER_TILE_SIZE) + 0.5;  // the tile's first pixel centre
  float x0 = origin.x - reach;
  float x1 = origin.x + float(RASTER_TILE_SIZE - 1u) + reach;
  float t0 = 0.0, t1 = 1.0;
  if (abs(ab.x) > 1e-6) {
    float ta = (x0 - f.a.x) / ab.x, tb = (x1 - f.a.x) / ab.x;
    t0 = max(min(ta, tb), 0.0);
    t1 = min(max(ta, tb), 1.0);
  } else if (f.a.x < x0 || f.a.x > x1) {
    return 0u;
  }
  if (t0 > t1) return 0u;
  float ya = f.a.y + ab.y * t0, yb = f.a.y + ab.y * t1;
  int first = max(int(ceil(min(ya, yb) - reach - origin.y)), 0);
  int last = min(int(floor(max(ya, yb) + reach - origin.y)), int(RASTER_TILE_SIZE) - 1);
  if (first > last) return 0u;
  return ((1u << uint(last - first + 1)) - 1u) << uint(first);
}

uint tileListStart(uint tile) { return tiles[tile].x + blocks[tile / RASTER_SCAN_SIZE]; }
#endif
