// GLSL only: what the compute rasterizer's segment passes share (compute/strand_raster_pass.h,
// shared/raster.h). The includer declares `push` (RasterPush), `screen` (vec4[]) and `state` (RasterState).
#ifndef HP_RASTER_GLSL
#define HP_RASTER_GLSL

// The screen-space footprint of segment k of a global strand: the tiles it may touch and its depth bin.
struct Footprint {
  bool visible;
  uvec2 tileMin;
  uvec2 tileMax;
  uint bin;
  vec4 a;  // screen records of the two ends (shared/raster.h)
  vec4 b;
};

Footprint segmentFootprint(uint globalStrand, uint k) {
  Footprint f;
  uint v = globalStrand * push.verticesPerStrand + k;
  f.a = screen[v];
  f.b = screen[v + 1u];
  f.visible = false;
  if (f.a.w < 0.0 || f.b.w < 0.0) return f;  // an end behind the camera
  // Reach past the centre line: half the width plus a pixel's half-diagonal.
  float reach = 0.5 * max(f.a.w, f.b.w) + 0.75;
  vec2 lo = max(min(f.a.xy, f.b.xy) - reach, vec2(0.0));
  vec2 hi = min(max(f.a.xy, f.b.xy) + reach, vec2(push.width, push.height) - 1e-3);
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

// Whether a tile can hold a pixel the segment covers: its centre within reach of the segment (a
// long diagonal segment's box holds many tiles it never touches).
bool footprintTouches(Footprint f, uvec2 tile) {
  vec2 centre = (vec2(tile) + 0.5) * float(RASTER_TILE_SIZE);
  vec2 ab = f.b.xy - f.a.xy;
  float t = clamp(dot(centre - f.a.xy, ab) / max(dot(ab, ab), 1e-12), 0.0, 1.0);
  float reach = 0.5 * max(f.a.w, f.b.w) + 0.75 + 0.7072 * float(RASTER_TILE_SIZE);
  return distance(centre, f.a.xy + t * ab) <= reach;
}

uint tileListStart(uint tile) { return tiles[tile].x + blocks[tile / RASTER_SCAN_SIZE]; }
#endif
