// Compute rasterizer, one workgroup per 8x8 tile, one invocation per pixel: walks the tile's list (depth
// bins near to far) and composites front to back, C += a s c, A += a s, until A > 1 - 1/255. a is the
// exact area of the pixel covered by the segment's band (rasterBandCoverage, shared/raster.h) at the
// width interpolated along it (the tip taper); s, the share of it not hidden by the strands in front, is
// 1 - A for independent strands, corrected by an 8 x 8 sample mask of the pixel for strands that overlap
// more or less than independence says (rasterVisibleShare: coincident strands of a sheet seen edge-on).
// A pixel centre belongs to the segment it projects onto within [0, 1), so the segments of a strand
// neither overlap nor leave gaps. Fragments at or behind the head's depth are hidden. Output:
// premultiplied radiance C and alpha A.
// With a multisampled head depth a pixel whose head samples hide some of its hair (the skin's edge in
// front of hair behind it) writes two layers: the far one, every fragment in front of the farthest head
// sample, and the near one, the fragments in front of every head sample, with the mask of the samples
// that hide hair; the composite gives each sample its layer (shared/raster.h), so the head's edge over
// the hair is antialiased like its edge over the background.
// With motion vectors (specialization constant MOTION) the vertices' screen motion is composited like the
// radiance, into the far layer's coverage-weighted motion: sum(a s m) / sum(a s) (0 without hair).
#include "shared/raster.h"
#include "common.glsl"
#include "half_rgb.glsl"

layout(local_size_x = RASTER_FINE_SIZE) in;
layout(constant_id = 0) const uint MOTION = 0u;
// The staged walk (GPUs: raster_fine_staged*.comp) or the direct one (CPU devices: raster_fine*.comp): two
// shaders, not a specialization constant, so the direct one has no barrier or shared memory at all (their
// mere presence made lavapipe's direct walk 5% slower).
#ifdef RASTER_FINE_STAGED
const uint STAGED = 1u;
#else
const uint STAGED = 0u;
#endif
layout(std430, binding = RASTER_BINDING_SCREEN) readonly buffer Screen { vec4 screen[]; };
layout(std430, binding = RASTER_BINDING_COLORS) readonly buffer Colors { uvec2 colors[]; };
layout(std430, binding = RASTER_BINDING_TILES) readonly buffer Tiles { uvec2 tiles[]; };
layout(std430, binding = RASTER_BINDING_BLOCKS) readonly buffer Blocks { uint blocks[]; };
layout(std430, binding = RASTER_BINDING_LIST) readonly buffer List { uvec2 list[]; };
#ifndef RASTER_FINE_STAGED
layout(binding = RASTER_BINDING_LIST_TEXELS) uniform usamplerBuffer listTexels;
layout(binding = RASTER_BINDING_SCREEN_TEXELS) uniform samplerBuffer screenTexels;
layout(binding = RASTER_BINDING_COLOR_TEXELS) uniform usamplerBuffer colorTexels;
#endif
layout(std430, binding = RASTER_BINDING_PARAMS) readonly buffer Params { RasterParams params; };
#include "raster_head_depth.glsl"
layout(binding = RASTER_BINDING_OUTPUT, rgba16f) uniform writeonly image2D outImage;
#ifdef RASTER_HEAD_MULTISAMPLED
layout(binding = RASTER_BINDING_OUTPUT_NEAR, rgba16f) uniform writeonly image2D nearImage;
layout(binding = RASTER_BINDING_NEAR_MASK, r32ui) uniform writeonly uimage2D nearMaskImage;
#endif
layout(std430, binding = RASTER_BINDING_MOTION) readonly buffer Motion { uint motion[]; };
layout(binding = RASTER_BINDING_MOTION_OUTPUT, rg16f) uniform writeonly image2D motionImage;

