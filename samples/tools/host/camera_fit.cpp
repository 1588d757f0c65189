#include "samples/tools/host/camera_fit.h"

#include <cmath>

#include "engine/core/error.h"

namespace hp {
void fitCameraToPoints(CameraSpec& camera, std::span<const glm::vec3> points) {
  if (points.empty()) throw Error("camera: nothing to frame");
  glm::vec3 lo(INFINITY), hi(-INFINITY);
  for (const auto& p : points) lo = glm::min(lo, p), hi = glm::max(hi, p);
  const float radius = std::max(0.5f * glm::length(hi - lo), 1e-6f);
  camera.target = 0.5f * (lo + hi);
  camera.distance = 1.1f * radius / std::sin(0.5f * glm::radians(camera.fovDeg));
}

std::size_t pointsInView(const CameraSpec& camera, float aspect, std::span<const glm::vec3> points) {
  const float orbit = glm::radians(camera.orbitDeg), elevation = glm::radians(camera.elevationDeg);
  const glm::vec3 back(std::sin(orbit) * std::cos(elevation), std::sin(elevation), std::cos(orbit) * std::cos(elevation));
  const glm::vec3 eye = camera.target + camera.distance * back;
  const glm::vec3 right = glm::normalize(glm::cross(glm::vec3(0, 1, 0), back)), up = glm::cross(back, right);
  const float tanY = std::tan(0.5f * glm::radians(camera.fovDeg)), tanX = tanY * aspect;
  std::size_t seen = 0;
  for (const auto& p : points) {
    const glm::vec3 d = p - eye;
    const float depth = -glm::dot(d, back);
    if (depth <= 1e-6f) continue;
    seen += std::abs(glm::dot(d, right)) <= tanX * depth && std::abs(glm::dot(d, up)) <= tanY * depth;
  }
  return seen;
}
}  // namespace hp
