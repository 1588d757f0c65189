#version 460
#extension GL_KHR_shader_subgroup_basic : require
#extension GL_KHR_shader_subgroup_arithmetic : require
#extension GL_KHR_shader_subgroup_ballot : require
// Compute rasterizer, per segment of a chunk: the (tile, depth bin) keys its footprint touches.
// RASTER_MODE_COUNT counts them and lists for shading the ends of every segment that touches a tile (or its pair's
// ends: the shading spacing); RASTER_MODE_SCATTER (after the tile scan) writes the segment's global
// id and the blocks of the tile it may cover into each tile's list, keeping the first `keys.y` of each key (the tile budget, nearest bins first).
// The mode is a specialization constant (one pipeline each), not a uniform value lavapipe would inline.
#include "shared/raster.h"
#include "common.glsl"

layout(local_size_x = RASTER_WORKGROUP_SIZE) in;
layout(constant_id = 0) const uint MODE = RASTER_MODE_COUNT;
layout(std430, binding = RASTER_BINDING_SCREEN) readonly buffer Screen { vec4 screen[]; };
layout(std430, binding = RASTER_BINDING_STATE) readonly buffer State { RasterState state; };
layout(std430, binding = RASTER_BINDING_COUNTS) buffer Counts { uint counts[]; };
layout(std430, binding = RASTER_BINDING_KEYS) readonly buffer Keys { uvec2 keys[]; };
layout(std430, binding = RASTER_BINDING_TILES) readonly buffer Tiles { uvec2 tiles[]; };
layout(std430, binding = RASTER_BINDING_BLOCKS) readonly buffer Blocks { uint blocks[]; };
layout(std430, binding = RASTER_BINDING_LIST) writeonly buffer List { uvec2 list[]; };
layout(std430, binding = RASTER_BINDING_TILE_DEPTH) readonly buffer TileDepth { float tileDepth[]; };
layout(std430, binding = RASTER_BINDING_PARAMS) readonly buffer Params { RasterParams params; };
layout(std430, binding = RASTER_BINDING_SHADE_FLAGS) buffer ShadeFlags { uint shadeFlags[]; };
layout(std430, binding = RASTER_BINDING_SHADE_LIST) writeonly buffer ShadeList { uint shadeList[]; };
layout(std430, binding = RASTER_BINDING_SHADE_ARGS) buffer ShadeArgs { uvec4 shadeArgs[]; };
#include "raster.glsl"

// Segments 2j and 2j + 1 of a strand are a pair (shared/raster.h RASTER_COLOR_A_MID) over vertices 2j, 2j + 1,
// 2j + 2: segment k has a partner unless it is the strand's last with an even k, and its pair starts at
// vertex v - (k & 1) (v: the segment's first vertex). One definition for the count and scatter steps, which
// must agree on every pair.
bool pairExists(uint k, uint segments) { return (k & ~1u) + 2u <= segments; }
uint pairStart(uint v, uint k) { return v - (k & 1u); }

// Scatter mode: the end of segment k whose colour is its pair's mean, as a list entry flag (or 0). Not decided
// again but read back: the count step left the pair's middle vertex unclaimed exactly where it chose the mean
// (only the pair's two segments can claim it, and one that is listed claims it otherwise), so the fine pass
// never reads a vertex that was not shaded.
uint colorMidFlag(uint v, uint k, uint segments) {
  if (!pairExists(k, segments) || shadeFlags[pairStart(v, k) + 1u] != 0u) return 0u;
  return (k & 1u) != 0u ? RASTER_COLOR_A_MID : RASTER_COLOR_B_MID;
}

