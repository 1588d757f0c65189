#include "samples/tools/host/interaction_stats.h"

#include <cmath>
#include <map>
#include <tuple>
#include <vector>

namespace hp {
VelocitySpread velocitySpreadInCells(std::span<const glm::vec4> positions, std::span<const glm::vec4> previous,
                                     std::uint32_t particlesPerGuide, const glm::mat4& head, double cellSize,
                                     double substepSeconds) {
  struct Cell {
    glm::dvec3 sum{0.0};
    double sumSquares = 0.0;
    std::size_t count = 0;
  };
  std::map<std::tuple<long, long, long>, Cell> cells;
  const glm::mat4 toHead = glm::inverse(head);
  for (std::size_t i = 0; i < positions.size() && i < previous.size(); ++i) {
    if (particlesPerGuide == 0 || i % particlesPerGuide == 0) continue;  // roots follow the scalp
    const glm::dvec3 v = glm::dvec3(glm::vec3(positions[i]) - glm::vec3(previous[i])) / substepSeconds;
    const glm::dvec3 q = glm::dvec3(glm::vec3(toHead * glm::vec4(glm::vec3(positions[i]), 1.0f))) / cellSize;
    if (!std::isfinite(q.x + q.y + q.z + v.x + v.y + v.z)) continue;
    Cell& c = cells[{long(std::floor(q.x)), long(std::floor(q.y)), long(std::floor(q.z))}];
    c.sum += v;
    c.sumSquares += glm::dot(v, v);
    ++c.count;
  }
  VelocitySpread s;
  double within = 0.0, overall = 0.0;
  for (const auto& [key, c] : cells) {
    if (c.count < 4) continue;
    const glm::dvec3 mean = c.sum / double(c.count);
    within += c.sumSquares - double(c.count) * glm::dot(mean, mean);
    overall += c.sumSquares;
    s.particles += c.count;
  }
  if (s.particles > 0) {
    s.withinCells = within / double(s.particles);
    s.overall = overall / double(s.particles);
  }
  return s;
}

CloseParticles closeNeighbourParticles(std::span<const glm::vec4> positions, std::uint32_t particlesPerGuide,
                                       double rootRadius, double separation) {
  CloseParticles r;
  if (particlesPerGuide < 2) return r;
  const std::size_t guides = positions.size() / particlesPerGuide;
  auto at = [&](std::size_t g, std::uint32_t i) { return glm::dvec3(glm::vec3(positions[g * particlesPerGuide + i])); };
  std::size_t close = 0;
  for (std::size_t a = 0; a < guides; ++a)
    for (std::size_t b = 0; b < guides; ++b) {
      if (a == b || glm::length(at(a, 0) - at(b, 0)) >= rootRadius) continue;
      for (std::uint32_t i = 1; i < particlesPerGuide; ++i) {
        bool near = false;
        for (std::uint32_t j = 1; j < particlesPerGuide && !near; ++j) near = glm::length(at(a, i) - at(b, j)) < separation;
        close += near ? 1 : 0;
        ++r.checked;
      }
    }
  r.fraction = r.checked ? double(close) / double(r.checked) : 0.0;
  return r;
}
}  // namespace hp
