#include "engine/hair/guide_growth.h"

#include <cmath>
#include <string>

#include "engine/error.h"
#include "engine/hair/rng.h"
#include "engine/hair/segment_profile.h"

namespace hp {
namespace {
void require(bool ok, const std::string& message) {
  if (!ok) throw Error("growth options: " + message);
}

// Rodrigues rotation of v about unit axis k by angle a.
glm::vec3 rotate(const glm::vec3& v, const glm::vec3& k, float a) {
  return v * std::cos(a) + glm::cross(k, v) * std::sin(a) + k * glm::dot(k, v) * (1.0f - std::cos(a));
}

// Turns unit d toward unit target by `fraction` of the angle between them.
glm::vec3 turnToward(const glm::vec3& d, const glm::vec3& target, float fraction) {
  float angle = std::acos(glm::clamp(glm::dot(d, target), -1.0f, 1.0f));
  glm::vec3 axis = glm::cross(d, target);
  float len = glm::length(axis);
  if (len < 1e-6f) {
    if (angle < 1e-3f) return d;  // already aligned
    // Anti-parallel: any perpendicular axis works; pick one deterministically.
    axis = glm::cross(d, std::abs(d.x) < 0.9f ? glm::vec3(1, 0, 0) : glm::vec3(0, 0, 1));
    len = glm::length(axis);
  }
  return glm::normalize(rotate(d, axis / len, angle * fraction));
}

const SphereCollider* insideCollider(const glm::vec3& p, std::span<const SphereCollider> colliders) {
  for (const auto& c : colliders)
    if (glm::length(p - c.center) < c.radius) return &c;
  return nullptr;
}

// Keeps |p - prev| = len while sliding p out of the colliders; a few projections converge on the
// surface (each one rotates the segment toward the tangent plane).
glm::vec3 slideOutside(const glm::vec3& prev, glm::vec3 dir, float len,
                       std::span<const SphereCollider> colliders, glm::vec3& dirOut) {
  glm::vec3 p = prev + dir * len;
  for (int it = 0; it < 16; ++it) {
    const SphereCollider* c = insideCollider(p, colliders);
    if (!c) break;
    glm::vec3 out = p - c->center;
    float d = glm::length(out);
    glm::vec3 onSurface = c->center + (d > 0.0f ? out / d : dir) * (c->radius * 1.0005f);
    glm::vec3 step = onSurface - prev;
    if (glm::length(step) < 1e-9f) break;
    dir = glm::normalize(step);
    p = prev + dir * len;
  }
  dirOut = dir;
  return p;
}
}  // namespace

void GrowthOptions::validate() const {
  checkParticlesPerGuide(particlesPerGuide, "growth options");
  require(std::isfinite(length) && length > 0.0f, "length must be positive, got " + std::to_string(length));
  require(lengthVariation >= 0.0f && lengthVariation < 1.0f,
          "lengthVariation must be in [0, 1), got " + std::to_string(lengthVariation));
  require(segmentRatio >= 1.0f && segmentRatio <= 4.0f,
          "segmentRatio must be in [1, 4], got " + std::to_string(segmentRatio));
  require(bend >= 0.0f && bend <= 1.0f, "bend must be in [0, 1], got " + std::to_string(bend));
  float dirLen = glm::length(bendDirection);
  require(std::isfinite(dirLen) && dirLen > 1e-6f, "bendDirection must be a non-zero vector");
}

float grownGuideLength(const GrowthOptions& options, std::uint32_t guide) {
  float r = hashRandom(options.seed, guide, 0);
  return options.length * (1.0f + options.lengthVariation * (2.0f * r - 1.0f));
}

GuideSet growGuides(const ScalpMesh& scalp, const GrowthOptions& options,
                    std::span<const SphereCollider> colliders, std::span<const glm::vec3> bendDirections) {
  options.validate();
  if (!bendDirections.empty() && bendDirections.size() != scalp.vertexCount())
    throw Error("growth: " + std::to_string(bendDirections.size()) + " bend directions for " +
                std::to_string(scalp.vertexCount()) + " scalp vertices");
  const std::uint32_t P = options.particlesPerGuide;
  GuideSet guides;
  guides.particlesPerGuide = P;
  guides.positions.resize(std::size_t(scalp.vertexCount()) * P);
  for (std::uint32_t g = 0; g < scalp.vertexCount(); ++g) {
    auto lengths = geometricSegmentLengths(grownGuideLength(options, g), options.segmentRatio, P - 1);
    auto guide = guides.guide(g);
    guide[0] = scalp.positions[g];
    glm::vec3 dir = scalp.normals[g];
    glm::vec3 target = glm::normalize(bendDirections.empty() ? options.bendDirection : bendDirections[g]);
    for (std::uint32_t k = 1; k < P; ++k) {
      if (k > 1 && options.bend > 0.0f) dir = turnToward(dir, target, options.bend);
      guide[k] = colliders.empty() ? guide[k - 1] + dir * lengths[k - 1]
                                   : slideOutside(guide[k - 1], dir, lengths[k - 1], colliders, dir);
    }
  }
  return guides;
}
}  // namespace hp
