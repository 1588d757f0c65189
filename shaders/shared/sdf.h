// Shared by GLSL and C++: a signed distance grid on the device (engine/core/hair/sdf_grid.h), one storage
// buffer: this header, then the node values as floats (x fastest, then y, then z), read by
// shaders/sdf_collide.glsl. An absent grid is a header with present = 0 and one padding value.
#ifndef HP_SHARED_SDF_H
#define HP_SHARED_SDF_H
#include "common.h"

HP_BEGIN
HP_CONST(uint, SDF_COLLISION_STEPS, 3)  // pushes along the gradient per particle per constraint iteration
// A distance field's gradient has length ~1. Where the trilinear interpolant's own is shorter than this, the cell
// spans the middle of a feature thinner than two cells (the nodes on its two sides are equal, so the interpolant is
// flat across it), and the push takes central differences over the neighbouring cells instead.
HP_CONST(float, SDF_FLAT_GRADIENT, 0.5f)

struct SdfHeader {
  vec4 originCell;  // xyz position of node (0, 0, 0) in head space, w node spacing
  uvec4 dims;       // xyz nodes per axis (each >= 2), w = 1 when a grid is present
};
HP_END

#ifdef __cplusplus
static_assert(sizeof(hp::gpu::SdfHeader) == 32);  // the values start at byte 32 (std430)
#endif
#endif
