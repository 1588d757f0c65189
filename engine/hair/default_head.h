#pragma once
// Contract: the procedural default head that `make demo` renders, in metres, Y up, face toward +Z,
// origin at the center of the cranium. The scalp is the part of the cranium ellipsoid behind a
// hairline (crown, back and sides; not the face), 1,000-4,000 vertices, one guide each. Guides are
// long and grown with a downward/backward bend (combed back from the forehead) and slid over the
// colliders, so the rest pose already reads as a head of hair; the simulation settles it further.
// Colliders: cranium, face, neck (2), upper back and shoulders (2). The head render mesh is one
// ellipsoid inside each collider, so strands kept outside the colliders stay outside the mesh.
#include <cstdint>

#include "engine/hair/guide_growth.h"
#include "engine/hair/hair_asset.h"
#include "engine/hair/scalp_mesh.h"
#include "engine/hair/strand_topology.h"

namespace hp {
// The growth options the default head uses unless a scene overrides them.
GrowthOptions defaultHeadGrowth();

// The scalp alone (vertex count grows with `sphereSamples`: about half of them are on the scalp).
ScalpMesh makeDefaultScalp(std::uint32_t sphereSamples = 5000);
std::vector<SphereCollider> defaultHeadColliders();
HeadMesh makeDefaultHeadMesh();

HairAsset buildDefaultHeadAsset(const GrowthOptions& growth = defaultHeadGrowth(),
                                const DensityOptions& density = {});
}  // namespace hp
