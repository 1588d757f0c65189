#pragma once
// Contract: measures of how guides interact, from a readback of their state (outside the frame loop): how
// coherent the motion is inside small cells (what the hair grid's friction raises) and how often guides that
// grow side by side pass through each other (what its volume lowers). Used by `hairpipe simulate --json` and
// the tests; docs/THEORY.md §2.7.
#include <glm/glm.hpp>

#include <cstdint>
#include <span>

namespace hp {
// Free particles binned into cubes of `cellSize` in head space (inverse(head)); per cube with at least 4
// particles, the mean squared deviation of their velocities from the cube's mean (velocity: position minus
// previous over `substepSeconds`), averaged over those particles; and the mean squared velocity over the same
// particles, to compare against.
struct VelocitySpread {
  double withinCells = 0.0;  // (scene units / s)^2
  double overall = 0.0;      // mean |v|^2 of the particles counted
  std::size_t particles = 0;
};
VelocitySpread velocitySpreadInCells(std::span<const glm::vec4> positions, std::span<const glm::vec4> previous,
                                     std::uint32_t particlesPerGuide, const glm::mat4& head, double cellSize,
                                     double substepSeconds);

// Over every pair of guides whose roots are within `rootRadius` of each other, for every free particle of
// the first, whether some free particle of the second is closer than `separation`: the fraction that are.
struct CloseParticles {
  double fraction = 0.0;
  std::size_t checked = 0;  // particle tests made
};
CloseParticles closeNeighbourParticles(std::span<const glm::vec4> positions, std::uint32_t particlesPerGuide,
                                       double rootRadius, double separation);
}  // namespace hp
