#version 450
// Evaluates the Marschner S for rows of (L, V, T): the GPU side of the direct/paper/float accuracy
// checks. Interface: shaders/shared/brdf_eval.h.
#include "shared/brdf_eval.h"
#include "common.glsl"

layout(local_size_x = BRDF_EVAL_WORKGROUP_SIZE) in;

layout(std430, binding = BRDF_EVAL_BINDING_INPUT) readonly buffer Inputs { BrdfEvalInput rows[]; };
layout(std430, binding = BRDF_EVAL_BINDING_OUTPUT) writeonly buffer Outputs { vec4 results[]; };
layout(std140, binding = BRDF_EVAL_BINDING_PARAMS) readonly buffer Params { MarschnerParams marschner; };
#include "marschner.glsl"  // after `marschner`: its table functions read the block in place
layout(binding = BRDF_EVAL_BINDING_M) uniform sampler2D mTex;
layout(binding = BRDF_EVAL_BINDING_N0) uniform sampler2D n0Tex;
layout(binding = BRDF_EVAL_BINDING_N1) uniform sampler2D n1Tex;
layout(push_constant) uniform Push { BrdfEvalPush push; };

void main() {
  // Never gl_WorkGroupSize (lavapipe 22.3 would run one invocation per group); the grid may be 2D.
  uint i = hpThreadId(BRDF_EVAL_WORKGROUP_SIZE);
  if (i >= push.control.x) return;
  BrdfEvalInput row = rows[i];
  vec3 s = marschnerEvaluate(push.control.y, row.L.xyz, row.V.xyz, row.T.xyz, mTex, n0Tex, n1Tex,
                             marschner, row.T.w, row.V.w);
  results[i] = vec4(s, 0.0);
}