// The list entry, screen vertex and colour at an index: storage buffer loads in the staged walk, texel
// fetches of the same buffers in the direct one (shared/raster.h RASTER_BINDING_LIST_TEXELS: lavapipe).
#ifdef RASTER_FINE_STAGED
uvec2 listEntry(uint e) { return list[e]; }
vec4 screenVertex(uint v) { return screen[v]; }
vec3 vertexColor(uint v) { return unpackHalfRgb(colors[v]); }
#else
uvec2 listEntry(uint e) { return texelFetch(listTexels, int(e)).xy; }
vec4 screenVertex(uint v) { return texelFetch(screenTexels, int(v)); }
vec3 vertexColor(uint v) { return unpackHalfRgb(texelFetch(colorTexels, int(v)).xy); }
#endif

uint samplesIn(uvec2 mask) { return uint(bitCount(mask.x) + bitCount(mask.y)); }  // of the 8 x 8 overlap mask

// Hair composited front to back so far: premultiplied radiance, alpha, the overlap mask's covered samples,
// and the coverage-weighted screen motion (MOTION).
struct Layer {
  vec3 color;
  float alpha;
  uvec2 covered;
  vec3 motion;  // xy: sum of visible share x motion, z: sum of visible shares
};

// Adds a fragment of exact area `coverage` and overlap-mask samples `band` behind what the layer holds;
// returns the share of the pixel it added.
float composite(inout Layer layer, float coverage, uvec2 band, vec3 c) {
  float share = rasterVisibleShare(samplesIn(band), samplesIn(layer.covered), samplesIn(band & layer.covered), layer.alpha);
  layer.covered |= band;
  float visible = coverage * share;
  layer.color += visible * c;
  layer.alpha = min(layer.alpha + visible, 1.0);
  return visible;
}

#ifdef RASTER_HEAD_MULTISAMPLED
// The head samples of `pixel` at or in front of depth z.
uint headSamplesInFront(ivec2 pixel, float z) {
  uint mask = 0u;
  for (uint s = 0u; s < headSamples(); ++s)
    if (headDepthAt(pixel, s) <= z) mask |= 1u << s;
  return mask;
}
#endif

// A list entry as the pixels read it: what every pixel of the tile would otherwise work out again.
struct Segment {
  vec4 a, b;      // screen[v], screen[v + 1]: x, y, z, width
  vec4 axis;      // xy = b - a, zw = the unit normal (staged walk only)
  float length2;  // |b - a|^2
  uint blocks;    // the tile's blocks it may cover (bits 0-7), RASTER_LAST_SEGMENT for the strand's tip segment;
                  // 0 for a degenerate segment (skipped)
  uint v;         // the global index of its first vertex
  uint colorMid;  // RASTER_COLOR_A_MID or _B_MID: which end's colour is its neighbours' mean (or 0)
  vec3 colorA, colorB;  // staged walk only: the direct one reads them for the fragments it composites
  vec4 motion;    // xy = screen motion at a, zw = at b (MOTION; staged walk only)
};

// The colours of the segment's ends: the two shaded vertices' radiance, or where an end is the middle of a
// pair (shared/raster.h RASTER_COLOR_A_MID), their neighbours' and its mean. Two fetches either way.
void loadColors(inout Segment g) {
  bool aMid = (g.colorMid & RASTER_COLOR_A_MID) != 0u, bMid = (g.colorMid & RASTER_COLOR_B_MID) != 0u;
  vec3 lo = vertexColor(aMid ? g.v - 1u : g.v), hi = vertexColor(bMid ? g.v + 2u : g.v + 1u);
  vec3 mean = 0.5 * (lo + hi);
  g.colorA = aMid ? mean : lo;
  g.colorB = bMid ? mean : hi;
}

Segment loadSegment(uvec2 item) {
  Segment g;
  uint v = item.x & ~RASTER_LAST_SEGMENT;
  g.v = v;
  g.colorMid = item.y & (RASTER_COLOR_A_MID | RASTER_COLOR_B_MID);
  g.a = screenVertex(v);
  g.b = screenVertex(v + 1u);
  vec2 ab = g.b.xy - g.a.xy;
  g.length2 = dot(ab, ab);
  g.blocks = g.length2 < 1e-12 ? 0u : (item.y & 0xFFu) | (item.x & RASTER_LAST_SEGMENT);
  g.axis = vec4(ab, 0.0, 0.0);
  if (STAGED == 0u) return g;  // the direct walk works out the rest for the fragments it composites
  g.axis.zw = vec2(-ab.y, ab.x) * inversesqrt(max(g.length2, 1e-12));
  loadColors(g);
  g.motion = MOTION != 0u ? vec4(unpackHalf2x16(motion[v]), unpackHalf2x16(motion[v + 1u])) : vec4(0.0);
  return g;
}

