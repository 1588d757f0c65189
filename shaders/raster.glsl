// GLSL only: what the compute rasterizer's segment passes share (compute/strand_raster_pass.h,
// shared/raster.h). The includer declares `params` (RasterParams), `screen` (vec4[]) and `state` (RasterState).
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
  uint v = globalStrand * params.verticesPerStrand + k;
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

// Whether a tile can hold a pixel the segment covers and the head does not hide: the tile's centre within
// reach of the segment (a long diagonal segment's box holds many tiles it never touches), the tile's
// square within reach of the segment's line (separating axis along the line's normal: a tile beside the
// segment but within the half-diagonal circle is out), and the nearer end in front of the farthest head
// depth in the tile (raster_tile_depth.comp; behind it every fragment fails raster_fine's depth test).
bool footprintTouches(Footprint f, uvec2 tile) {
  if (min(f.a.z, f.b.z) >= tileDepth[tile.y * params.tilesX + tile.x]) return false;
  vec2 centre = (vec2(tile) + 0.5) * float(RASTER_TILE_SIZE);
  vec2 ab = f.b.xy - f.a.xy;
  float len2 = max(dot(ab, ab), 1e-12);
  float t = clamp(dot(centre - f.a.xy, ab) / len2, 0.0, 1.0);
  float band = 0.5 * max(f.a.w, f.b.w) + 0.75;
  if (distance(centre, f.a.xy + t * ab) > band + 0.7072 * float(RASTER_TILE_SIZE)) return false;
  vec2 n = vec2(-ab.y, ab.x) * inversesqrt(len2);
  float halfTile = 0.5 * float(RASTER_TILE_SIZE);
  return abs(dot(centre - f.a.xy, n)) <= band + halfTile * (abs(n.x) + abs(n.y)) + 1e-3;
}

uint tileListStart(uint tile) { return tiles[tile].x + blocks[tile / RASTER_SCAN_SIZE]; }
#endif
