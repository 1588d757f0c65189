// Shared by GLSL and C++: the guide simulation pass (docs/THEORY.md §2).
// Guide particles live in three storage buffers of vec4, P consecutive entries per guide, root first:
//   positions  xyz world position now (w = 1)
//   previous   xyz world position one substep ago (Verlet's implicit velocity)
//   rest       xyz rest position in head space, w = rest length of the segment ending here (0 at root)
// The frame block (std140 layout, read as a read-only storage buffer) is written by the host into the command buffer every frame.
// Scalp input (scalpMode): where each guide's root and rest pose are, as a per-guide "root matrix" that maps
// the head-space rest pose to the world (the rest pose is carried in the root frame, so the pull toward it
// works under skinning), interpolated over the substeps from its value at the frame's start to its end:
//   SIM_SCALP_RIGID        headFrom -> headTo for every guide
//   SIM_SCALP_ROOT_FRAMES  the application's per-guide frames (roots: 2 vec4 per guide, world position and
//                          unit quaternion xyzw); M = T(position) R(q) T(-rest root). Last frame's copy is
//                          kept in rootsPrev (written by the same invocation).
//   SIM_SCALP_BONES        linear blend skinning: M = sum_k weight_k bone_k, 4 bones per guide (skin), bone
//                          matrices at the frame's start in bones[0, boneCount), at its end in
//                          bones[boneCount, 2 boneCount)
// Colliders stay in head space (headFrom -> headTo) in every mode: spheres, then capsules.
#ifndef HP_SHARED_SIMULATE_H
#define HP_SHARED_SIMULATE_H
#include "common.h"

HP_BEGIN
HP_CONST(uint, SIM_WORKGROUP_SIZE, 64)       // one invocation per guide
HP_CONST(uint, SIM_MAX_PARTICLES, 64)        // per guide (GuideSet allows 2..64)
HP_CONST(uint, SIM_SPEC_PARTICLES, 0)        // specialization constant id: particles per guide
HP_CONST(uint, SIM_MAX_COLLIDERS, 32)
HP_CONST(uint, SIM_MAX_CAPSULES, 16)
HP_CONST(uint, SIM_MAX_BONES, 256)           // 2 x 256 mat4 fit one vkCmdUpdateBuffer (64 KiB)
HP_CONST(uint, SIM_SCALP_RIGID, 0)
HP_CONST(uint, SIM_SCALP_ROOT_FRAMES, 1)
HP_CONST(uint, SIM_SCALP_BONES, 2)
HP_CONST(uint, SIM_COLLISION_PASSES, 3)      // visits of every collider per constraint iteration
HP_CONST(uint, SIM_BINDING_FRAME, 0)
HP_CONST(uint, SIM_BINDING_POSITIONS, 1)
HP_CONST(uint, SIM_BINDING_PREVIOUS, 2)
HP_CONST(uint, SIM_BINDING_REST, 3)
HP_CONST(uint, SIM_BINDING_ROOTS, 4)         // the application's buffer (root frames mode)
HP_CONST(uint, SIM_BINDING_ROOTS_PREV, 5)
HP_CONST(uint, SIM_BINDING_BONES, 6)
HP_CONST(uint, SIM_BINDING_SKIN, 7)

struct SkinWeights {
  uvec4 bones;   // bone indices
  vec4 weights;  // summing to 1
};
HP_CONST(uint, SIM_BINDING_SDF, 8)           // the head's distance grid (shared/sdf.h), read only
HP_CONST(uint, SIM_BINDING_GRID, 9)          // the hair grid (shared/hair_grid.h), read only

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
  uint scalpMode;        // SIM_SCALP_*; particles per guide is the pipeline's specialization constant
  uint substeps;
  uint iterations;
  uint colliderCount;
  uint capsuleCount;
  uint boneCount;
  float localStiffness;  // SimulationParams::localStiffness (simulate.comp keepLocalShape)
  vec4 colliders[SIM_MAX_COLLIDERS];  // head space: xyz center, w radius
  vec4 capsules[2u * SIM_MAX_CAPSULES];  // head space: [2c] xyz end a, w radius; [2c + 1] xyz end b
  // The hair grid (shared/hair_grid.h), built from this frame's starting state in head space.
  vec4 gridOriginCell;   // xyz head-space corner of cell (0, 0, 0), w cell size
  uvec4 gridDims;        // xyz cells per axis; w = 1 when the grid acts this frame
  vec4 gridForces;       // x volume as a speed (volume x cell size / dt), y friction, z volumeTarget (unused here)
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
static_assert(offsetof(hp::gpu::SimFrame, capsules) == 224 + 16 * 32);
static_assert(offsetof(hp::gpu::SimFrame, gridOriginCell) == 224 + 16 * 32 + 16 * 32);
static_assert(sizeof(hp::gpu::SimFrame) == 224 + 16 * 32 + 16 * 32 + 3 * 16);
static_assert(sizeof(hp::gpu::SkinWeights) == 32);
#endif
#endif
