#pragma once
// Contract: where an instance's hair grid lies (docs/THEORY.md §2.7, shaders/shared/hair_grid.h) and the
// host's copy of its trilinear splat. The grid covers, in head space, every place a guide particle can reach:
// the roots' box grown by the longest guide and the pearl radius, in cubic cells with `resolution` cells
// along its longest side. The rest mean density (weight-averaged cell weight of the rest pose's free
// particles) is the unit in which the device grid's densities and the volume target are expressed.
#include <glm/glm.hpp>

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace hp {
struct HairGridLayout {
  glm::vec3 origin{0.0f};  // head-space corner of cell (0, 0, 0)
  float cellSize = 1.0f;
  glm::uvec3 dims{1u};
  std::uint32_t cellCount() const { return dims.x * dims.y * dims.z; }
  // Cell c's index, x fastest (shaders/hair_grid.glsl gridCellIndex).
  std::size_t cellIndex(const glm::ivec3& c) const { return (std::size_t(c.z) * dims.y + c.y) * dims.x + c.x; }
};

// `rest`: head-space particles (xyz; w the rest length of the segment ending there), P per guide, root first.
// Throws hp::Error on a resolution outside [GRID_MIN_RESOLUTION, GRID_MAX_RESOLUTION] or no guides.
HairGridLayout hairGridLayout(std::span<const glm::vec4> rest, std::uint32_t particlesPerGuide,
                              std::uint32_t resolution, float pearlRadius);

// Each point's value (1 when `values` is empty) spread over the 8 cells around it (trilinear; cells outside
// dropped), per cell.
std::vector<double> splatHairGrid(std::span<const glm::vec3> points, const HairGridLayout& layout,
                                  std::span<const double> values = {});

// The particles the grid holds: every one but the roots (P per guide, root first), in order.
std::vector<glm::vec3> freeParticles(std::span<const glm::vec4> particles, std::uint32_t particlesPerGuide);

// sum(w^2) / sum(w) over cells: the density the average particle sees (0 for an empty grid).
double weightedMeanDensity(std::span<const double> cellWeights);

// Fixed-point units per unit of weight for `particles` splatted particles: the most that cannot overflow
// a 32-bit cell sum (each particle adds at most one unit of weight plus rounding), at most
// GRID_MAX_FIXED_POINT. Throws hp::Error when even one unit would overflow.
float hairGridFixedPoint(std::uint64_t particles);
}  // namespace hp
