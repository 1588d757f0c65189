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

namespace {
using Bin = std::tuple<long, long, long>;

Bin binOf(const glm::dvec3& p, double size) {
  return {long(std::floor(p.x / size)), long(std::floor(p.y / size)), long(std::floor(p.z / size))};
}

// Guides by the bin of rootRadius their root falls in, so neighbours are found in the 27 bins around.
std::map<Bin, std::vector<std::size_t>> binRoots(std::span<const glm::vec4> positions, std::uint32_t p, double size) {
  std::map<Bin, std::vector<std::size_t>> bins;
  for (std::size_t g = 0; g < positions.size() / p; ++g) {
    const glm::dvec3 root = glm::dvec3(glm::vec3(positions[g * p]));
    if (std::isfinite(root.x + root.y + root.z)) bins[binOf(root, size)].push_back(g);
  }
  return bins;
}

// How many free particles of guide a have a free particle of guide b closer than `separation`.
std::size_t closeParticlesOf(std::span<const glm::vec4> positions, std::uint32_t p, std::size_t a, std::size_t b,
                             double separation) {
  auto at = [&](std::size_t g, std::uint32_t i) { return glm::dvec3(glm::vec3(positions[g * p + i])); };
  std::size_t close = 0;
  for (std::uint32_t i = 1; i < p; ++i) {
    bool near = false;
    for (std::uint32_t j = 1; j < p && !near; ++j) near = glm::length(at(a, i) - at(b, j)) < separation;
    close += near ? 1 : 0;
  }
  return close;
}
}  // namespace

CloseParticles closeNeighbourParticles(std::span<const glm::vec4> positions, std::uint32_t particlesPerGuide,
                                       double rootRadius, double separation) {
  CloseParticles r;
  if (particlesPerGuide < 2 || !(rootRadius > 0.0)) return r;
  const std::uint32_t p = particlesPerGuide;
  auto root = [&](std::size_t g) { return glm::dvec3(glm::vec3(positions[g * p])); };
  const auto bins = binRoots(positions, p, rootRadius);
  std::size_t close = 0;
  for (const auto& [bin, members] : bins)
    for (std::size_t a : members)
      for (long dz = -1; dz <= 1; ++dz)
        for (long dy = -1; dy <= 1; ++dy)
          for (long dx = -1; dx <= 1; ++dx) {
            const auto it = bins.find({std::get<0>(bin) + dx, std::get<1>(bin) + dy, std::get<2>(bin) + dz});
            if (it == bins.end()) continue;
            for (std::size_t b : it->second) {
              if (a == b || glm::length(root(a) - root(b)) >= rootRadius) continue;
              close += closeParticlesOf(positions, p, a, b, separation);
              r.checked += p - 1;
            }
          }
  r.fraction = r.checked ? double(close) / double(r.checked) : 0.0;
  return r;
}
}  // namespace hp
