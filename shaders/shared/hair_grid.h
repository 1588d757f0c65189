// Shared by GLSL and C++: the hair density / velocity grid (docs/THEORY.md §2.7) that gives guides a volume
// and a friction between them. One grid per simulated instance, in head space, cubic cells; cell c = (i, j, k)
// is i + dims.x (j + dims.y k), its centre at origin + (c + 0.5) cellSize. A point's weight goes to the 8
// cells around it (trilinear, cells outside the grid dropped): engine/core/hair/hair_grid_layout.cpp splats
// the same way on the host.
// Per frame, before the simulation (compute/strands/hair_grid_pass.*):
//   1. the accumulation buffer is cleared,
//   2. hair_grid_splat.comp adds every free guide particle's weight (1 per particle; the roots, pinned to the
//      scalp, neither flow nor are pushed, so they are left out) and its weight times its velocity (in units of
//      maxSpeed) as fixed-point integers (deterministic: integer sums do not depend on the order), 4 ints per
//      cell; a particle that is not finite is left out too,
//   3. hair_grid_resolve.comp turns them into 2 vec4 per cell, read by simulate.comp:
//        [2c]     xyz density times velocity (world, scene units / s), w density
//        [2c + 1] xyz gradient of the pressure (head space, per scene unit), w pressure
//      where density is relative to the rest pose's (weight-averaged) mean cell density and the pressure is
//      max(density - target, 0); and raises the frame's peak density (float bits, atomicMax) in peak[0].
#ifndef HP_SHARED_HAIR_GRID_H
#define HP_SHARED_HAIR_GRID_H
#include "common.h"

HP_BEGIN
HP_CONST(uint, GRID_WORKGROUP_SIZE, 64)
HP_CONST(uint, GRID_ACCUM_INTS, 4)         // per cell: weight, momentum x, y, z
HP_CONST(uint, GRID_CELL_VEC4S, 2)         // per cell in the resolved grid
HP_CONST(float, GRID_MAX_FIXED_POINT, 65536.0f)  // integer units per unit of weight, at most
HP_CONST(float, GRID_VOLUME_BLEND, 0.5f)   // share of the outflow speed's shortfall made up per substep
HP_CONST(uint, GRID_MIN_RESOLUTION, 4)
HP_CONST(uint, GRID_MAX_RESOLUTION, 128)
HP_CONST(uint, GRID_BINDING_POSITIONS, 0)
HP_CONST(uint, GRID_BINDING_PREVIOUS, 1)
HP_CONST(uint, GRID_BINDING_ACCUM, 2)
HP_CONST(uint, GRID_BINDING_CELLS, 3)
HP_CONST(uint, GRID_BINDING_PEAK, 4)

// Push constants of both grid passes (128 bytes, the guaranteed minimum).
struct GridParams {
  mat4 worldToGrid;   // world -> head space at the frame's start (where the particles are now)
  vec4 originCell;    // xyz head-space corner of cell (0, 0, 0), w cell size
  uvec4 dims;         // xyz cells per axis, w particle count
  vec4 fixedPoint;    // x integer units per unit of weight, y its inverse, z 1 / substep time, w maxSpeed
  vec4 density;       // x 1 / rest mean density (weight per cell), y target (relative), z particles per guide
                      // (the roots are left out), w unused
};
HP_END

#ifdef __cplusplus
static_assert(sizeof(hp::gpu::GridParams) == 128);
#endif
#endif
