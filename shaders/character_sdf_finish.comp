#version 460
// One invocation per row of grid nodes along x: the keys the triangles left (shared/character.h, step 3) into
// the signed distances the simulation reads, walking the row from its outside end: a node no triangle came
// near takes the side of the last node before it that one did (inside: minus the band, else plus), so the
// body's interior beyond the band stays inside and the band's inner edge interpolates with inside values.
#include "shared/character.h"
#include "shared/sdf.h"
#include "common.glsl"

layout(local_size_x = CHARACTER_WORKGROUP_SIZE) in;
layout(push_constant) uniform Push { CharacterParams params; };
layout(std430, binding = CHARACTER_BINDING_KEYS) readonly buffer Keys { uint keys[]; };
layout(std430, binding = CHARACTER_BINDING_SDF) writeonly buffer SdfField {
  SdfHeader sdfHeader;
  float sdfValues[];
};

void main() {
  uint row = hpThreadId(CHARACTER_WORKGROUP_SIZE);
  if (row >= params.dims.y * params.dims.z) return;
  float band = float(params.counts.z) * params.originCell.w;
  bool inside = false;  // the grid's faces are outside the body (padded beyond it)
  uint first = row * params.dims.x;
  for (uint x = 0u; x < params.dims.x; ++x) {
    uint key = keys[first + x];
    if (key != 0xFFFFFFFFu) inside = (key & 1u) == 1u;
    float d = key == 0xFFFFFFFFu ? band : uintBitsToFloat(key & ~1u);
    sdfValues[first + x] = inside ? -d : d;
  }
}
