#include "engine/core/hair/guide_growth.h"

#include <cmath>
#include <string>

#include "engine/core/error.h"
#include "engine/core/number_text.h"
#include "engine/core/hair/model_transform.h"
#include "engine/core/hair/rng.h"
#include "engine/core/hair/segment_profile.h"

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

// The point at distance len from a that lies just outside collider c and is nearest to p0: on the
// circle where the sphere of radius len around a meets the collider's surface.
glm::vec3 nearestOnShell(const glm::vec3& a, float len, const SphereCollider& c, const glm::vec3& p0) {
  const float r = c.radius * 1.0005f;  // a hair's breadth outside, so the result tests as outside
  glm::vec3 ac = c.center - a;
  float d = glm::length(ac);
  if (d < r) {  // a itself is inside (a root below the collider surface): leave radially
    glm::vec3 q = c.center + glm::normalize(p0 - c.center) * r;
    return a + glm::normalize(q - a) * len;
  }
  glm::vec3 u = ac / d;
  float h = (len * len + d * d - r * r) / (2.0f * d);
  float rho2 = len * len - h * h;
  if (rho2 < 0.0f) return p0;  // cannot reach the collider (p0 was not inside after all)
  glm::vec3 w = (p0 - a) - glm::dot(p0 - a, u) * u;
  if (glm::length(w) < 1e-12f) w = glm::cross(u, std::abs(u.x) < 0.9f ? glm::vec3(1, 0, 0) : glm::vec3(0, 0, 1));
  return a + h * u + std::sqrt(rho2) * glm::normalize(w);
}

// Keeps |p - prev| = len while moving p out of the colliders (a few rounds: leaving one collider
// may enter another).
glm::vec3 slideOutside(const glm::vec3& prev, const glm::vec3& dir, float len,
                       std::span<const SphereCollider> colliders, glm::vec3& dirOut) {
  glm::vec3 p = prev + dir * len;
  for (int round = 0; round < 8; ++round) {
    const SphereCollider* c = insideCollider(p, colliders);
    if (!c) break;
    p = nearestOnShell(prev, len, *c, p);
  }
  dirOut = glm::normalize(p - prev);
  return p;
}

// Keeps |p - prev| = len while pushing p out of the field along its gradient.
glm::vec3 slideOutsideField(const glm::vec3& prev, const glm::vec3& p0, float len, const DistanceFunction& field,
                            glm::vec3& dirOut) {
  glm::vec3 p = p0;
  const float h = 2e-4f;
  for (int round = 0; round < 8; ++round) {
    const float d = field(p);
    if (d >= kGrowthClearance) break;
    glm::vec3 grad(field(p + glm::vec3(h, 0, 0)) - field(p - glm::vec3(h, 0, 0)),
                   field(p + glm::vec3(0, h, 0)) - field(p - glm::vec3(0, h, 0)),
                   field(p + glm::vec3(0, 0, h)) - field(p - glm::vec3(0, 0, h)));
    if (glm::length(grad) < 1e-12f) break;
    p += glm::normalize(grad) * (kGrowthClearance * 1.01f - d);
    p = prev + glm::normalize(p - prev) * len;
  }
  dirOut = glm::normalize(p - prev);
  return p;
}
}  // namespace

void GrowthOptions::validate() const {
  checkParticlesPerGuide(particlesPerGuide, "growth options");
  // Shorter than 0.1 mm (in metres) the segments' lengths vanish in the constraints' single precision.
  require(std::isfinite(length) && length >= 1e-4f && length <= kMaxHeadSpaceCoordinate,
          "length must be in [0.0001, " + std::to_string(int(kMaxHeadSpaceCoordinate)) + "], got " + numberText(length));
  require(lengthVariation >= 0.0f && lengthVariation < 1.0f,
          "lengthVariation must be in [0, 1), got " + numberText(lengthVariation));
  require(segmentRatio >= 1.0f && segmentRatio <= 4.0f,
          "segmentRatio must be in [1, 4], got " + numberText(segmentRatio));
  require(bend >= 0.0f && bend <= 1.0f, "bend must be in [0, 1], got " + numberText(bend));
  float dirLen = glm::length(bendDirection);
  require(std::isfinite(dirLen) && dirLen > 1e-6f, "bendDirection must be a non-zero vector");
}

float grownGuideLength(const GrowthOptions& options, std::uint32_t guide) {
  float r = hashRandom(options.seed, guide, 0);
  return options.length * (1.0f + options.lengthVariation * (2.0f * r - 1.0f));
}

GuideSet growGuides(const ScalpMesh& scalp, const GrowthOptions& options,
                    std::span<const SphereCollider> colliders, const BendField& bendField,
                    const DistanceFunction& field) {
  options.validate();
  const glm::vec3 constantTarget = glm::normalize(options.bendDirection);
  const std::uint32_t P = options.particlesPerGuide;
  GuideSet guides;
  guides.particlesPerGuide = P;
  guides.positions.resize(std::size_t(scalp.vertexCount()) * P);
  for (std::uint32_t g = 0; g < scalp.vertexCount(); ++g) {
    auto lengths = geometricSegmentLengths(grownGuideLength(options, g), options.segmentRatio, P - 1);
    auto guide = guides.guide(g);
    guide[0] = scalp.positions[g];
    glm::vec3 dir = scalp.normals[g];
    for (std::uint32_t k = 1; k < P; ++k) {
      if (k > 1 && options.bend > 0.0f)
        dir = turnToward(dir, bendField ? glm::normalize(bendField(guide[k - 1], g)) : constantTarget, options.bend);
      guide[k] = colliders.empty() ? guide[k - 1] + dir * lengths[k - 1]
                                   : slideOutside(guide[k - 1], dir, lengths[k - 1], colliders, dir);
      if (field) guide[k] = slideOutsideField(guide[k - 1], guide[k], lengths[k - 1], field, dir);
    }
  }
  return guides;
}
}  // namespace hp
