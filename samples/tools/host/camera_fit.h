#pragma once
// Contract: frames a camera on a set of points (the hair): the target is the center of their bounds
// and the distance puts the bounding sphere inside the vertical field of view with a 10% margin.
// Orbit, elevation and field of view are kept. And the check that a camera sees any of them.
#include <glm/glm.hpp>

#include <span>

#include "engine/core/hair/scene.h"

namespace hp {
void fitCameraToPoints(CameraSpec& camera, std::span<const glm::vec3> points);

// How many of the points fall inside the camera's view (aspect = width / height).
std::size_t pointsInView(const CameraSpec& camera, float aspect, std::span<const glm::vec3> points);
}  // namespace hp
