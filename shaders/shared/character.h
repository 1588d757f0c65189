// Shared by GLSL and C++: a skinned character mesh on the device (docs/THEORY.md §8.7), posed every frame it
// is given a pose (compute/strands/character_pass.*):
//   1. character_skin.comp, one invocation per vertex: linear blend skinning of the rest vertex and normal by
//      the pose's bone matrices (head space), into the posed buffers (the normal's w, the scalp weight, kept);
//   2. the key buffer is filled with ~0u, then character_sdf_splat.comp, one invocation per triangle and z slice
//      of its box (counts.w slices: its longest edge and the band on either side, from the rest pose; lavapipe
//      ends a shader's loops after 65535 iterations in all), visits the grid nodes within
//      CHARACTER_SDF_BAND_CELLS cells of the posed triangle and lowers each node's key with
//      atomicMin: the float bits of the unsigned distance to the triangle with the lowest bit replaced by 1
//      inside or 0 outside (distances are >= 0, so their bits order as the floats do; the bit costs one ulp,
//      and on a tie outside wins). The side is that of the nearest point's normal: the face's inside the
//      face, the vertex's posed normal at a vertex, the sum of its two vertices' normals on an edge;
//   3. character_sdf_finish.comp, one invocation per row of nodes along x, writes the simulation's distance grid
//      (shared/sdf.h): minus or plus the distance, and where no triangle came near minus or plus the band, by the
//      side of the last node before it in the row that one did (the row starting outside: the grid is padded
//      beyond the body), so the interior past the band stays inside.
#ifndef HP_SHARED_CHARACTER_H
#define HP_SHARED_CHARACTER_H
#include "common.h"

HP_BEGIN
HP_CONST(uint, CHARACTER_WORKGROUP_SIZE, 64)
HP_CONST(uint, CHARACTER_SDF_BAND_CELLS, 4)
HP_CONST(uint, CHARACTER_MAX_BONES, 1024)       // 64 KiB of matrices: one vkCmdUpdateBuffer
HP_CONST(uint, CHARACTER_MAX_SLICE_NODES, 65535)  // nodes one splat invocation may visit (a slice of a box)
HP_CONST(uint, CHARACTER_BINDING_REST, 0)       // 2 vec4 per vertex: position (w 1), normal (w scalp weight)
HP_CONST(uint, CHARACTER_BINDING_SKIN, 1)       // CharacterSkin per vertex
HP_CONST(uint, CHARACTER_BINDING_BONES, 2)      // mat4 per bone
HP_CONST(uint, CHARACTER_BINDING_POSED, 3)      // vec4 position per vertex (w 1)
HP_CONST(uint, CHARACTER_BINDING_POSED_NORMALS, 4)  // vec4 normal per vertex (w the rest normal's)
HP_CONST(uint, CHARACTER_BINDING_TRIANGLES, 5)  // uvec4 per triangle (xyz vertex indices)
HP_CONST(uint, CHARACTER_BINDING_KEYS, 6)       // uint per grid node
HP_CONST(uint, CHARACTER_BINDING_SDF, 7)        // the simulation's distance grid (shared/sdf.h)

struct CharacterSkin {
  uvec4 bones;
  vec4 weights;  // summing to 1
};

// Push constants of the three passes.
struct CharacterParams {
  vec4 originCell;  // the grid: xyz node (0, 0, 0) in head space, w node spacing
  uvec4 dims;       // xyz nodes per axis, w nodes in all
  uvec4 counts;     // x vertices, y triangles, z band (cells), w z slices per triangle (the splat's invocations)
};
HP_END

#ifdef __cplusplus
static_assert(sizeof(hp::gpu::CharacterSkin) == 32);
static_assert(sizeof(hp::gpu::CharacterParams) == 48);
#endif
#endif
