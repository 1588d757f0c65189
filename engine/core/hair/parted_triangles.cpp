#include "engine/core/hair/parted_triangles.h"

#include <algorithm>
#include <array>

namespace hp {
namespace {
float depthIn(const SphereCollider& sphere, const glm::vec3& p) { return sphere.radius - glm::distance(p, sphere.center); }

// The blends probed: each edge's midpoint and the centroid (weights of guides A, B, C).
constexpr std::array<glm::vec3, 4> kProbes = {glm::vec3(0.5f, 0.5f, 0.0f), glm::vec3(0.0f, 0.5f, 0.5f),
                                              glm::vec3(0.5f, 0.0f, 0.5f), glm::vec3(1.0f / 3.0f)};

bool partsAround(const GuideSet& guides, const glm::uvec3& t, const SphereCollider& sphere, float margin) {
  const auto a = guides.guide(t.x), b = guides.guide(t.y), c = guides.guide(t.z);
  for (std::uint32_t k = 1; k < guides.particlesPerGuide; ++k) {
    const float own = std::max({depthIn(sphere, a[k]), depthIn(sphere, b[k]), depthIn(sphere, c[k]), 0.0f});
    for (const glm::vec3& w : kProbes)
      if (depthIn(sphere, w.x * a[k] + w.y * b[k] + w.z * c[k]) > own + margin * sphere.radius) return true;
  }
  return false;
}
}  // namespace

PartedTriangles dropPartedTriangles(const GuideSet& guides, std::span<const glm::uvec3> triangles,
                                    std::span<const SphereCollider> colliders, float margin) {
  PartedTriangles out;
  out.kept.reserve(triangles.size());
  const std::uint32_t n = guides.guideCount();
  for (const glm::uvec3& t : triangles) {
    // A triangle naming a guide that does not exist is kept, for the topology to refuse with its own message.
    const bool parted = t.x < n && t.y < n && t.z < n && std::any_of(colliders.begin(), colliders.end(),
                                    [&](const SphereCollider& s) { return partsAround(guides, t, s, margin); });
    if (parted) ++out.dropped;
    else out.kept.push_back(t);
  }
  return out;
}
}  // namespace hp
