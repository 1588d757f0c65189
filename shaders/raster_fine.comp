#version 460
// Compute rasterizer, one workgroup per 8x8 tile, one invocation per pixel: walks the tile's list (depth
// bins near to far) and composites front to back, C += a s c, A += a s, until A > 1 - 1/255. a is the
// exact area of the pixel covered by the segment's band (rasterBandCoverage, shared/raster.h) at the
// width interpolated along it (the tip taper); s, the share of it not hidden by the strands in front, is
// 1 - A for independent strands, corrected by an 8 x 8 sample mask of the pixel for strands that overlap
// more or less than independence says (rasterVisibleShare: coincident strands of a sheet seen edge-on).
// A pixel centre belongs to the segment it projects onto within [0, 1), so the segments of a strand
// neither overlap nor leave gaps. Fragments at or behind the head's depth are hidden. Output:
// premultiplied radiance C and alpha A.
#include "shared/raster.h"
#include "common.glsl"

layout(local_size_x = RASTER_FINE_SIZE) in;
layout(std430, binding = RASTER_BINDING_SCREEN) readonly buffer Screen { vec4 screen[]; };
layout(std430, binding = RASTER_BINDING_COLORS) readonly buffer Colors { uvec2 colors[]; };
layout(std430, binding = RASTER_BINDING_TILES) readonly buffer Tiles { uvec2 tiles[]; };
layout(std430, binding = RASTER_BINDING_BLOCKS) readonly buffer Blocks { uint blocks[]; };
layout(std430, binding = RASTER_BINDING_LIST) readonly buffer List { uvec2 list[]; };
layout(binding = RASTER_BINDING_DEPTH) uniform sampler2D headDepth;
layout(binding = RASTER_BINDING_OUTPUT, rgba16f) uniform writeonly image2D outImage;
layout(std430, binding = RASTER_BINDING_PARAMS) readonly buffer Params { RasterParams params; };

vec3 radianceOf(uvec2 c) { return vec3(unpackHalf2x16(c.x), unpackHalf2x16(c.y).x); }
uint samplesIn(uvec2 mask) { return uint(bitCount(mask.x) + bitCount(mask.y)); }  // of the 8 x 8 overlap mask

void main() {
  uint invocation = hpThreadId(RASTER_FINE_SIZE);
  uint tile = invocation / RASTER_FINE_SIZE;
  uint lane = invocation % RASTER_FINE_SIZE;
  if (tile >= params.tilesX * params.tilesY) return;
  uvec2 pixel = uvec2(tile % params.tilesX, tile / params.tilesX) * RASTER_TILE_SIZE +
                uvec2(lane % RASTER_TILE_SIZE, lane / RASTER_TILE_SIZE);
  if (pixel.x >= params.width || pixel.y >= params.height) return;
  vec2 centre = vec2(pixel) + 0.5;
  float occluder = texelFetch(headDepth, ivec2(pixel), 0).r;
  uint start = tiles[tile].x + blocks[tile / RASTER_SCAN_SIZE];
  uint end = min(start + tiles[tile].y, params.capacity);
  vec3 color = vec3(0.0);
  float alpha = 0.0;
  uvec2 covered = uvec2(0u);  // the overlap mask's samples covered so far (rows 0-3, 4-7)
  // Entries that touch none of this pixel's row are skipped in a tight loop before the body: a row of the
  // tile is one 8-wide SIMD vector on lavapipe (whose branches are predicated: a `continue` would still run
  // the body), and on GPUs the skip is as cheap as the body's first test.
  uint rowBit = 1u << (lane / RASTER_TILE_SIZE);
  uint e = start;
  while (alpha <= 1.0 - RASTER_OPAQUE_T) {
    while (e < end && (list[e].y & rowBit) == 0u) ++e;
    if (e >= end) break;
    uint entry = list[e++].x;
    uint v = entry & ~RASTER_LAST_SEGMENT;
    vec4 a = screen[v];
    vec4 b = screen[v + 1u];
    vec2 ab = b.xy - a.xy;
    float len2 = dot(ab, ab);
    if (len2 < 1e-12) continue;
    float t = dot(centre - a.xy, ab) / len2;
    if (t < 0.0 || t > 1.0 || (t == 1.0 && entry < RASTER_LAST_SEGMENT)) continue;
    vec2 n = vec2(-ab.y, ab.x) * inversesqrt(len2);
    float d = dot(centre - a.xy, n);
    float w = mix(a.w, b.w, t);
    if (abs(d) > 0.5 * w + 0.75) continue;
    if (mix(a.z, b.z, t) >= occluder) continue;
    float coverage = rasterBandCoverage(d, w, n.x, n.y);
    if (coverage <= 0.0) continue;
    uvec2 band = uvec2(0u);
    for (uint row = 0u; row < RASTER_MASK_SIDE; ++row)
      band[row >> 2u] |= rasterBandRowBits(d, w, n.x, n.y, row) << ((row & 3u) * 8u);
    float share = rasterVisibleShare(samplesIn(band), samplesIn(covered), samplesIn(band & covered), alpha);
    covered |= band;
    float visible = coverage * share;
    vec3 c = mix(radianceOf(colors[v]), radianceOf(colors[v + 1u]), t);
    color += visible * c;
    alpha = min(alpha + visible, 1.0);
  }
  imageStore(outImage, ivec2(pixel), vec4(color, alpha));
}
