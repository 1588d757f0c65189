#pragma once
// Contract: how distant light reaches a head mesh's skin past the mesh itself, per vertex, in the mesh's
// own space (docs/SHADING.md "The skin's indirect light"). With L the radiance of the light around the
// head as the 9 real SH of order <= 2 (shaders/shared/environment.h's basis), a vertex receives
//   direct irradiance   E0 = sum_i L_i direct_i        (the sky it sees: its cosine lobe, less what the mesh hides)
//   bounced irradiance  E1 = albedo sum_i L_i bounce_i (one diffuse bounce off the mesh, per unit albedo)
// with direct_i = A_l Y_i(n) - occluded_i: `occluded` is what the mesh hides of the lobe, the part a posed
// (skinned) vertex can keep while its own lobe turns with its normal. `blocked` is the cosine-weighted share
// of its hemisphere the mesh covers, `reflecting` the share covered by skin that passes light on (front
// faces, not the scalp under the hair). Rays are cast from every
// vertex (cosine-distributed, stratified, a fixed seed) against the mesh (TriangleBvh); each vertex's
// estimates are then averaged with its neighbours' a few times along the mesh's edges, which removes most of
// the few rays' noise and keeps the features larger than a few edges (a jaw, a neck, an ear). A ray that
// meets a triangle's back face (inside a model, through a hole) is blocked and brings nothing back, and so
// does the scalp under the hair (HeadMesh::scalp: the hair over it takes its light).
// Deterministic: the same mesh gives the same numbers on any thread count.
#include <array>
#include <cstdint>
#include <vector>

#include "engine/core/hair/hair_asset.h"

namespace hp {
struct SkinTransferOptions {
  std::uint32_t raysPerVertex = 16;  // in [1, 1024]
  std::uint32_t smoothingPasses = 4;  // neighbour averages, in [0, 64]
};

struct SkinTransfer {
  std::vector<std::array<float, 9>> direct;    // per vertex
  std::vector<std::array<float, 9>> occluded;  // per vertex: A_l Y_i(n) - direct_i
  std::vector<std::array<float, 9>> bounce;    // per vertex, per unit albedo of the mesh
  std::vector<float> blocked;                  // per vertex, in [0, 1]
  std::vector<float> reflecting;               // per vertex, in [0, blocked]
};

// mesh: as HeadMesh says (indices checked: hp::Error on one out of range). An empty mesh gives empty arrays.
SkinTransfer computeSkinTransfer(const HeadMesh& mesh, const SkinTransferOptions& options = {});
}  // namespace hp
