#include "engine/core/hair/sdf_grid.h"

#include <algorithm>
#include <cmath>
#include <string>

#include "engine/core/error.h"

namespace hp {
float SdfGrid::sample(const glm::vec3& p) const {
  const glm::vec3 clamped = glm::clamp(p, origin, upper());
  const float outside = glm::length(p - clamped);
  const glm::vec3 g = (clamped - origin) / cell;
  const glm::uvec3 i0 = glm::min(glm::uvec3(g), dims - 2u);
  const glm::vec3 t = g - glm::vec3(i0);
  auto v = [&](std::uint32_t dx, std::uint32_t dy, std::uint32_t dz) { return at(i0.x + dx, i0.y + dy, i0.z + dz); };
  const float x00 = glm::mix(v(0, 0, 0), v(1, 0, 0), t.x), x10 = glm::mix(v(0, 1, 0), v(1, 1, 0), t.x);
  const float x01 = glm::mix(v(0, 0, 1), v(1, 0, 1), t.x), x11 = glm::mix(v(0, 1, 1), v(1, 1, 1), t.x);
  return glm::mix(glm::mix(x00, x10, t.y), glm::mix(x01, x11, t.y), t.z) + outside;
}

glm::vec3 SdfGrid::gradient(const glm::vec3& p) const {
  const float h = 0.5f * cell;
  return glm::vec3(sample(p + glm::vec3(h, 0, 0)) - sample(p - glm::vec3(h, 0, 0)),
                   sample(p + glm::vec3(0, h, 0)) - sample(p - glm::vec3(0, h, 0)),
                   sample(p + glm::vec3(0, 0, h)) - sample(p - glm::vec3(0, 0, h))) /
         (2.0f * h);
}

SdfGrid gridCovering(const glm::vec3& lo, const glm::vec3& hi, float cell, std::size_t maxNodes) {
  if (!(cell > 0.0f) || !std::isfinite(cell)) throw Error("distance grid: the cell size must be positive");
  const glm::vec3 extent = hi - lo;
  if (!(extent.x > 0.0f && extent.y > 0.0f && extent.z > 0.0f) || !std::isfinite(glm::length(extent)))
    throw Error("distance grid: the box is empty or not finite");
  const glm::dvec3 cells = glm::ceil(glm::dvec3(extent) / double(cell));
  if (cells.x * cells.y * cells.z > double(maxNodes))
    throw Error("distance grid: " + std::to_string(cells.x * cells.y * cells.z) + " nodes needed, at most " +
                std::to_string(maxNodes) + " allowed (use a larger cell)");
  SdfGrid g;
  g.cell = cell;
  g.dims = glm::uvec3(cells) + 1u;
  g.origin = 0.5f * (lo + hi) - 0.5f * cell * glm::vec3(g.dims - 1u);
  g.values.resize(std::size_t(g.dims.x) * g.dims.y * g.dims.z);
  return g;
}

SdfGrid sampleField(const DistanceFunction& f, const glm::vec3& lo, const glm::vec3& hi, float cell,
                    std::size_t maxNodes) {
  SdfGrid g = gridCovering(lo, hi, cell, maxNodes);
  for (std::uint32_t k = 0; k < g.dims.z; ++k)
    for (std::uint32_t j = 0; j < g.dims.y; ++j)
      for (std::uint32_t i = 0; i < g.dims.x; ++i) g.values[g.index(i, j, k)] = f(g.node(i, j, k));
  return g;
}
}  // namespace hp
