#version 460
// One invocation per grid cell: fixed-point sums -> relative density, density times velocity, and the
// pressure max(density - target, 0) with its gradient by central differences (one-sided at the grid's
// faces), for simulate.comp (layout: shaders/shared/hair_grid.h). Raises the frame's peak density.
#include "shared/hair_grid.h"
#include "common.glsl"
#include "hair_grid.glsl"

layout(local_size_x = GRID_WORKGROUP_SIZE) in;
layout(push_constant) uniform Push { GridParams params; };
layout(std430, binding = GRID_BINDING_ACCUM) readonly buffer Accum { int accum[]; };
layout(std430, binding = GRID_BINDING_CELLS) writeonly buffer Cells { vec4 cells[]; };
layout(std430, binding = GRID_BINDING_PEAK) buffer Peak { uint peak[]; };

float density(ivec3 c) {
  return float(accum[gridCellIndex(c, params.dims.xyz) * GRID_ACCUM_INTS]) * params.fixedPoint.y * params.density.x;
}

float pressure(ivec3 c) { return max(density(c) - params.density.y, 0.0); }

// d pressure / d axis at c, from the neighbours inside the grid.
float pressureSlope(ivec3 c, int axis) {
  ivec3 e = ivec3(0);
  e[axis] = 1;
  int last = int(params.dims[axis]) - 1;
  ivec3 lo = c[axis] > 0 ? c - e : c;
  ivec3 hi = c[axis] < last ? c + e : c;
  float span = float(hi[axis] - lo[axis]) * params.originCell.w;
  return span > 0.0 ? (pressure(hi) - pressure(lo)) / span : 0.0;
}

void main() {
  uvec3 d = params.dims.xyz;
  uint index = hpThreadId(GRID_WORKGROUP_SIZE);
  if (index >= d.x * d.y * d.z) return;
  ivec3 c = ivec3(index % d.x, (index / d.x) % d.y, index / (d.x * d.y));
  uint at = index * GRID_ACCUM_INTS;
  float rho = density(c);
  // weight x velocity / maxSpeed in fixed point -> density x velocity in scene units / s.
  float toVelocity = params.fixedPoint.y * params.density.x * params.fixedPoint.w;
  vec3 momentum = vec3(accum[at + 1u], accum[at + 2u], accum[at + 3u]) * toVelocity;
  cells[GRID_CELL_VEC4S * index] = vec4(momentum, rho);
  cells[GRID_CELL_VEC4S * index + 1u] =
      vec4(pressureSlope(c, 0), pressureSlope(c, 1), pressureSlope(c, 2), max(rho - params.density.y, 0.0));
  if (rho > 0.0) atomicMax(peak[0], floatBitsToUint(rho));
}
