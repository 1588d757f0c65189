#pragma once
// Contract: signed distance primitives and blends for building fields (negative inside). sphere,
// capsule and box are exact; ellipsoid and taperedCapsule are close bounds (exact on their axes),
// good enough for meshing and collision where the field is re-sampled on a grid. smoothUnion is the
// polynomial smooth minimum: equal to min(a, b) where |a - b| >= k, blending within k.
#include <glm/glm.hpp>

#include <algorithm>
#include <cmath>

namespace hp::sdf {
inline float sphere(const glm::vec3& p, const glm::vec3& c, float r) { return glm::length(p - c) - r; }

// Scaled-gradient estimate |p/r| (|p/r| - 1) / |p/r^2|: exact on the axes, smooth, no blow-up near the center.
inline float ellipsoid(const glm::vec3& p, const glm::vec3& c, const glm::vec3& r) {
  const glm::vec3 q = p - c;
  const float k0 = glm::length(q / r), k1 = glm::length(q / (r * r));
  if (k1 < 1e-12f) return -std::min(r.x, std::min(r.y, r.z));
  return k0 * (k0 - 1.0f) / k1;
}

// Distance to the segment ab, minus a radius that goes linearly from ra (at a) to rb (at b).
inline float taperedCapsule(const glm::vec3& p, const glm::vec3& a, const glm::vec3& b, float ra, float rb) {
  const glm::vec3 ab = b - a;
  const float t = glm::clamp(glm::dot(p - a, ab) / glm::dot(ab, ab), 0.0f, 1.0f);
  return glm::length(p - (a + t * ab)) - glm::mix(ra, rb, t);
}

inline float capsule(const glm::vec3& p, const glm::vec3& a, const glm::vec3& b, float r) {
  return taperedCapsule(p, a, b, r, r);
}

inline float smoothUnion(float a, float b, float k) {
  const float h = std::max(k - std::abs(a - b), 0.0f) / k;
  return std::min(a, b) - h * h * k * 0.25f;
}

// a with b carved out, blended within k.
inline float smoothSubtract(float a, float b, float k) { return -smoothUnion(-a, b, k); }
}  // namespace hp::sdf
