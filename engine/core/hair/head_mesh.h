#pragma once
#include <span>
// Contract: simple opaque meshes for the head: a UV ellipsoid, and their concatenation; and the check that a
// mesh's arrays agree (requireMeshShape). Every vertex
// of an ellipsoid built with radii <= r (per axis) lies inside the sphere of radius r at the same
// center, which is how the default head keeps its render mesh inside its colliders.
#include <glm/glm.hpp>

#include <cstdint>
#include <string>

#include "engine/core/hair/hair_asset.h"

namespace hp {
HeadMesh makeEllipsoidMesh(const glm::vec3& center, const glm::vec3& radii, std::uint32_t slices = 32,
                           std::uint32_t stacks = 16);
void appendMesh(HeadMesh& into, const HeadMesh& part);

// Throws hp::Error "<where>: ..." naming the first disagreement: indices that are not whole triangles, not
// one normal per position, scalp weights neither none nor one per position, an index past the positions.
void requireMeshShape(const HeadMesh& mesh, const std::string& where);

// Sets mesh.scalp: 1 within about one root spacing of the nearest guide root, fading to 0 at three
// spacings, so the skin under the hair takes the hair's colour instead of showing between strands.
// The spacing is the mean nearest-neighbour distance of (a sample of) the roots.
void markScalp(HeadMesh& mesh, std::span<const glm::vec3> roots);
}  // namespace hp
