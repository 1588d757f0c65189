#pragma once
// Contract: the 3D convex hull of a point set (Quickhull, double precision). Returns triangles of
// input indices, counter-clockwise seen from outside. Points within a relative tolerance of the hull
// (duplicates, points on a face) are not hull vertices. Returns an empty list when the points span
// no volume (fewer than 4 points, all coplanar). Deterministic for a given input order.
#include <glm/glm.hpp>

#include <span>
#include <vector>

namespace hp {
std::vector<glm::uvec3> convexHull(std::span<const glm::dvec3> points);
}  // namespace hp
