#include "compute/shadows/head_shadow_view.h"

#include <algorithm>
#include <cmath>

#include <glm/gtc/matrix_transform.hpp>

namespace hp::render {
namespace {
// Receiver offset toward the light, in texels: covers the 3 x 3 bilinear taps' reach on back faces
// seen at a slant, where the wrap-lit side meets its own back-face depth (skin facing away from the light adds
// 2 texels x the tangent of its slope to the light: shaders/head_shadow.glsl).
constexpr float kOffsetTexels = 3.0f;

glm::vec3 perpendicular(const glm::vec3& axis) {
  const glm::vec3 other = std::abs(axis.y) < 0.9f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0);
  return glm::normalize(glm::cross(axis, other));
}
}  // namespace

HeadSphere enclose(const HeadSphere& a, const HeadSphere& b) {
  if (a.radius <= 0.0f) return b;
  if (b.radius <= 0.0f) return a;
  const float d = glm::length(b.centre - a.centre);
  if (d + b.radius <= a.radius) return a;
  if (d + a.radius <= b.radius) return b;
  const float r = 0.5f * (d + a.radius + b.radius);
  return {a.centre + (b.centre - a.centre) * ((r - a.radius) / d), r};
}

HeadSphere boundingSphere(std::span<const glm::vec3> points) {
  if (points.empty()) return {};
  glm::vec3 lo = points.front(), hi = lo;
  for (const glm::vec3& p : points) lo = glm::min(lo, p), hi = glm::max(hi, p);
  HeadSphere sphere{0.5f * (lo + hi), 0.0f};
  for (const glm::vec3& p : points) sphere.radius = std::max(sphere.radius, glm::length(p - sphere.centre));
  return sphere;
}

HeadShadowView headShadowView(const LightSpec& light, const HeadSphere& heads, std::uint32_t resolution) {
  HeadShadowView v;
  if (!(heads.radius > 0.0f)) return v;
  const float r = 1.02f * heads.radius;
  const glm::vec3 toward = glm::normalize(light.direction);
  float texelWorld = 2.0f * r / float(resolution);
  if (light.type == LightSpec::Type::Directional) {
    const glm::vec3 eye = heads.centre + toward * (2.0f * r);
    v.viewProj = glm::orthoRH_ZO(-r, r, -r, r, r, 3.0f * r) * glm::lookAtRH(eye, heads.centre, perpendicular(toward));
  } else {
    const glm::vec3 eye = light.position;
    const float dist = glm::length(heads.centre - eye);
    const float half = dist > 1.05f * r ? std::asin(r / dist) : glm::radians(std::min(light.coneDeg + 5.0f, 85.0f));
    const glm::vec3 axis = dist > 1e-6f ? (heads.centre - eye) / dist : -toward;
    v.viewProj = glm::perspectiveRH_ZO(2.0f * half, 1.0f, std::max(dist - r, 0.01f * r), dist + r) *
                 glm::lookAtRH(eye, eye + axis, perpendicular(axis));
    texelWorld = 2.0f * std::tan(half) * dist / float(resolution);
  }
  v.params = glm::vec4(1.0f, kOffsetTexels * texelWorld, 1.0f / float(resolution), texelWorld);
  v.extentWorld = texelWorld * float(resolution);
  return v;
}
}  // namespace hp::render
