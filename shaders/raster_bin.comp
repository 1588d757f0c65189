#version 460
// Compute rasterizer, per segment of a chunk: the (tile, depth bin) keys its footprint touches.
// RASTER_MODE_COUNT counts them and lists the ends of every segment that touches a tile for shading; RASTER_MODE_SCATTER (after the tile scan) writes the segment's global
// id and the rows of the tile it may cover into each tile's list, keeping the first `keys.y` of each key (the tile budget, nearest bins first).
// The mode is a specialization constant (one pipeline each), not a uniform value lavapipe would inline.
#include "shared/raster.h"
#include "common.glsl"

layout(local_size_x = RASTER_WORKGROUP_SIZE) in;
layout(constant_id = 0) const uint MODE = RASTER_MODE_COUNT;
layout(constant_id = 1) const uint GROUPED = 0u;  // the workgroup's entries counted together (GPUs) or each alone
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

// Lists vertex v for raster_shade.comp once (the segments on either side of it may both ask).
void listForShading(uint v) {
  if (atomicExchange(shadeFlags[v], 1u) != 0u) return;
  uint slot = atomicAdd(shadeArgs[params.chunkIndex].w, 1u);
  shadeList[params.firstVertex + slot] = v;
}

// The workgroup's keys. Its 64 segments are a strand or two, so many of their (tile, bin) entries share a
// key: each distinct key takes one atomic on `counts` per workgroup (its entries' sum) instead of one per
// entry, and the entries take their slots from the workgroup's share. A key that finds no room within
// GROUP_PROBES slots of its hash goes to `counts` directly (so does every later entry of it: slots are
// never freed, so it can never find room later either).
const uint GROUP_KEYS = 4u * RASTER_WORKGROUP_SIZE;
const uint GROUP_PROBES = 8u;
const uint NO_SLOT = 0xFFFFFFFFu;
shared uint groupKey[GROUP_KEYS];    // key + 1; 0 = free
shared uint groupCount[GROUP_KEYS];  // the workgroup's entries of the key
shared uint groupBase[GROUP_KEYS];   // its first slot in the key's share of `counts` (after the flush)
shared uint groupCursor[GROUP_KEYS]; // the entries given a slot so far (scatter)

// The table slot of `key`, inserted when `insert`; NO_SLOT when it has none.
uint groupSlot(uint key, bool insert) {
  uint h = (key * 2654435761u) >> 24u;  // 8 bits: GROUP_KEYS = 256
  for (uint p = 0u; p < GROUP_PROBES; ++p) {
    uint s = (h + p) % GROUP_KEYS;
    uint held = insert ? atomicCompSwap(groupKey[s], 0u, key + 1u) : groupKey[s];
    if (held == key + 1u || (insert && held == 0u)) return s;
    if (held == 0u) return NO_SLOT;  // looking up: a free slot ends the probe
  }
  return NO_SLOT;
}

// An entry with a global slot: written into the tile's list in scatter mode, within the key's budget.
void writeEntry(uint key, uint tile, uint slot, uvec2 entry) {
  if (MODE != RASTER_MODE_SCATTER || slot >= keys[key].y) return;
  uint index = tileListStart(tile) + keys[key].x + slot;
  if (index < params.capacity) list[index] = entry;
}

// Walks the segment's entries: `phase` 0 counts them into the table (or `counts` without room there),
// `phase` 1 (scatter) gives the table's entries their slots and writes them. Returns whether it has any.
bool walkEntries(Footprint f, uint id, uint phase) {
  bool listed = false;
  for (uint ty = f.tileMin.y; ty <= f.tileMax.y; ++ty)
    for (uint tx = f.tileMin.x; tx <= f.tileMax.x; ++tx) {
      uint rows = footprintRows(f, uvec2(tx, ty));
      if (rows == 0u) continue;
      listed = true;
      uint tile = ty * params.tilesX + tx;
      uint key = tile * RASTER_DEPTH_BINS + f.bin;
      uint s = groupSlot(key, phase == 0u);
      if (phase == 0u && s == NO_SLOT) writeEntry(key, tile, atomicAdd(counts[key], 1u), uvec2(id, rows));
      else if (phase == 0u) atomicAdd(groupCount[s], 1u);
      else if (s != NO_SLOT) writeEntry(key, tile, groupBase[s] + atomicAdd(groupCursor[s], 1u), uvec2(id, rows));
    }
  return listed;
}

// Each segment on its own (CPU devices: lavapipe ran the grouped binning 3x slower, 230-250 ms against
// 79-103 at the default frame): one atomic on `counts` per entry.
void binAlone() {
  uint segments = params.verticesPerStrand - 1u;
  uint i = hpThreadId(RASTER_WORKGROUP_SIZE);
  if (i >= params.strandCount * segments) return;
  uint k = i % segments;
  uint v = params.firstVertex + (i / segments) * params.verticesPerStrand + k;
  Footprint f = segmentFootprint(v);
  if (!f.visible) return;
  uint id = v | (k + 1u == segments ? RASTER_LAST_SEGMENT : 0u);
  bool listed = false;
  for (uint ty = f.tileMin.y; ty <= f.tileMax.y; ++ty)
    for (uint tx = f.tileMin.x; tx <= f.tileMax.x; ++tx) {
      uint rows = footprintRows(f, uvec2(tx, ty));
      if (rows == 0u) continue;
      listed = true;
      uint tile = ty * params.tilesX + tx;
      uint key = tile * RASTER_DEPTH_BINS + f.bin;
      writeEntry(key, tile, atomicAdd(counts[key], 1u), uvec2(id, rows));
    }
  if (MODE == RASTER_MODE_COUNT && listed) {
    listForShading(v);
    listForShading(v + 1u);
  }
}

// The workgroup's segments together (GPUs), through the table above.
void binGrouped() {
  uint lane = gl_LocalInvocationID.x;
  for (uint s = lane; s < GROUP_KEYS; s += RASTER_WORKGROUP_SIZE) {
    groupKey[s] = 0u;
    groupCount[s] = 0u;
    groupCursor[s] = 0u;
  }
  barrier();
  uint segments = params.verticesPerStrand - 1u;
  uint i = hpThreadId(RASTER_WORKGROUP_SIZE);
  uint v = 0u, id = 0u;
  Footprint f;
  f.visible = false;
  if (i < params.strandCount * segments) {  // no return: every invocation reaches the barriers
    uint k = i % segments;
    v = params.firstVertex + (i / segments) * params.verticesPerStrand + k;
    f = segmentFootprint(v);
    id = v | (k + 1u == segments ? RASTER_LAST_SEGMENT : 0u);
  }
  bool listed = f.visible && walkEntries(f, id, 0u);
  barrier();
  // The flush: one atomic per key the workgroup holds; its entries' slots start at the value it returns.
  for (uint s = lane; s < GROUP_KEYS; s += RASTER_WORKGROUP_SIZE)
    if (groupKey[s] != 0u) groupBase[s] = atomicAdd(counts[groupKey[s] - 1u], groupCount[s]);
  // Count mode: both ends of a segment in some tile's list get shaded; the others never composite.
  if (MODE == RASTER_MODE_COUNT && listed) {
    listForShading(v);
    listForShading(v + 1u);
  }
  if (MODE != RASTER_MODE_SCATTER) return;
  barrier();
  if (f.visible) walkEntries(f, id, 1u);
}

void main() {
  if (GROUPED != 0u)
    binGrouped();
  else
    binAlone();
}
