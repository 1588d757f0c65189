#pragma once
// Contract: the camera of a frame as matrices: view (world -> view, looking down -Z) and a Vulkan
// [0,1]-depth perspective projection. orbitCamera places it on a sphere around the scene's target.
#include <glm/glm.hpp>

#include "engine/core/hair/scene.h"

namespace hp {
struct CameraMatrices {
  glm::mat4 view{1.0f};
  glm::mat4 proj{1.0f};
  glm::vec3 position{0.0f};
  float fovY = 0.6f;  // radians
};

// Throws hp::Error when the camera is degenerate (distance <= 0, fov outside (0, 180) deg, NaN).
CameraMatrices orbitCamera(const CameraSpec& camera, float aspect);
}  // namespace hp
