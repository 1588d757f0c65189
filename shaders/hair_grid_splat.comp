#version 460
// One invocation per free guide particle: adds its weight and momentum to the 8 grid cells around it as
// fixed-point integers (shaders/shared/hair_grid.h). Velocity is the last substep's (Verlet: position minus
// previous), clamped to maxSpeed and carried in units of it so the integers cannot overflow
// (compute/strands/hair_grid_pass.cpp picks the scale from the particle count).
#include "shared/hair_grid.h"
#include "common.glsl"
#include "hair_grid.glsl"

layout(local_size_x = GRID_WORKGROUP_SIZE) in;
layout(push_constant) uniform Push { GridParams params; };
layout(std430, binding = GRID_BINDING_POSITIONS) readonly buffer Positions { vec4 positions[]; };
layout(std430, binding = GRID_BINDING_PREVIOUS) readonly buffer Previous { vec4 previous[]; };
layout(std430, binding = GRID_BINDING_ACCUM) buffer Accum { int accum[]; };

void main() {
  uint particle = hpThreadId(GRID_WORKGROUP_SIZE);
  if (particle >= params.dims.w || particle % uint(params.density.z) == 0u) return;  // roots stay out
  vec3 x = positions[particle].xyz;
  vec3 v = (x - previous[particle].xyz) * params.fixedPoint.z / params.fixedPoint.w;
  if (!allFinite(x) || !allFinite(v)) return;  // one bad particle stays its own
  float speed = length(v);
  if (speed > 1.0) v /= speed;
  ivec3 base;
  vec3 frac;
  gridFootprint((params.worldToGrid * vec4(x, 1.0)).xyz, params.originCell, base, frac);
  for (uint k = 0u; k < 8u; ++k) {
    float w;
    int cell = gridCorner(base, frac, params.dims.xyz, k, w);
    if (cell < 0) continue;
    float units = w * params.fixedPoint.x;
    uint at = uint(cell) * GRID_ACCUM_INTS;
    atomicAdd(accum[at], int(roundEven(units)));
    atomicAdd(accum[at + 1u], int(roundEven(units * v.x)));
    atomicAdd(accum[at + 2u], int(roundEven(units * v.y)));
    atomicAdd(accum[at + 3u], int(roundEven(units * v.z)));
  }
}
