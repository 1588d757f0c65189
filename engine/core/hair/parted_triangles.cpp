#include "engine/core/hair/parted_triangles.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace hp {
float CollisionBody::depth(const glm::vec3& p) const {
  float d = -INFINITY;
  for (const SphereCollider& s : spheres) d = std::max(d, s.radius - glm::distance(p, s.center));
  if (grid != nullptr && !grid->empty()) d = std::max(d, -grid->sample(p));
  return d;
}

namespace {
// The blends probed: each edge's midpoint and the centroid (weights of guides A, B, C).
constexpr std::array<glm::vec3, 4> kProbes = {glm::vec3(0.5f, 0.5f, 0.0f), glm::vec3(0.0f, 0.5f, 0.5f),
                                              glm::vec3(0.5f, 0.0f, 0.5f), glm::vec3(1.0f / 3.0f)};

bool partsAround(const GuideSet& guides, const glm::uvec3& t, const CollisionBody& body, float marginLength) {
  const auto a = guides.guide(t.x), b = guides.guide(t.y), c = guides.guide(t.z);
  for (std::uint32_t k = 1; k < guides.particlesPerGuide; ++k) {
    const float own = std::max({body.depth(a[k]), body.depth(b[k]), body.depth(c[k]), 0.0f});
    for (const glm::vec3& w : kProbes)
      if (body.depth(w.x * a[k] + w.y * b[k] + w.z * c[k]) > own + marginLength) return true;
  }
  return false;
}
}  // namespace

PartedTriangles dropPartedTriangles(const GuideSet& guides, std::span<const glm::uvec3> triangles,
                                    const CollisionBody& body, float marginLength) {
  PartedTriangles out;
  out.kept.reserve(triangles.size());
  const std::uint32_t n = guides.guideCount();
  for (const glm::uvec3& t : triangles) {
    // A triangle naming a guide that does not exist is kept, for the topology to refuse with its own message.
    const bool parted = !body.empty() && t.x < n && t.y < n && t.z < n && partsAround(guides, t, body, marginLength);
    if (parted) ++out.dropped;
    else out.kept.push_back(t);
  }
  return out;
}
}  // namespace hp
