// Shared by GLSL and C++: the guide simulation pass (REFERENCES.md §2).
// Guide particles live in three storage buffers of vec4, P consecutive entries per guide, root first:
//   positions  xyz world position now (w = 1)
//   previous   xyz world position one substep ago (Verlet's implicit velocity)
//   rest       xyz rest position in head space, w = rest length of the segment ending here (0 at root)
// The frame block (std140 UBO) is written by the host into the command buffer every frame.
#ifndef HP_SHARED_SIMULATE_H
#define HP_SHARED_SIMULATE_H
#include "common.h"

HP_BEGIN
HP_CONST(uint, SIM_WORKGROUP_SIZE, 64)       // one invocation per guide
HP_CONST(uint, SIM_MAX_PARTICLES, 64)        // per guide (GuideSet allows 2..64)
HP_CONST(uint, SIM_SPEC_PARTICLES, 0)        // specialization constant id: particles per guide
HP_CONST(uint, SIM_MAX_COLLIDERS, 32)
HP_CONST(uint, SIM_COLLISION_PASSES, 3)      // visits of every collider per constraint iteration
HP_CONST(uint, SIM_BINDING_FRAME, 0)
HP_CONST(uint, SIM_BINDING_POSITIONS, 1)
HP_CONST(uint, SIM_BINDING_PREVIOUS, 2)
HP_CONST(uint, SIM_BINDING_REST, 3)
HP_CONST(uint, SIM_BINDING_SDF, 4)           // the head's distance grid (shared/sdf.h), read only

struct SimFrame {
  mat4 headFrom;         // head-to-world transform at the start of the frame
  mat4 headTo;           // ... and at its end; substeps interpolate between the two
  vec4 gravity;          // xyz acceleration; w = substep time step h
  vec4 wind;             // xyz = direction * strength (acceleration); w = gust amplitude [0, 1]
  float damping;         // fraction of velocity removed per substep
  float pearlRadius;     // r_p
  float stiffness;       // pull toward the rest pose at the first free particle
  float stiffnessFalloff;
  float maxSpeed;        // scene units per second
  float time;            // seconds at the start of the frame (wind gusts)
  float gustFrequency;   // Hz
  uint teleport;         // 1: carry every particle rigidly with the head this frame
  uint guideCount;
  uint pad3;             // particles per guide is the pipeline's specialization constant, not a field
  uint substeps;
  uint iterations;
  uint colliderCount;
  uint pad0;
  uint pad1;
  uint pad2;
  vec4 colliders[SIM_MAX_COLLIDERS];  // head space: xyz center, w radius
};
HP_END

#ifdef __cplusplus
#include <cstddef>
static_assert(offsetof(hp::gpu::SimFrame, gravity) == 128);
static_assert(offsetof(hp::gpu::SimFrame, damping) == 160);
static_assert(offsetof(hp::gpu::SimFrame, maxSpeed) == 176);
static_assert(offsetof(hp::gpu::SimFrame, guideCount) == 192);
static_assert(offsetof(hp::gpu::SimFrame, colliderCount) == 208);
static_assert(offsetof(hp::gpu::SimFrame, colliders) == 224);
static_assert(sizeof(hp::gpu::SimFrame) == 224 + 16 * 32);
#endif
#endif