// The pixel's state: fixed (where it is, its head depths) and composited so far.
uvec2 pixel;
vec2 centre;
float farthest, nearest;  // over the pixel's head samples
Layer far;                // rows 0-3, 4-7 of the overlap mask
#ifdef RASTER_HEAD_MULTISAMPLED
Layer near;
bool split;     // whether a fragment was hidden at some head samples (then `near` is its own layer)
uint nearMask;
#endif

// Composites the segment's fragment at this pixel, if it has one; returns whether the pixel is still open.
bool compositeSegment(Segment g) {
  float t = dot(centre - g.a.xy, g.axis.xy) / g.length2;
  // One exit (lavapipe lowers early returns of an inlined function into extra masks per fragment).
  if (g.blocks != 0u && t >= 0.0 && t <= 1.0 && (t != 1.0 || (g.blocks & RASTER_LAST_SEGMENT) != 0u)) {
    vec2 n = STAGED != 0u ? g.axis.zw : vec2(-g.axis.y, g.axis.x) * inversesqrt(g.length2);
    float d = dot(centre - g.a.xy, n);
    float w = mix(g.a.w, g.b.w, t);
    float z = mix(g.a.z, g.b.z, t);
    float coverage = abs(d) > 0.5 * w + 0.75 || z >= farthest ? 0.0 : rasterBandCoverage(d, w, n.x, n.y);
    if (coverage > 0.0) {
      uvec2 band = rasterBandMask(d, w, n.x, n.y);
      if (STAGED == 0u) loadColors(g);
      vec3 c = mix(g.colorA, g.colorB, t);
#ifdef RASTER_HEAD_MULTISAMPLED  // one sample: nearest == farthest, nothing is hidden at some samples only
      if (z >= nearest) {  // hidden at some head samples: those keep only the hair in front of all of them
        if (!split) near = far;
        split = true;
        nearMask |= headSamplesInFront(ivec2(pixel), z);
      } else if (split) {
        composite(near, coverage, band, c);
      }
#endif
      float visible = composite(far, coverage, band, c);
      if (MOTION != 0u && STAGED == 0u) g.motion = vec4(unpackHalf2x16(motion[g.v]), unpackHalf2x16(motion[g.v + 1u]));
      if (MOTION != 0u) far.motion += visible * vec3(mix(g.motion.xy, g.motion.zw, t), 1.0);
    }
  }
  return far.alpha <= 1.0 - RASTER_OPAQUE_T;
}

// Entries that touch none of this pixel's block are skipped in a tight loop before the body: a block of the
// tile is one 8-wide SIMD vector on lavapipe (whose branches are predicated: a `continue` would still run
// the body), and on GPUs the skip is as cheap as the body's first test.

// The direct walk (CPU devices): each pixel walks the tile's list on its own and stops when it is opaque.
void walkDirect(uint start, uint end, uint blockBit) {
  bool open = true;
  for (uint e = start; open;) {
    while (e < end && (listEntry(e).y & blockBit) == 0u) ++e;
    if (e >= end) break;
    open = compositeSegment(loadSegment(listEntry(e++)));
  }
}

// The staged walk (GPUs): the list in batches of RASTER_FINE_SIZE entries, each invocation loading one into
// shared memory, then every pixel walking the batch. The batch's loads are issued at once instead of one
// dependent chain (list, screen, colours) per entry and pixel, and each entry's set-up is done once per
// tile instead of once per pixel. The workgroup stops after a batch in which every pixel became opaque (a
// vote through `live`). On lavapipe it takes about 2x the direct walk's time (the default frame, 640x480).
#ifdef RASTER_FINE_STAGED
shared Segment staged[RASTER_FINE_SIZE];
shared uint live[2];  // whether some pixel is still open, alternate batches

