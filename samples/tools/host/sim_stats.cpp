#include "samples/tools/host/sim_stats.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "engine/core/hair/root_binding.h"

namespace hp {
namespace {
bool finite(const glm::vec4& p) { return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z); }
}  // namespace

SimStats computeSimStats(std::span<const glm::vec4> positions, std::span<const glm::vec4> previous,
                         std::span<const glm::vec4> rest, std::uint32_t particlesPerGuide,
                         std::span<const SphereCollider> colliders, const glm::mat4& head, double pearlRadius,
                         double substepSeconds) {
  SimStats s;
  s.minColliderClearance = std::numeric_limits<double>::infinity();
  std::vector<glm::dvec3> centers;
  for (const auto& c : colliders) centers.push_back(glm::dvec3(head * glm::vec4(c.center, 1.0f)));
  for (std::size_t i = 0; i < positions.size(); ++i) {
    if (!finite(positions[i])) {
      ++s.nanCount;
      continue;
    }
    const glm::dvec3 x(positions[i]);
    const bool root = i % particlesPerGuide == 0;
    if (!root) {
      if (finite(positions[i - 1]) && rest[i].w > 0.0f) {
        double len = glm::length(x - glm::dvec3(positions[i - 1]));
        s.maxLengthError = std::max(s.maxLengthError, std::abs(len - rest[i].w) / rest[i].w);
      }
      glm::dvec3 v = (x - glm::dvec3(previous[i])) / substepSeconds;
      s.maxSpeed = std::max(s.maxSpeed, glm::length(v));
      s.kineticEnergy += 0.5 * glm::dot(v, v);
      for (std::size_t c = 0; c < centers.size(); ++c)
        s.minColliderClearance = std::min(s.minColliderClearance,
                                          glm::length(x - centers[c]) - colliders[c].radius - pearlRadius);
    }
  }
  if (!std::isfinite(s.minColliderClearance)) s.minColliderClearance = 0.0;
  return s;
}

MeshPenetration meshPenetration(std::span<const glm::vec4> positions, std::uint32_t particlesPerGuide,
                                std::span<const glm::vec3> vertices, std::span<const glm::uvec3> triangles,
                                const glm::mat4& head) {
  MeshPenetration out;
  if (particlesPerGuide == 0) return out;
  const glm::mat4 toHead = glm::inverse(head);
  std::vector<glm::vec3> points;
  for (std::size_t i = 0; i < positions.size(); ++i)
    if (i % particlesPerGuide != 0 && finite(positions[i])) points.push_back(glm::vec3(toHead * glm::vec4(glm::vec3(positions[i]), 1.0f)));
  if (points.empty()) return out;
  const RootBindings near = bindRoots(points, vertices, triangles, 0.0f);
  out.particles = points.size();
  out.minClearance = std::numeric_limits<double>::infinity();
  for (const RootBinding& b : near.roots) {
    const double signedDistance = b.offset < 0.0f ? -double(b.distance) : double(b.distance);
    out.minClearance = std::min(out.minClearance, signedDistance);
    if (signedDistance < 0.0) ++out.inside, out.deepest = std::max(out.deepest, -signedDistance);
  }
  return out;
}

LayerThickness hairLayerThickness(std::span<const glm::vec4> positions, std::uint32_t particlesPerGuide,
                                  const SdfGrid& sdf, const glm::mat4& head) {
  LayerThickness t;
  if (particlesPerGuide == 0 || sdf.empty()) return t;
  const glm::mat4 toHead = glm::inverse(head);
  std::vector<double> d;
  for (std::size_t g = 0; g < positions.size() / particlesPerGuide; ++g) {
    const glm::vec3 p = glm::vec3(toHead * glm::vec4(glm::vec3(positions[g * particlesPerGuide + particlesPerGuide / 2]), 1.0f));
    if (std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z)) d.push_back(sdf.sample(p));
  }
  if (d.empty()) return t;
  t.guides = d.size();
  for (double v : d) t.mean += v / double(d.size());
  const std::size_t k = std::min(d.size() - 1, std::size_t(std::ceil(0.9 * double(d.size()))) - 1);
  std::nth_element(d.begin(), d.begin() + std::ptrdiff_t(k), d.end());
  t.p90 = d[k];
  return t;
}
}  // namespace hp
