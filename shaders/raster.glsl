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
  vec2 invAxis;  // 1 / (b.xy - a.xy), 0 where a coordinate does not change (see clipToSlab)
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
  if (!all(lessThanEqual(lo, hi))) return f;  // off-screen, or not a number (the tile loops stay bounded)
  f.visible = true;
  vec2 ab = f.b.xy - f.a.xy;
  f.invAxis = vec2(abs(ab.x) > 1e-6 ? 1.0 / ab.x : 0.0, abs(ab.y) > 1e-6 ? 1.0 / ab.y : 0.0);
  f.tileMin = uvec2(lo) / RASTER_TILE_SIZE;
  f.tileMax = uvec2(hi) / RASTER_TILE_SIZE;
  float zMin = uintBitsToFloat(state.depthBits.x);
  float zMax = uintBitsToFloat(state.depthBits.y);
  float z = min(f.a.z, f.b.z);
  float bin = (z - zMin) / max(zMax - zMin, 1e-20) * float(RASTER_DEPTH_BINS);
  f.bin = uint(clamp(bin, 0.0, float(RASTER_DEPTH_BINS - 1u)));
  return f;
}

// Narrows [t0, t1] to the part of the segment a + t d (one coordinate, inv = 1 / d, or 0 where d is
// within 1e-6 of 0: constant) within [lo, hi]; false when none.
bool clipToSlab(float a, float inv, float lo, float hi, inout float t0, inout float t1) {
  if (inv != 0.0) {
    precise float ta = (lo - a) * inv, tb = (hi - a) * inv;
    t0 = max(t0, min(ta, tb));
    t1 = min(t1, max(ta, tb));
  } else if (a < lo || a > hi) {
    return false;
  }
  return t0 <= t1;
}

// How far from a pixel centre the segment's foot point may lie for raster_fine.glsl to composite it: half
// the width + 0.75 px (the pixel's half-diagonal, rounded up), + 1e-3.
float footprintReach(Footprint f) {
  precise float reach = 0.5 * max(f.a.w, f.b.w) + 0.75 + 1e-3;
  return reach;
}

// Whether the segment may cover a pixel of the tile that the head does not hide: the count and scatter
// modes' one decision, so both list the same entries. raster_fine.glsl composites a pixel centre c only when
// its foot point s on the segment (t in [0, 1]) is within half the width + 0.75 px (`reach`) of c; with c in
// the tile's columns, s lies on the part of the segment within `reach` of those columns in x (`span`, the
// range of t), and c within `reach` of that part's y range. A segment whose nearer end is at or behind the
// farthest head depth in the tile (raster_tile_depth.glsl) is out: every fragment it could give there fails
// raster_fine's depth test. Its arithmetic is `precise`: the count and scatter modes are two pipelines, and
// a compiler must not contract their expressions differently (an entry counted but not scattered would
// leave a stale one).
bool tileTouched(Footprint f, uvec2 tile, out vec2 span) {
  span = vec2(0.0, 1.0);
  if (min(f.a.z, f.b.z) >= tileDepth[tile.y * params.tilesX + tile.x]) return false;
  float reach = footprintReach(f);
  vec2 origin = vec2(tile * RASTER_TILE_SIZE) + 0.5;  // the tile's first pixel centre
  precise float x0 = origin.x - reach, x1 = origin.x + float(RASTER_TILE_SIZE - 1u) + reach;
  if (!clipToSlab(f.a.x, f.invAxis.x, x0, x1, span.x, span.y)) return false;
  precise float dy = f.b.y - f.a.y;
  precise float ya = f.a.y + dy * span.x, yb = f.a.y + dy * span.y;
  precise float lo = min(ya, yb) - reach - origin.y, hi = max(ya, yb) + reach - origin.y;
  return max(int(ceil(lo)), 0) <= min(int(floor(hi)), int(RASTER_TILE_SIZE) - 1);
}

// The blocks of a touched tile (tileTouched, its `span`) that can hold such a pixel: bit b set when block b
// may. A tile is 8 blocks of 2 x 4 pixels, block b holding columns 2 (b % 4) .. + 1 of rows 4 (b / 4) .. + 3
// (RASTER_BLOCK_*; the fine pass gives each block one 8-wide SIMD vector on lavapipe, so a thin strand
// crossing a tile meets fewer vectors than it would rows: 2-4 blocks against 8 rows for a vertical one). By
// the argument above, s lies on the part of the span within `reach` of the block's rows in y, and c within
// `reach` of that part's x range: one clip per band of 4 rows gives a conservative set. Scatter mode only; an
// entry whose set comes out empty (float rounding at the edge of the decision) is skipped by every pixel.
uint footprintBlocks(Footprint f, uvec2 tile, vec2 span) {
  float reach = footprintReach(f);
  vec2 ab = f.b.xy - f.a.xy;
  vec2 origin = vec2(tile * RASTER_TILE_SIZE) + 0.5;
  // Per band of rows, the part of the span within reach of it, then its four blocks at once (shared/raster.h
  // asserts the 2 bands x 4 blocks; a vec4, no inner loop: lavapipe runs it as four SIMD vectors).
  const float w = float(RASTER_BLOCK_WIDTH);
  vec4 x0 = origin.x + vec4(0.0, 1.0, 2.0, 3.0) * w;  // the blocks' first pixel centres
  uint mask = 0u;  // (not `blocks`: raster_bin.comp's scan-block buffer)
  for (uint band = 0u; band < RASTER_TILE_SIZE / RASTER_BLOCK_HEIGHT; ++band) {
    float y0 = origin.y + float(band * RASTER_BLOCK_HEIGHT) - reach;
    float s0 = span.x, s1 = span.y;
    if (!clipToSlab(f.a.y, f.invAxis.y, y0, y0 + float(RASTER_BLOCK_HEIGHT - 1u) + 2.0 * reach, s0, s1)) continue;
    float xa = f.a.x + ab.x * s0, xb = f.a.x + ab.x * s1;
    vec4 lo = vec4(min(xa, xb) - reach), hi = vec4(max(xa, xb) + reach);
    uvec4 in4 = uvec4(lessThanEqual(lo, x0 + (w - 1.0))) & uvec4(greaterThanEqual(hi, x0));
    mask |= (in4.x | (in4.y << 1u) | (in4.z << 2u) | (in4.w << 3u)) << (4u * band);
  }
  return mask;
}

uint tileListStart(uint tile) { return tiles[tile].x + blocks[tile / RASTER_SCAN_SIZE]; }
#endif
