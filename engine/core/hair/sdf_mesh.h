#pragma once
// Contract: a signed distance grid from a closed triangle mesh (a collider: a body, a head). Exact
// point-triangle distances near the surface (every node within 1.5 cells of a triangle's box), then
// the nearest triangle propagated through the rest of the grid by eight fast sweeps (each node tries
// its neighbours' nearest triangles), and the sign from the parity of the mesh's crossings along +x
// through each node row (inside: odd). The grid pads the mesh's box by `padding` cells. cell <= 0
// picks one so the longest side has about 64 cells. Meant for closed meshes; an open one gets a sign
// that is only as good as its holes allow. Throws hp::Error for no triangles, a non-finite vertex,
// a grid past maxNodes, or near-surface work past 250M point-triangle tests (triangles that each span much
// of a fine grid). Deterministic.
#include <glm/glm.hpp>

#include <span>

#include "engine/core/hair/sdf_grid.h"

namespace hp {
SdfGrid meshSdf(std::span<const glm::vec3> positions, std::span<const glm::uvec3> triangles, float cell = 0.0f,
                std::uint32_t padding = 4, std::size_t maxNodes = std::size_t(1) << 23);

// The point of triangle abc nearest to p (by the region of the triangle's plane p projects into).
glm::vec3 closestPointOnTriangle(const glm::vec3& p, const glm::vec3& a, const glm::vec3& b, const glm::vec3& c);
// Distance from p to triangle abc.
float pointTriangleDistance(const glm::vec3& p, const glm::vec3& a, const glm::vec3& b, const glm::vec3& c);
}  // namespace hp
