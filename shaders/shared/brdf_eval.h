// Shared by GLSL and C++: the interface of shaders/brdf_eval.comp, a kernel that evaluates the
// Marschner S for rows of (L, V, T) so the GPU modes can be compared with the CPU reference.
//   binding 0 (std430 buffer, readonly): BrdfEvalInput rows[]   (xyz; T.w = the fibre's tilt offset, radians;
//     V.w = its beta_R scale)
//   binding 1 (std430 buffer, writeonly): vec4 S[]              (rgb = S, a = 0)
//   binding 2 (std140 uniform): MarschnerParams (shaders/shared/marschner.h)
//   binding 3, 4, 5: combined image samplers M, N0, N1 (linear, clamp to edge). All three must be
//     bound in every mode because the mode is a run-time branch: bind any 1x1 texture to the unused.
//   push constant BrdfEvalPush: control.x = row count, control.y = MARSCHNER_MODE_*.
// Dispatch with ComputePipeline::dispatch(count) (the grid may fold into 2D; the kernel uses
// hpThreadId). Host side: tools/brdf_evaluator.h.
#ifndef HP_SHARED_BRDF_EVAL_H
#define HP_SHARED_BRDF_EVAL_H

#include "marschner.h"

HP_BEGIN

HP_CONST(uint, BRDF_EVAL_WORKGROUP_SIZE, 64u)
HP_CONST(uint, BRDF_EVAL_BINDING_INPUT, 0u)
HP_CONST(uint, BRDF_EVAL_BINDING_OUTPUT, 1u)
HP_CONST(uint, BRDF_EVAL_BINDING_PARAMS, 2u)
HP_CONST(uint, BRDF_EVAL_BINDING_M, 3u)
HP_CONST(uint, BRDF_EVAL_BINDING_N0, 4u)
HP_CONST(uint, BRDF_EVAL_BINDING_N1, 5u)

struct BrdfEvalInput {
  vec4 L;  // toward the light
  vec4 V;  // xyz = toward the eye, w = the fibre's beta_R scale (physical and direct modes; 1: the material's)
  vec4 T;  // xyz = fibre tangent, w = its cuticle tilt offset from alpha_R (radians; physical and direct modes)
};

struct BrdfEvalPush {
  uvec4 control;  // x = row count, y = MARSCHNER_MODE_*, zw = 0
};

HP_END

#endif
