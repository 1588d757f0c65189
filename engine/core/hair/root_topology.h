#pragma once
// Contract: triangulates strand roots that lie on a roughly spherical scalp (imported .hair models
// have roots but no scalp mesh). Each root is projected to the unit sphere around `center`; the convex
// hull of those directions is a spherical Delaunay-like triangulation of the roots. Hull triangles
// that do not belong to the scalp surface are dropped: those facing away from the center (the "lid"
// that closes an open scalp cap) and those far larger than typical (edge longer than maxEdgeFactor
// times the median longest edge). Roots that coincide with another root are in no triangle.
#include <glm/glm.hpp>

#include <cstdint>
#include <span>
#include <vector>

namespace hp {
struct RootTriangulationOptions {
  float maxEdgeFactor = 5.0f;   // drop triangles whose longest edge exceeds this * median
  float minFacing = 0.5f;       // drop triangles whose normal . centroid direction is below this
};

struct RootTriangulation {
  std::vector<glm::uvec3> triangles;  // root indices, counter-clockwise seen from outside
  std::uint32_t droppedLarge = 0;
  std::uint32_t droppedFacingAway = 0;
};

RootTriangulation triangulateRoots(std::span<const glm::vec3> roots, const glm::vec3& center,
                                   const RootTriangulationOptions& options = {});
}  // namespace hp
