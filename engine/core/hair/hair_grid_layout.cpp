#include "engine/core/hair/hair_grid_layout.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "engine/core/error.h"
#include "shaders/shared/hair_grid.h"

namespace hp {
HairGridLayout hairGridLayout(std::span<const glm::vec4> rest, std::uint32_t particlesPerGuide,
                              std::uint32_t resolution, float pearlRadius) {
  if (resolution < gpu::GRID_MIN_RESOLUTION || resolution > gpu::GRID_MAX_RESOLUTION)
    throw Error("hair grid: resolution must be in [" + std::to_string(gpu::GRID_MIN_RESOLUTION) + ", " +
                std::to_string(gpu::GRID_MAX_RESOLUTION) + "], got " + std::to_string(resolution));
  if (particlesPerGuide == 0 || rest.size() < particlesPerGuide) throw Error("hair grid: no guides");
  glm::vec3 lo(1e30f), hi(-1e30f);
  float longest = 0.0f;
  for (std::size_t g = 0; g + particlesPerGuide <= rest.size(); g += particlesPerGuide) {
    lo = glm::min(lo, glm::vec3(rest[g]));
    hi = glm::max(hi, glm::vec3(rest[g]));
    float length = 0.0f;
    for (std::uint32_t i = 1; i < particlesPerGuide; ++i) length += rest[g + i].w;
    longest = std::max(longest, length);
  }
  const float reach = longest + pearlRadius;
  lo -= glm::vec3(reach);
  hi += glm::vec3(reach);
  const glm::vec3 extent = hi - lo;
  HairGridLayout layout;
  layout.origin = lo;
  layout.cellSize = std::max(std::max(extent.x, extent.y), std::max(extent.z, 1e-6f)) / float(resolution);
  for (int a = 0; a < 3; ++a)
    layout.dims[a] = std::clamp(std::uint32_t(std::ceil(extent[a] / layout.cellSize)), 1u, resolution);
  return layout;
}

std::vector<double> splatHairGrid(std::span<const glm::vec3> points, const HairGridLayout& layout,
                                  std::span<const double> values) {
  if (!values.empty() && values.size() != points.size())
    throw Error("hair grid: " + std::to_string(values.size()) + " values for " + std::to_string(points.size()) + " points");
  std::vector<double> cells(layout.cellCount(), 0.0);
  for (std::size_t i = 0; i < points.size(); ++i) {
    const glm::vec3& p = points[i];
    const double value = values.empty() ? 1.0 : values[i];
    const glm::vec3 g = (p - layout.origin) / layout.cellSize - 0.5f;
    const glm::vec3 base = glm::floor(g);
    const glm::vec3 frac = g - base;
    for (int k = 0; k < 8; ++k) {
      const glm::ivec3 o(k & 1, (k >> 1) & 1, k >> 2);
      const glm::ivec3 c = glm::ivec3(base) + o;
      if (glm::any(glm::lessThan(c, glm::ivec3(0))) || glm::any(glm::greaterThanEqual(c, glm::ivec3(layout.dims))))
        continue;
      const glm::vec3 w = glm::mix(1.0f - frac, frac, glm::vec3(o));
      cells[layout.cellIndex(c)] += value * w.x * w.y * w.z;
    }
  }
  return cells;
}

std::vector<glm::vec3> freeParticles(std::span<const glm::vec4> particles, std::uint32_t particlesPerGuide) {
  std::vector<glm::vec3> out;
  for (std::size_t i = 0; i < particles.size(); ++i)
    if (particlesPerGuide > 0 && i % particlesPerGuide != 0) out.emplace_back(particles[i]);
  return out;
}

double weightedMeanDensity(std::span<const double> cellWeights) {
  double sum = 0.0, sumSquares = 0.0;
  for (double w : cellWeights) {
    sum += w;
    sumSquares += w * w;
  }
  return sum > 0.0 ? sumSquares / sum : 0.0;
}

float hairGridFixedPoint(std::uint64_t particles) {
  // A cell's sum is at most particles x (scale + 0.5) (rounding of each contribution): stay under 2^31 - 1.
  const double most = double(0x7fffffff) / double(std::max<std::uint64_t>(particles, 1)) - 1.0;
  if (most < 1.0)
    throw Error("hair grid: " + std::to_string(particles) + " particles are more than its 32-bit cells can sum");
  return float(std::min(std::floor(most), double(gpu::GRID_MAX_FIXED_POINT)));
}
}  // namespace hp