// Bins the segment from vertex v (its key counts, and in scatter mode its list entries, flagged with
// colorMidFlag: which end's colour is a mean, shared/raster.h); returns whether some tile lists it, and its
// footprint in f.
bool binSegment(uint v, uint k, uint segments, out Footprint f) {
  f = segmentFootprint(v);
  if (!f.visible) return false;
  uint colorMid = MODE == RASTER_MODE_SCATTER ? colorMidFlag(v, k, segments) : 0u;
  uint id = v | (k + 1u == segments ? RASTER_LAST_SEGMENT : 0u);
  bool listed = false;
  // The footprint's tiles row by row in one loop: the lanes of a SIMD vector (lavapipe) each take their own
  // segment's next tile, so a vector runs as many iterations as its largest footprint has tiles rather than its
  // tallest one's rows times its widest one's columns. (No integer division: lavapipe runs it lane by lane.)
  uvec2 size = f.tileMax - f.tileMin + 1u;
  uint tx = f.tileMin.x - 1u, ty = f.tileMin.y;  // one before the first tile (wraps at 0: the step below undoes it)
  for (uint n = 0u; n < size.x * size.y; ++n) {
    if (++tx > f.tileMax.x) {
      tx = f.tileMin.x;
      ++ty;
    }
    vec2 span;
    if (!tileTouched(f, uvec2(tx, ty), span)) continue;
    listed = true;
    uint tile = ty * params.tilesX + tx;
    uint key = tile * RASTER_DEPTH_BINS + f.bin;
    uint slot = atomicAdd(counts[key], 1u);
    if (MODE != RASTER_MODE_SCATTER || slot >= keys[key].y) continue;
    uint index = tileListStart(tile) + keys[key].x + slot;
    if (index < params.capacity) list[index] = uvec2(id, footprintBlocks(f, uvec2(tx, ty), span) | colorMid);
  }
  return listed;
}

// Count mode: whether segment k of a strand (first vertex v, `segments` per strand) is one of a pair (2j, 2j + 1)
// whose middle vertex takes the mean of its neighbours' radiance (shared/raster.h RASTER_COLOR_A_MID): its
// neighbours lie within the shading spacing on screen and the pair bends little there (the middle vertex
// within 1/8 of the chord from the chord's midpoint: a turn of at most ~28 degrees, where a curl or a kink
// would change the shading most between the ends). Both segments of the pair compare the same three screen
// records: two are the segment's footprint ends f.a, f.b, the third the pair's vertex beyond them. A
// strand's last segment with an even k has no partner; an end behind the camera keeps every vertex.
bool pairInterpolated(Footprint f, uint v, uint k, uint segments) {
  if (params.shadingSpacing <= 0.0 || !pairExists(k, segments)) return false;
  bool odd = (k & 1u) != 0u;
  vec4 beyond = screen[pairStart(v, k) + (odd ? 0u : 2u)];  // the pair's vertex outside this segment
  vec4 a = odd ? beyond : f.a, middle = odd ? f.a : f.b, b = odd ? f.b : beyond;
  if (a.w < 0.0 || b.w < 0.0) return false;
  vec2 chord = b.xy - a.xy, off = middle.xy - 0.5 * (a.xy + b.xy);
  float chord2 = dot(chord, chord);
  return chord2 <= params.shadingSpacing * params.shadingSpacing && 64.0 * dot(off, off) <= chord2;
}

// Whether this invocation is the one that lists vertex v for shading (the segments on either side of it
// may both ask). A flag only goes from 0 to 1 in a frame: one already read as set needs no atomic.
bool claimForShading(uint v) { return shadeFlags[v] == 0u && atomicExchange(shadeFlags[v], 1u) == 0u; }

void main() {
  uint segments = params.verticesPerStrand - 1u;
  uint i = hpThreadId(RASTER_WORKGROUP_SIZE);
  bool inRange = i < params.strandCount * segments;
  uint k = i % segments;
  uint v = params.firstVertex + (i / segments) * params.verticesPerStrand + k;
  if (MODE != RASTER_MODE_COUNT) {  // a specialization constant: uniform, no subgroup operation below is skipped unevenly
    Footprint f;
    if (inRange) binSegment(v, k, segments, f);
    return;
  }
  // Count mode: both ends of a segment in some tile's list get shaded, or where one end is a mean, the two
  // vertices it is the mean of (the pair's ends); the others never composite.
  Footprint f;
  bool listed = inRange && binSegment(v, k, segments, f);
  bool mean = listed && pairInterpolated(f, v, k, segments);
  uint lo = mean ? pairStart(v, k) : v, hi = mean ? lo + 2u : v + 1u;
  bool first = listed && claimForShading(lo);
  bool second = listed && claimForShading(hi);
  // Where they go in the chunk's shade list: one global atomic per subgroup instead of one per listed vertex
  // on a single counter (which serialises on GPUs), and a subgroup's vertices land next to each other, as
  // the shade pass reads them. No shared memory or barrier.
  uint mine = uint(first) + uint(second);
  uint local = subgroupExclusiveAdd(mine), listedHere = subgroupAdd(mine);
  uint base = 0u;
  if (subgroupElect() && listedHere > 0u) base = atomicAdd(shadeArgs[params.chunkIndex].w, listedHere);
  base = subgroupBroadcastFirst(base);
  uint slot = params.firstVertex + base + local;
  if (first) shadeList[slot++] = lo;
  if (second) shadeList[slot] = hi;
}
