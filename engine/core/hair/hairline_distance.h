#pragma once
// Contract: how far each triangle of a scalp triangulation lies from the hairline: the triangulation's
// open boundary (edges that one triangle uses alone) where no root lies beyond it. Gaps inside the hair (a
// parting left open, triangles dropped from an imported groom) have roots across them and are not
// hairline: an edge counts when no root lies within one edge length of the point one edge length out from
// its midpoint, in its triangle's plane. A triangle with a hairline edge is at the distance from its
// centroid to that edge's midpoint (the nearest, when it has several); every other triangle at the shortest
// path to one of those through neighbouring triangles (sharing an edge), centroid to centroid.
// Triangles with no path to a boundary (a closed scalp) and degenerate ones (a guide repeated) are at
// kNoHairline. Deterministic; pure geometry, no device. The groom's frizz grows toward the hairline with it
// (GroomSettings::frizzHairline, docs/THEORY.md "Groom detail").
#include <glm/glm.hpp>

#include <span>
#include <vector>

namespace hp {
inline constexpr float kNoHairline = 1e30f;

// One distance per triangle, in the roots' units. Triangles name roots by index (checked by the caller).
std::vector<float> hairlineDistances(std::span<const glm::vec3> roots, std::span<const glm::uvec3> triangles);
}  // namespace hp
