// The hair grid's trilinear footprint (shaders/shared/hair_grid.h): the 8 cells around a head-space point and
// their weights, the same for splatting and sampling. engine/core/hair/hair_grid_layout.cpp is the host's copy.
#ifndef HP_HAIR_GRID_GLSL
#define HP_HAIR_GRID_GLSL

// The cell below-left-front of q's cell-centre coordinates, and q's fraction past it.
void gridFootprint(vec3 q, vec4 originCell, out ivec3 base, out vec3 frac) {
  vec3 g = (q - originCell.xyz) / originCell.w - 0.5;
  vec3 lo = floor(g);
  base = ivec3(lo);
  frac = g - lo;
}

uint gridCellIndex(ivec3 c, uvec3 dims) { return (uint(c.z) * dims.y + uint(c.y)) * dims.x + uint(c.x); }

// Corner k (bit 0: x, 1: y, 2: z) of the footprint: its cell index, or -1 outside the grid, and its weight.
int gridCorner(ivec3 base, vec3 frac, uvec3 dims, uint k, out float weight) {
  ivec3 o = ivec3(int(k & 1u), int((k >> 1u) & 1u), int(k >> 2u));
  vec3 w = mix(1.0 - frac, frac, vec3(o));
  weight = w.x * w.y * w.z;
  ivec3 c = base + o;
  if (any(lessThan(c, ivec3(0))) || any(greaterThanEqual(c, ivec3(dims)))) return -1;
  return int(gridCellIndex(c, dims));
}
#endif