void walkStaged(uint start, uint end, uint blockBit, uint lane, bool open) {
  if (lane == 0u) live[0] = 0u;
  for (uint base = start, batch = 0u; base < end; base += RASTER_FINE_SIZE, ++batch) {
    if (base + lane < end) staged[lane] = loadSegment(listEntry(base + lane));
    barrier();
    // Every invocation has read the previous batch's vote: the next batch's may be cleared.
    if (lane == 0u) live[(batch + 1u) & 1u] = 0u;
    uint count = min(end - base, RASTER_FINE_SIZE);
    for (uint j = 0u; open;) {
      while (j < count && (staged[j].blocks & blockBit) == 0u) ++j;
      if (j >= count) break;
      open = compositeSegment(staged[j++]);
    }
    if (open) live[batch & 1u] = 1u;
    barrier();  // the vote is in; the staged batch is read
    if (live[batch & 1u] == 0u) break;
  }
}

#endif
void main() {
  uint invocation = hpThreadId(RASTER_FINE_SIZE);
  uint tile = invocation / RASTER_FINE_SIZE;
  uint lane = invocation % RASTER_FINE_SIZE;
  if (tile >= params.tilesX * params.tilesY) return;  // the whole workgroup: one workgroup is one tile
  // Lanes 8 b .. 8 b + 7 are block b (shared/raster.h): 2 x 4 pixels.
  uint block = lane / (RASTER_BLOCK_WIDTH * RASTER_BLOCK_HEIGHT), within = lane % (RASTER_BLOCK_WIDTH * RASTER_BLOCK_HEIGHT);
  const uint blocksPerRow = RASTER_TILE_SIZE / RASTER_BLOCK_WIDTH;
  pixel = uvec2(tile % params.tilesX, tile / params.tilesX) * RASTER_TILE_SIZE +
          uvec2((block % blocksPerRow) * RASTER_BLOCK_WIDTH + within % RASTER_BLOCK_WIDTH,
                (block / blocksPerRow) * RASTER_BLOCK_HEIGHT + within / RASTER_BLOCK_WIDTH);
  // In the staged walk, pixels past the image's edge load entries and vote but composite nothing.
  bool inside = pixel.x < params.width && pixel.y < params.height;
  if (!inside && STAGED == 0u) return;
  centre = vec2(pixel) + 0.5;
  farthest = 0.0;
  nearest = 1.0;
  for (uint s = 0u; inside && s < headSamples(); ++s) {
    float depth = headDepthAt(ivec2(pixel), s);
    farthest = max(farthest, depth);
    nearest = min(nearest, depth);
  }
  far = Layer(vec3(0.0), 0.0, uvec2(0u), vec3(0.0));
#ifdef RASTER_HEAD_MULTISAMPLED
  near = far;
  split = false;
  nearMask = 0u;
#endif
  uint start = tiles[tile].x + blocks[tile / RASTER_SCAN_SIZE];
  uint end = min(start + tiles[tile].y, params.capacity);
  uint blockBit = 1u << block;
#ifdef RASTER_FINE_STAGED
  walkStaged(start, end, blockBit, lane, inside);
#else
  walkDirect(start, end, blockBit);
#endif
  if (!inside) return;
  imageStore(outImage, ivec2(pixel), vec4(far.color, far.alpha));
  if (MOTION != 0u)
    imageStore(motionImage, ivec2(pixel), vec4(far.motion.z > 0.0 ? far.motion.xy / far.motion.z : vec2(0.0), 0.0, 0.0));
#ifdef RASTER_HEAD_MULTISAMPLED
  if (!split) near = far;
  imageStore(nearImage, ivec2(pixel), vec4(near.color, near.alpha));
  imageStore(nearMaskImage, ivec2(pixel), uvec4(nearMask));
#endif
}
