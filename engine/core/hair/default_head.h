#pragma once
// Contract: the procedural default head that `make demo` renders, in metres, Y up, face toward +Z,
// origin at the center of the cranium: one signed distance field (head_sdf.h) sampled on a grid in a
// narrow band (the hair's collider), meshed at load time by marching cubes (render mesh). The scalp is the field's
// surface above the hairline (crown, back and sides; not the face or the ears), 1,000-4,000
// vertices, one guide each. Guides are long, parted on the crown, laid along the head, combed back
// from the forehead and behind the ears, and slid over the field, so the rest pose already reads
// as a head of hair and stays off the face. The geometry is built once per process (deterministic).
#include <cstdint>
#include <memory>

#include "engine/core/hair/guide_growth.h"
#include "engine/core/hair/hair_asset.h"
#include "engine/core/hair/mesh_simplify.h"
#include "engine/core/hair/narrow_band.h"
#include "engine/core/hair/scalp_mesh.h"
#include "engine/core/hair/sdf_grid.h"
#include "engine/core/hair/strand_topology.h"

namespace hp {
inline constexpr float kDefaultHeadCell = 0.004f;  // grid spacing of the head's field (m)
// Nodes closer than this to the surface hold the field's exact value; farther ones a correctly signed
// bound (narrow_band.h). Three cells: a pearl's clearance plus the collision gradient's half-cell probes.
inline constexpr float kDefaultHeadBand = 3.0f * kDefaultHeadCell;
inline constexpr std::uint32_t kDefaultHeadBrick = 4;  // cells per brick side of the narrow band
// The render mesh is cut on every kDefaultHeadMeshStride-th grid node. 2 (8 mm cells, 16.7k triangles)
// looked worse in a close-up of the face (the lips cut flat, shallower eye sockets, a lumpier jaw), so
// it stays 1 (66.5k triangles) and is then simplified where that shows nothing (mesh_simplify.h): within
// kDefaultHeadMeshError of its surface, its triangles' vertex normals within kDefaultHeadMeshNormalDegrees
// (wider, and a close-up shows lines where the shading bends across a long triangle), the hairline whole:
// ~20k triangles (docs/PERFORMANCE.md "Default head and distance grids"). The collider keeps the 4 mm grid.
inline constexpr std::uint32_t kDefaultHeadMeshStride = 1;
inline constexpr float kDefaultHeadMeshError = 0.0005f;       // m
inline constexpr float kDefaultHeadMeshNormalDegrees = 15.0f;
inline constexpr SimplifyOptions kDefaultHeadSimplify{kDefaultHeadMeshError, kDefaultHeadMeshNormalDegrees, 0};

// The growth options the default head uses unless a scene overrides them.
GrowthOptions defaultHeadGrowth();

// The scalp alone (vertex count grows with `sphereSamples`: about half of them are on the scalp).
ScalpMesh makeDefaultScalp(std::uint32_t sphereSamples = 5000);
// The head's field on a kDefaultHeadCell grid (exact within kDefaultHeadBand), and the
// marching-cubes mesh of it on every kDefaultHeadMeshStride-th node (scalp not marked).
NarrowBandGrid makeDefaultHeadField();
HeadMesh makeDefaultHeadMesh(const NarrowBandGrid& field);
// The render mesh the default head draws: the marching-cubes mesh, its scalp marked, simplified (through the
// process's disk cache, HAIRPIPE_CACHE_DIR, when it has one).
HeadMesh simplifyDefaultHeadMesh(const HeadMesh& marked);

HairAsset buildDefaultHeadAsset(const GrowthOptions& growth = defaultHeadGrowth(),
                                const DensityOptions& density = {});
}  // namespace hp
