#include "engine/core/hair/strand_topology.h"

#include <algorithm>
#include <numeric>
#include <string>

#include "engine/core/error.h"
#include "engine/core/hair/hairline_distance.h"
#include "engine/core/hair/rng.h"

namespace hp {
namespace {
constexpr std::uint32_t kMaxTotalStrands = 16u << 20;

double triangleArea(std::span<const glm::vec3> roots, const glm::uvec3& t) {
  glm::dvec3 a(roots[t.x]), b(roots[t.y]), c(roots[t.z]);
  return 0.5 * glm::length(glm::cross(b - a, c - a));
}

std::vector<std::uint32_t> spreadByArea(std::span<const glm::vec3> roots, std::span<const glm::uvec3> tris,
                                        std::uint32_t total) {
  std::vector<double> area(tris.size());
  for (std::size_t i = 0; i < tris.size(); ++i) area[i] = triangleArea(roots, tris[i]);
  double sum = std::accumulate(area.begin(), area.end(), 0.0);
  std::vector<std::uint32_t> count(tris.size(), 0);
  if (!(sum > 0.0)) return count;
  std::vector<std::pair<double, std::uint32_t>> remainder(tris.size());
  std::uint64_t given = 0;
  for (std::size_t i = 0; i < tris.size(); ++i) {
    double exact = total * area[i] / sum;
    count[i] = static_cast<std::uint32_t>(exact);
    given += count[i];
    remainder[i] = {exact - count[i], static_cast<std::uint32_t>(i)};
  }
  // Largest remainders first; ties by index keep the result deterministic.
  std::sort(remainder.begin(), remainder.end(),
            [](const auto& x, const auto& y) { return x.first != y.first ? x.first > y.first : x.second < y.second; });
  for (std::size_t k = 0; given < total && k < remainder.size(); ++k, ++given) ++count[remainder[k].second];
  return count;
}
}  // namespace

void DensityOptions::validate() const {
  if (strandsPerTriangle < 1 || strandsPerTriangle > 4096)
    throw Error("density: strandsPerTriangle must be in [1, 4096], got " + std::to_string(strandsPerTriangle));
  if (totalStrands < 1 || totalStrands > kMaxTotalStrands)
    throw Error("density: totalStrands must be in [1, " + std::to_string(kMaxTotalStrands) + "], got " +
                std::to_string(totalStrands));
}

glm::vec3 foldBarycentric(float u, float v) {
  if (u + v > 1.0f) u = 1.0f - u, v = 1.0f - v;
  return {u, v, std::max(0.0f, 1.0f - u - v)};
}

std::vector<std::uint32_t> strandsPerTriangle(std::span<const glm::vec3> roots,
                                              std::span<const glm::uvec3> triangles,
                                              const DensityOptions& density) {
  density.validate();
  if (density.mode == DensityOptions::Mode::PerTriangle)
    return std::vector<std::uint32_t>(triangles.size(), density.strandsPerTriangle);
  return spreadByArea(roots, triangles, density.totalStrands);
}

DensityOptions::Mode resolvedMode(const DensityOptions& density, std::size_t guides) {
  if (density.mode != DensityOptions::Mode::Auto) return density.mode;
  return guides >= density.totalStrands ? DensityOptions::Mode::Guides : DensityOptions::Mode::Total;
}

namespace {
// One strand on every guide: at its corner of the first triangle that has it (a triangle of its own added
// where none does), ordered by a hash so any prefix is an even thinning.
InterpolationTopology ownStrands(std::size_t guides, std::vector<glm::uvec3> triangles, std::uint32_t seed) {
  std::vector<std::pair<std::uint32_t, std::uint32_t>> corner(guides, {~0u, 0u});  // (triangle, corner)
  for (std::uint32_t t = 0; t < triangles.size(); ++t)
    for (std::uint32_t k = 0; k < 3; ++k)
      if (corner[triangles[t][k]].first == ~0u) corner[triangles[t][k]] = {t, k};
  std::vector<std::pair<float, std::uint32_t>> order;
  for (std::uint32_t g = 0; g < guides; ++g) {
    if (corner[g].first == ~0u) {
      corner[g] = {std::uint32_t(triangles.size()), 0u};
      triangles.emplace_back(g, g, g);
    }
    order.emplace_back(hashRandom(seed, g, 4), g);
  }
  std::sort(order.begin(), order.end());
  InterpolationTopology topo;
  for (const auto& [rank, g] : order) {
    glm::vec3 x(0.0f);
    x[int(corner[g].second)] = 1.0f;
    topo.strands.push_back({corner[g].first, x, hashRandom(seed, g, 3)});
  }
  topo.triangles = std::move(triangles);
  return topo;
}

// The strands of buildInterpolationTopology, in level-of-detail order (the density was validated).
InterpolationTopology bindStrands(std::span<const glm::vec3> roots, std::vector<glm::uvec3> triangles,
                                  const DensityOptions& density) {
  if (triangles.empty()) throw Error("interpolation topology: no triangles");
  for (std::size_t t = 0; t < triangles.size(); ++t)
    if (glm::any(glm::greaterThanEqual(triangles[t], glm::uvec3(roots.size()))))
      throw Error("interpolation topology: triangle " + std::to_string(t) + " names a guide beyond " +
                  std::to_string(roots.size()));
  if (resolvedMode(density, roots.size()) == DensityOptions::Mode::Guides)
    return ownStrands(roots.size(), std::move(triangles), density.seed);
  std::vector<std::uint32_t> counts = strandsPerTriangle(roots, triangles, density);
  const std::size_t total = std::accumulate(counts.begin(), counts.end(), std::size_t(0));
  // Per triangle the density is bounded, in all not: a large scalp times strandsPerTriangle is refused here,
  // before gigabytes of bindings (the same bound as totalStrands).
  if (total > kMaxTotalStrands)
    throw Error("density: strandsPerTriangle " + std::to_string(density.strandsPerTriangle) + " on " +
                std::to_string(triangles.size()) + " scalp triangles makes " + std::to_string(total) +
                " strands, more than the " + std::to_string(kMaxTotalStrands) + " allowed");
  std::vector<StrandBinding> made;
  std::vector<std::pair<float, std::uint32_t>> order;  // (LOD rank, index in `made`)
  made.reserve(total);
  order.reserve(total);
  for (std::uint32_t t = 0; t < counts.size(); ++t)
    for (std::uint32_t k = 0; k < counts[t]; ++k) {
      auto s = static_cast<std::uint32_t>(made.size());
      glm::vec3 x = foldBarycentric(hashRandom(density.seed, s, 1), hashRandom(density.seed, s, 2));
      made.push_back({t, x, hashRandom(density.seed, s, 3)});
      // Jittered strata of the triangle's own strands: any prefix of the sorted order holds each
      // triangle's share of the strands, up to one.
      order.emplace_back((float(k) + hashRandom(density.seed, s, 4)) / float(counts[t]), s);
    }
  std::sort(order.begin(), order.end());
  InterpolationTopology topo;
  topo.strands.reserve(total);
  for (const auto& [rank, s] : order) topo.strands.push_back(made[s]);
  topo.triangles = std::move(triangles);
  return topo;
}
}  // namespace

InterpolationTopology buildInterpolationTopology(std::span<const glm::vec3> roots,
                                                 std::vector<glm::uvec3> triangles,
                                                 const DensityOptions& density) {
  density.validate();
  InterpolationTopology topo = bindStrands(roots, std::move(triangles), density);
  topo.hairlineDistance = hairlineDistances(roots, topo.triangles);
  return topo;
}
}  // namespace hp
